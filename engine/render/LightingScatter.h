#pragma once
// The lighting pass's hook for SSS techniques that scatter there instead of
// blurring (scene/SssTechniques.h, SssLightingScatter): the GLSL that
// dispatches to each one's functions, and the texture of the slots' tables.
// A new such technique needs nothing here: its descriptor names its GLSL
// file, its function prefix and its table.
//
// The generated include "LightingTechniques.glsl" (which shaders/lighting.frag
// includes) defines
//   vec3 lightingScatterFalloff(LightingScatterSurface s, float nDotL);
//   bool lightingScatterShadowShows(LightingScatterSurface s, float viewDepthM);
//   vec4 lightingScatterShadow(LightingScatterSurface s, sampler2D shadowMap, GpuLight light,
//                              vec3 worldPositionM, vec3 N, float nDotL);
// each a branch per technique on s.technique (its SssTechnique id + 1;
// include/LightingScatter.glsl), and the table texture's layout:
// DERMIS_LIGHTING_TABLE_COLUMNS x DERMIS_LIGHTING_TABLE_SLOT_ROWS texels per
// slot, slot s from row s x DERMIS_LIGHTING_TABLE_SLOT_ROWS up.

#include "gl/GlObjects.h"
#include "gl/ShaderProgram.h"
#include "plan/SssPlan.h"

#include <array>

namespace dermis {

struct LightingTableLayout {
    int columns = 0;   // the widest technique's
    int slotRows = 0;  // the tallest technique's
};
LightingTableLayout lightingTableLayout();

gl::GeneratedInclude lightingTechniquesGlsl();

// The value of ProfileParams.lightingTechnique for a slot using `technique`: 0 where it does not scatter in lighting.
int lightingTechniqueId(SssTechnique technique);

// The slots' tables, stacked in one 2-D texture (a 2-D array texture sampled
// in the lights' loop crashed llvmpipe's shader compiler, LLVM 15). A slot's
// table is made on the CPU when the slot's (technique, profile, width scale)
// first needs it, and kept while those stay.
class LightingTables {
public:
    // Builds the texture on first use and the slots' tables that changed.
    // Returns whether any slot scatters in the lighting pass.
    bool prepare(const SssPlan& plan);
    GLuint texture() const { return mTexture.get(); }

private:
    struct Slot {
        SssTechnique technique = SssTechnique::Gaussians;
        const DiffusionProfile* profile = nullptr;
        float widthScale = 0.0f;
    };
    gl::Texture mTexture;
    std::array<Slot, DERMIS_MAX_PROFILES + 1> mSlots{};  // [slot]
};

}  // namespace dermis
