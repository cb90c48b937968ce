#pragma once
// On/off switches for whole effects, like the keys of Chappuis 2011's application
// (appendix A.2): each light, specular, shadows, SSS, transmittance, ambient
// light and SSAO. They never touch the scene the panels edit: each frame the
// renderer's scene is rebuilt as the edited scene with the switches applied,
// so switching an effect back on restores exactly what was there.

#include "scene/Scene.h"

#include <vector>

namespace dermis::viewer {

struct LightSwitch {
    bool on = true;  // a struct, not vector<bool>, so that ImGui can take a bool*
};

struct EffectSwitches {
    std::vector<LightSwitch> lights;  // by light index; a light without an entry is on
    bool specular = true;             // off: every material's rho_s is 0 (no specular lobe, no energy taken by it)
    bool shadows = true;              // off: no light casts shadows
    bool sss = true;
    bool transmittance = true;
    bool ambient = true;              // off: the ambient irradiance is 0
    bool ssao = true;

    bool lightOn(size_t index) const { return index >= lights.size() || lights[index].on; }
    void toggleLight(size_t index);
};

// Writes `edited` with the switches applied into `rendered`. The renderer holds
// pointers into rendered.characters, so the characters are assigned one by
// one and the vector is never reallocated; both scenes must have the same
// number of characters.
void applySwitches(const Scene& edited, const EffectSwitches& switches, Scene& rendered);

}  // namespace dermis::viewer
