#include "reference/ReferenceDefinition.h"

#include "core/ContentHash.h"
#include "scene/SceneLoader.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <utility>

namespace dermis::reference {
namespace {

std::string hex(uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

uint64_t digest(const std::string& text) { return fnv1a(text.data(), text.size()); }

std::vector<std::pair<std::string, std::string>> parts(const Scene& scene) {
    Scene unplaced = scene;
    unplaced.path.clear();  // file paths as resolved, not relative to where the scene file lies
    const nlohmann::json document = nlohmann::json::parse(sceneToJson(unplaced));
    const auto section = [&](const char* key) { return document.contains(key) ? document[key].dump() : std::string(); };
    const RenderSettings& s = scene.settings;
    const nlohmann::json settings = {{"ambient", {s.ambient.x, s.ambient.y, s.ambient.z}},
                                     {"energy_conservation", s.energyConservation},
                                     {"sss", {{"enabled", s.sss.enabled}, {"width_scale", s.sss.widthScale}, {"mix", s.sss.mix}}}};
    return {{"camera", hex(digest(section("camera")))},           {"lights", hex(digest(section("lights")))},
            {"characters", hex(digest(section("characters")))},   {"profiles", hex(digest(section("profiles")))},
            {"environment", hex(digest(section("environment")))}, {"settings", hex(digest(settings.dump()))}};
}

}  // namespace

std::string definitionRecord(const Scene& scene) {
    std::string record;
    for (const auto& [name, value] : parts(scene)) record += (record.empty() ? "" : ";") + name + "=" + value;
    return record;
}

std::vector<std::string> definitionMismatch(const std::string& record, const Scene& scene) {
    std::vector<std::string> differing;
    for (const auto& [name, value] : parts(scene)) {
        if (record.find(name + "=" + value) == std::string::npos) differing.push_back(name);
    }
    return differing;
}

}  // namespace dermis::reference
