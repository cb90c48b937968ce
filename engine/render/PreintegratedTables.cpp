#include "render/PreintegratedTables.h"

#include "scene/SssTechniques.h"
#include "sss/PreintegratedShadow.h"
#include "sss/PreintegratedTable.h"

namespace dermis {

bool PreintegratedTables::prepare(const SssPlan& plan) {
    bool any = false;
    for (const SssSlotPlan& slot : plan.slots) {
        if (!sssTechniqueInfo(slot.choice.technique).scattersInLighting) continue;
        any = true;
        if (!mTexture.isValid()) {
            mTexture = gl::createTexture(GL_TEXTURE_2D);
            glTextureStorage2D(mTexture.get(), 1, GL_RGBA16F, kPreintegratedCosines,
                               DERMIS_PREINTEGRATED_SLOT_ROWS * (DERMIS_MAX_PROFILES + 1));
            glTextureParameteri(mTexture.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(mTexture.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(mTexture.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(mTexture.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        }
        Layer& layer = mLayers[size_t(slot.slot)];
        if (layer.profile == slot.profile && layer.widthScale == slot.widthScale) continue;
        const int firstRow = slot.slot * DERMIS_PREINTEGRATED_SLOT_ROWS;
        const PreintegratedTable falloff = makePreintegratedTable(*slot.profile, slot.widthScale);
        glTextureSubImage2D(mTexture.get(), 0, 0, firstRow, falloff.cosines, falloff.curvatures, GL_RGB, GL_FLOAT,
                            falloff.texels.data());
        if (layer.profile != slot.profile) {
            const PreintegratedShadowTable shadow = makePreintegratedShadowTable(*slot.profile);
            glTextureSubImage2D(mTexture.get(), 0, 0, firstRow + falloff.curvatures, shadow.coverages, shadow.rows, GL_RGBA,
                                GL_FLOAT, shadow.texels.data());
        }
        layer = {slot.profile, slot.widthScale};
    }
    return any;
}

}  // namespace dermis
