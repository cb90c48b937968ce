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
        {"unknown diffusion profile", "profile", "known: skin",
         [](Scene& s) { s.characters.front().material.profile = "nosuch"; },
         [](const Scene&) { return std::string("characters.0.material.profile=nosuch"); }},
    };
    return kValues;
}

}  // namespace dermis::stress
