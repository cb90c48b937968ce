// Texture units bound outside the passes (the environment map, the material's
// grey maps, the Beckmann and energy tables: units DERMIS_UNIT_ENVIRONMENT up
// to DERMIS_UNIT_FIRST_PASS_EXTRA, include/SharedConstants.glsl) must not be
// taken by a pass's own inputs: a pass that binds one leaves its own texture
// there for every pass after it. The texture-space gather once bound its pixel
// irradiance to unit 11, and the skybox of every texture-space frame drew
// that irradiance instead of the sky.
#include "include/SharedConstants.glsl"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

namespace {

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

const std::filesystem::path kShaderDir = DERMIS_SOURCE_SHADER_DIR;
const std::filesystem::path kPassDir = kShaderDir.parent_path() / "engine" / "passes";

// Every `#define DERMIS_NAME <integer>` of the shared constants.
std::map<std::string, int> sharedIntegers() {
    std::map<std::string, int> values;
    const std::string text = readFile(kShaderDir / "include" / "SharedConstants.glsl");
    const std::regex define(R"(#define\s+(DERMIS_\w+)\s+(\d+)\b)");
    for (std::sregex_iterator it(text.begin(), text.end(), define), end; it != end; ++it) {
        values[(*it)[1].str()] = std::stoi((*it)[2].str());
    }
    return values;
}

bool isSharedUnit(int unit) { return unit >= DERMIS_UNIT_ENVIRONMENT && unit < DERMIS_UNIT_FIRST_PASS_EXTRA; }

}  // namespace

TEST(TextureUnits, PassInputsLeaveTheSharedUnitsAlone) {
    static_assert(DERMIS_UNIT_ROUGHNESS > DERMIS_UNIT_ENVIRONMENT && DERMIS_UNIT_ENERGY < DERMIS_UNIT_FIRST_PASS_EXTRA &&
                      DERMIS_UNIT_SPECULAR > DERMIS_UNIT_ENVIRONMENT && DERMIS_UNIT_BECKMANN < DERMIS_UNIT_FIRST_PASS_EXTRA,
                  "the units bound outside the passes lie in [DERMIS_UNIT_ENVIRONMENT, DERMIS_UNIT_FIRST_PASS_EXTRA)");
    const std::map<std::string, int> shared = sharedIntegers();
    auto resolve = [&](const std::string& token) {
        if (std::isdigit(static_cast<unsigned char>(token[0]))) return std::stoi(token);
        const auto found = shared.find(token);
        return found == shared.end() ? -1 : found->second;
    };
    const std::regex sampler(R"(layout\s*\(\s*binding\s*=\s*(\w+)\s*\)\s*uniform\s+\w*sampler\w*\s+(\w+)\s*(\[\s*(\w+)\s*\])?)");
    int samplers = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kShaderDir)) {
        if (!entry.is_regular_file()) continue;
        const std::string text = readFile(entry.path());
        const std::string file = entry.path().lexically_relative(kShaderDir).string();
        for (std::sregex_iterator it(text.begin(), text.end(), sampler), end; it != end; ++it) {
            const std::string binding = (*it)[1].str();
            const std::string name = (*it)[2].str();
            const int first = resolve(binding);
            const int count = (*it)[4].matched ? resolve((*it)[4].str()) : 1;
            ASSERT_GE(first, 0) << file << ": " << name << "'s binding " << binding << " is not a number or shared constant";
            ASSERT_GE(count, 1) << file << ": " << name << "'s array size";
            ++samplers;
            // A shared unit may be named only by its own constant (it is that texture).
            const bool namesSharedUnit = binding.rfind("DERMIS_UNIT_", 0) == 0 && isSharedUnit(first) && count == 1;
            if (namesSharedUnit) continue;
            for (int unit = first; unit < first + count; ++unit) {
                EXPECT_FALSE(isSharedUnit(unit)) << file << ": " << name << " takes unit " << unit
                                                 << ", which is bound outside the passes";
            }
        }
    }
    EXPECT_GT(samplers, 50) << "the pattern found too few sampler declarations in " << kShaderDir;

    // The passes' own glBindTextureUnit calls with a literal unit.
    const std::regex bind(R"(glBindTextureUnit\(\s*(\d+)\s*,)");
    int binds = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kPassDir)) {
        const std::string text = readFile(entry.path());
        for (std::sregex_iterator it(text.begin(), text.end(), bind), end; it != end; ++it) {
            ++binds;
            EXPECT_FALSE(isSharedUnit(std::stoi((*it)[1].str())))
                << entry.path().filename() << " binds unit " << (*it)[1].str() << ", which is bound outside the passes";
        }
    }
    EXPECT_GT(binds, 5) << "the pattern found too few glBindTextureUnit calls in " << kPassDir;
}
