#include "viewer/EffectSwitches.h"

#include <cassert>

namespace dermis::viewer {

void EffectSwitches::toggleLight(size_t index) {
    if (index >= lights.size()) lights.resize(index + 1);
    lights[index].on = !lights[index].on;
}

void applySwitches(const Scene& edited, const EffectSwitches& switches, Scene& rendered) {
    assert(edited.characters.size() == rendered.characters.size());
    rendered.path = edited.path;
    rendered.camera = edited.camera;
    rendered.background = edited.background;
    rendered.environment = edited.environment;
    rendered.settings = edited.settings;
    for (size_t i = 0; i < rendered.characters.size() && i < edited.characters.size(); ++i) {
        rendered.characters[i] = edited.characters[i];
        if (!switches.specular) rendered.characters[i].material.rhoS = 0.0f;
    }
    // A light that is off keeps its index (and so its pass names and shadow
    // slot) but gives no light and needs no shadow map.
    rendered.lights = edited.lights;
    for (size_t i = 0; i < rendered.lights.size(); ++i) {
        Light& light = rendered.lights[i];
        if (!switches.lightOn(i)) {
            light.intensity = 0.0f;
            light.castsShadow = false;
        }
        if (!switches.shadows) light.castsShadow = false;
    }
    RenderSettings& settings = rendered.settings;
    if (!switches.sss) settings.sss.enabled = false;
    if (!switches.transmittance) settings.transmittance.enabled = false;
    if (!switches.ssao) settings.ssao.enabled = false;
    if (!switches.ambient) settings.ambient = glm::vec3(0.0f);
}

}  // namespace dermis::viewer
