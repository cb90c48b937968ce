#pragma once
// Where the subsurface integral's samples get their value, E x albedo^mix
// (DiffusionIntegrator.h): the exact lighting (ReferenceLighting, shadow rays)
// or, in the matched-irradiance mode, the engine's own texture-space
// irradiance (EngineIrradiance.h). One integrator serves both.

#include "reference/CharacterSurface.h"
#include "reference/ReferenceLighting.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace dermis::reference {

class SampleValues {
public:
    virtual ~SampleValues() = default;
    // The value at barycentric weights b of the triangle. A source that casts
    // shadow rays reports them in *visibility, so the integrator refines cells
    // that a shadow edge crosses; others leave it empty.
    virtual glm::vec3 valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const = 0;
};

// E from ReferenceLighting x albedo^mix, the surface shaded at level 0 of its maps.
class ExactLightingValues final : public SampleValues {
public:
    // `surface` and `lighting` must outlive this object; `sampleSet` as ReferenceLighting::irradiance takes it.
    ExactLightingValues(const CharacterSurface& surface, const ReferenceLighting& lighting, float mix,
                        uint32_t sampleSet = 0)
        : mSurface(&surface), mLighting(&lighting), mMix(mix), mSampleSet(sampleSet) {}
    glm::vec3 valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const override;

private:
    const CharacterSurface* mSurface;
    const ReferenceLighting* mLighting;
    float mMix;
    uint32_t mSampleSet;
};

// albedo^exponent with x^0 = 1 and 0^e = 0 (shaders/include/Common.glsl albedoPower).
glm::vec3 albedoPower(const glm::vec3& albedo, float exponent);

}  // namespace dermis::reference
