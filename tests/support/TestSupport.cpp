#include "TestSupport.h"

#include <algorithm>

#include "core/ImageResample.h"
#include "env/SphericalHarmonics.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace dermis::test {

TempDir::TempDir() {
    static std::atomic<int> counter{0};
    mPath = std::filesystem::temp_directory_path() /
            ("dermis-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(mPath);
    std::filesystem::create_directories(mPath);
}

TempDir::~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(mPath, ec);
}

ScopedEnvironmentVariable::ScopedEnvironmentVariable(std::string name, const char* value) : mName(std::move(name)) {
    if (const char* previous = std::getenv(mName.c_str())) {
        mPrevious = previous;
        mHadPrevious = true;
    }
    if (value) {
        ::setenv(mName.c_str(), value, 1);
    } else {
        ::unsetenv(mName.c_str());
    }
}

ScopedEnvironmentVariable::~ScopedEnvironmentVariable() {
    if (mHadPrevious) {
        ::setenv(mName.c_str(), mPrevious.c_str(), 1);
    } else {
        ::unsetenv(mName.c_str());
    }
}

ProcessResult runProcess(const std::string& command) {
    TempDir dir;
    const std::string outFile = dir.file("stdout");
    const std::string errFile = dir.file("stderr");
    const int status = std::system((command + " >" + outFile + " 2>" + errFile + " </dev/null").c_str());
    ProcessResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = readTextFile(outFile);
    result.err = readTextFile(errFile);
    return result;
}

void writeTextFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string contentDir() { return DERMIS_SOURCE_CONTENT_DIR; }

std::string contentScene(const std::string& name) { return contentDir() + "/scenes/" + name; }
std::string sharedContentDir() { return DERMIS_SHARED_CONTENT_DIR; }

Image solidImage(int width, int height, float value) {
    return makeImage(width, height, ColourSpace::Linear, glm::vec4(value, value, value, 1.0f));
}

Image latLongImage(int width, int height, const std::function<glm::vec3(const glm::vec3&)>& radiance) {
    Image map = makeImage(width, height, ColourSpace::Linear);
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u) map.at(u, v) = glm::vec4(radiance(latLongDirection(u, v, width, height)), 1.0f);
    return map;
}

CapMap capLatLongImage(int width, int height, const glm::dvec3& centre, double halfAngleRad, int sub) {
    constexpr double kPi = 3.14159265358979323846;
    const glm::dvec3 axis = glm::normalize(centre);
    CapMap cap;
    cap.map = makeImage(width, height, ColourSpace::Linear);
    for (int v = 0; v < height; ++v) {
        for (int u = 0; u < width; ++u) {
            int inside = 0;
            for (int j = 0; j < sub; ++j) {
                for (int i = 0; i < sub; ++i) {
                    const double phi = 2.0 * kPi * (u + (i + 0.5) / sub) / width;
                    const double theta = kPi * (v + (j + 0.5) / sub) / height;
                    const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
                    if (glm::dot(d, axis) >= std::cos(halfAngleRad)) ++inside;
                }
            }
            const float covered = float(inside) / float(sub * sub);
            cap.map.at(u, v) = glm::vec4(glm::vec3(covered), 1.0f);
            cap.drawnSolidAngle += covered * latLongTexelSolidAngle(v, width, height);
        }
    }
    cap.drawnOverExact = cap.drawnSolidAngle / (2.0 * kPi * (1.0 - std::cos(halfAngleRad)));
    return cap;
}

std::vector<std::string> errorLines(const std::string& stderrText) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < stderrText.size()) {
        size_t end = stderrText.find('\n', start);
        if (end == std::string::npos) end = stderrText.size();
        if (stderrText.compare(start, 7, "error: ") == 0) lines.push_back(stderrText.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

std::vector<std::string> namesIn(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace dermis::test
