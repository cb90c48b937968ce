#include "stress/StressHostile.h"

#include "core/Limits.h"

#include <cstdio>

namespace dermis::stress {
namespace {

std::string number(double x) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.9g", x);
    return text;
}

}  // namespace

// The range texts are the loader's messages as a user reads them
// (content/scenes/README.md), written out here rather than formatted from
// core/Limits.h, so a changed limit or message is noticed.
const std::vector<HostileValue>& hostileValues() {
    static const std::vector<HostileValue> kValues = {
        {"near_m below 1e-4", "near_m", ">= 1e-04",
         [](Scene& s) { s.camera.nearM = 1e-5f; },
         [](const Scene&) { return std::string("camera.near_m=1e-5"); }},
        {"far_m / near_m above 1e5", "far_m", "at most 1e+05 x near_m",
         [](Scene& s) { s.camera.farM = float(s.camera.nearM * kMaxFarOverNear * 2.0); },
         [](const Scene& s) { return "camera.far_m=" + number(s.camera.nearM * kMaxFarOverNear * 2.0); }},
        {"field of view below 1 degree", "vertical_fov_deg", "[1, 179]",
         [](Scene& s) { s.camera.verticalFovDeg = 0.5f; },
         [](const Scene&) { return std::string("camera.vertical_fov_deg=0.5"); }},
        {"field of view above 179 degrees", "vertical_fov_deg", "[1, 179]",
         [](Scene& s) { s.camera.verticalFovDeg = 179.5f; },
         [](const Scene&) { return std::string("camera.vertical_fov_deg=179.5"); }},
        {"exposure above 1e4", "exposure", "(0, 10000]",
         [](Scene& s) { s.settings.exposure = 2e4f; },
         [](const Scene&) { return std::string("exposure=2e4"); }},
        {"1e999 through --set", "exposure", "1.8e308", nullptr,
         [](const Scene&) { return std::string("exposure=1e999"); }},
        {"light colour x intensity above 1e20", "intensity", "at most 1e+20 per channel",
         [](Scene& s) {
             if (s.lights.empty()) s.lights.emplace_back();
             s.lights.front().colour = glm::vec3(3e18f, 1.0f, 1.0f);
             s.lights.front().intensity = 3e18f;
         },
         nullptr},
        {"ambient above 1e20", "ambient", "[0, 1e+20]", [](Scene& s) { s.settings.ambient = glm::vec3(1.0f, 3e20f, 1.0f); },
         [](const Scene&) { return std::string("ambient=[1, 3e20, 1]"); }},
        {"scale x metres_per_unit above 1e6", "metres_per_unit", "[1e-06, 1e+06] metres per mesh unit",
         [](Scene& s) { s.characters.front().transform.scale = 1e20f; },
         [](const Scene&) { return std::string("characters.0.transform.scale=1e20"); }},
        {"scale x metres_per_unit below 1e-6", "metres_per_unit", "[1e-06, 1e+06] metres per mesh unit",
         [](Scene& s) { s.characters.front().metresPerUnit = 1e-9f; },
         [](const Scene&) { return std::string("characters.0.metres_per_unit=1e-9"); }},
        {"unknown diffusion profile", "profile", "known: skin",
         [](Scene& s) { s.characters.front().material.profile = "nosuch"; },
         [](const Scene&) { return std::string("characters.0.material.profile=nosuch"); }},
    };
    return kValues;
}

}  // namespace dermis::stress
