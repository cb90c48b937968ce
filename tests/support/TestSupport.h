#pragma once
// Shared helpers for the GL and command-line tests.

#include "core/Image.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>
#include <functional>
#include <string>

namespace dermis::test {

// A fresh, empty directory under the system temp dir, removed on destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return mPath; }
    std::string file(const std::string& name) const { return (mPath / name).string(); }

private:
    std::filesystem::path mPath;
};

// Sets an environment variable (unsets it for nullptr) until destruction,
// then restores what it was.
class ScopedEnvironmentVariable {
public:
    ScopedEnvironmentVariable(std::string name, const char* value);
    ~ScopedEnvironmentVariable();
    ScopedEnvironmentVariable(const ScopedEnvironmentVariable&) = delete;
    ScopedEnvironmentVariable& operator=(const ScopedEnvironmentVariable&) = delete;

private:
    std::string mName;
    std::string mPrevious;
    bool mHadPrevious = false;
};

struct ProcessResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// Runs `command` through /bin/sh with stdout and stderr captured.
ProcessResult runProcess(const std::string& command);
// The lines of a command's stderr that start with "error: ", in order.
std::vector<std::string> errorLines(const std::string& stderrText);

void writeTextFile(const std::string& path, const std::string& text);
std::string readTextFile(const std::string& path);
// Every name in `dir`, hidden ones included, sorted.
std::vector<std::string> namesIn(const std::filesystem::path& dir);

std::string contentDir();  // the project's content/
std::string contentScene(const std::string& name);  // content/scenes/<name>
std::string sharedContentDir();  // ../shared/content (may not exist)

// A width x height image of one grey value (alpha 1).
Image solidImage(int width, int height, float value);

// A width x height lat-long map (env/SphericalHarmonics.h's layout) whose
// texels hold radiance(direction of the texel's centre), alpha 1.
Image latLongImage(int width, int height, const std::function<glm::vec3(const glm::vec3&)>& radiance);

// A black lat-long map holding one uniform cap of radiance 1, half-angle
// `halfAngleRad` about `centre` (normalised), each texel the share of its
// sub x sub samples inside the cap; and the cap's solid angle as drawn,
// sum of share x texel solid angle, which closed forms are scaled by.
struct CapMap {
    Image map;
    double drawnSolidAngle = 0.0;
    double drawnOverExact = 1.0;  // drawnSolidAngle / (2 pi (1 - cos halfAngle))
};
CapMap capLatLongImage(int width, int height, const glm::dvec3& centre, double halfAngleRad, int sub);

}  // namespace dermis::test
