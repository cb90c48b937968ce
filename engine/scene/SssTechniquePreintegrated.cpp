// Pre-integrated skin shading (Penner & Borshukov 2011): the lighting pass
// looks each light's N.L and the surface's curvature up in a table of the
// profile's falloff (sss/PreintegratedTable.h), and each shadowed light's
// coverage of a disc in the table of the shadow the profile scatters
// (sss/PreintegratedShadow.h); shaders/include/PreintegratedSkin.glsl reads
// both. No pass blurs anything.
#include "scene/SssTechniques.h"

#include "sss/PreintegratedShadow.h"
#include "sss/PreintegratedTable.h"

namespace dermis {
namespace {

static_assert(kPreintegratedShadowCoverages == kPreintegratedCosines, "the shadow rows are as wide as the falloff's");

// A slot's table (DERMIS_PREINTEGRATED_SLOT_ROWS rows): the falloff's rows, then the shadow's.
std::vector<glm::vec4> slotTable(const DiffusionProfile& profile, float widthScale) {
    const PreintegratedTable falloff = makePreintegratedTable(profile, widthScale);
    const PreintegratedShadowTable shadow = makePreintegratedShadowTable(profile);
    std::vector<glm::vec4> texels;
    texels.reserve(falloff.texels.size() + shadow.texels.size());
    for (const glm::vec3& texel : falloff.texels) texels.emplace_back(texel, 1.0f);
    texels.insert(texels.end(), shadow.texels.begin(), shadow.texels.end());
    return texels;
}

float shadowSigmaMm(const DiffusionProfile& profile, float widthScale) {
    return float(preintegratedShadowSigmaMm(profile, widthScale));
}

}  // namespace

SssTechniqueInfo preintegratedTechnique() {
    SssTechniqueInfo info;
    info.technique = SssTechnique::Preintegrated;
    info.lighting.glslFile = "PreintegratedSkin.glsl";
    info.lighting.glslPrefix = "preintegrated";
    info.lighting.tableColumns = kPreintegratedCosines;
    info.lighting.tableRows = DERMIS_PREINTEGRATED_SLOT_ROWS;
    info.lighting.makeTable = slotTable;
    info.lighting.slotParameter = shadowSigmaMm;
    SssChoice choice;
    choice.technique = info.technique;
    info.candidates = {choice};
    return info;
}

}  // namespace dermis
