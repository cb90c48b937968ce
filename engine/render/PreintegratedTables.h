#pragma once
// The pre-integrated skin tables of a frame (sss/PreintegratedTable.h,
// sss/PreintegratedShadow.h, shaders/include/PreintegratedSkin.glsl): one 2-D
// texture of the slots' tables stacked, slot s from row s x
// DERMIS_PREINTEGRATED_SLOT_ROWS up (its falloff, then its shadow table), for
// each slot whose technique is "preintegrated", built on the CPU when a slot's
// (profile, width scale) first needs it and kept while it stays (the shadow
// table depends on the profile only).

#include "gl/GlObjects.h"
#include "plan/SssPlan.h"

#include <array>

namespace dermis {

class PreintegratedTables {
public:
    // Builds the texture on first use and the layers whose slot changed.
    // Returns whether any slot uses the technique.
    bool prepare(const SssPlan& plan);
    GLuint texture() const { return mTexture.get(); }

private:
    struct Layer {
        const DiffusionProfile* profile = nullptr;
        float widthScale = 0.0f;
    };
    gl::Texture mTexture;
    std::array<Layer, DERMIS_MAX_PROFILES + 1> mLayers{};  // [slot]
};

}  // namespace dermis
