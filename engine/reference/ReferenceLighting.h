#pragma once
// The irradiance E at a surface point as the renderer's lighting pass defines it
// (shaders/lighting.frag, include/Lights.glsl, include/EnergyConservation.glsl),
// with exact visibility from shadow rays instead of shadow maps:
//   E = ambient + sum over lights of radiance x max(N.L, 0) x visibility x (1 - rho_s rho_dt(N.L, m))
// - directional: radiance = colour x intensity; spot and point: / r^2, spots
//   fade by smoothstep(cos outer, cos inner, cos angle);
// - the last factor only with settings.energyConservation (Chappuis 2011 §2.6);
// - the ambient is uniform and unoccluded: the renderer darkens it by SSAO, the
//   reference takes AO = 1;
// - the lights the renderer shadows are exactly the ones that cast shadow rays
//   here (engine/render/LightSetup.cpp: shadow on, not a point light, the first
//   DERMIS_MAX_SHADOWED_LIGHTS of them); only the first DERMIS_MAX_LIGHTS lights count.
// Transmittance (back-lit light through thin parts) is not part of E.

#include "reference/Bvh.h"
#include "reference/CharacterSurface.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::reference {

// Which lights a sample tested with a shadow ray, and which of those it saw.
// Two samples that tested the same light and disagree lie on either side of a
// shadow edge: the integrator refines there.
struct LightVisibility {
    uint64_t tested = 0;
    uint64_t visible = 0;

    bool disagreesWith(const LightVisibility& other) const {
        return ((visible ^ other.visible) & tested & other.tested) != 0;
    }
};

class ReferenceLighting {
public:
    // `occluders` must outlive this object.
    ReferenceLighting(const Scene& scene, const Bvh& occluders);

    // E at the point (energy conservation on the way in included).
    glm::vec3 irradiance(const SurfacePoint& point, LightVisibility* visibility = nullptr) const;
    // 1 - rho_s rho_dt(N.V, m) when energy conservation is on, else 1.
    float outgoingFactor(const SurfacePoint& point, const glm::vec3& towardsViewer) const;
    // 1 - rho_s rho_dt(cos, m), bilinear in the renderer's table like the shader.
    float energyLeftForDiffuse(float cosTheta, float roughness, float rhoS) const;

private:
    struct PreparedLight {
        int type = 0;  // DERMIS_LIGHT_*
        glm::vec3 positionM{0.0f};
        glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way the light travels
        glm::vec3 radiance{0.0f};
        float cosInner = 1.0f;
        float cosOuter = 1.0f;
        bool shadowed = false;
    };

    const Bvh* mOccluders;
    std::vector<PreparedLight> mLights;
    glm::vec3 mAmbient{0.0f};
    bool mEnergyConservation = true;
    std::vector<float> mEnergyTable;  // row-major, row = m (engine/brdf/EnergyTable.h)
};

}  // namespace dermis::reference
