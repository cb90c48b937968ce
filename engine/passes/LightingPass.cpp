#include "passes/LightingPass.h"

#include "passes/FullscreenPass.h"
#include "plan/ScreenRegions.h"
#include "scene/SssTechniques.h"

#include <algorithm>

namespace dermis {
namespace {
struct LightingData {
    GBuffer gbuffer;
    std::vector<graph::TextureHandle> shadowMaps;
    graph::TextureHandle ambientOcclusion;
    graph::TextureHandle leanCross;
    graph::TextureHandle scatter;  // read where a technique scatters in this pass (render/LightingScatter.h): slot, curvature
    Lighting out;
};
// The screen rectangles of the slots whose technique scatters in this pass
// (plan/ScreenRegions.h): the pass draws the frame with the program without
// that code, then these rectangles again with it. On a CPU driver the code
// costs every pixel it is compiled into (docs/shadows.md, "Only the filters
// a frame uses"); the pixels it draws are written, not blended, so a
// rectangle drawn twice is the same.
std::vector<glm::ivec4> lightingScatterRegions(const SssPlan& sss) {
    std::vector<glm::ivec4> rects;
    for (const SssSlotPlan& slot : sss.slots) {
        if (!scattersInLightingPass(slot)) continue;
        rects.insert(rects.end(), slot.regions.begin(), slot.regions.end());
    }
    return disjointCover(rects);
}

// Whether every submesh of the character scatters in this pass: the draw
// without that code then leaves the character to the second draw, which
// covers exactly the slots that scattersInLightingPass names (with SSS off,
// a slot of the pre-integrated technique is not visible and the first draw
// lights the character).
bool onlyScattersInLighting(const SssPlan& sss, size_t character) {
    if (character >= sss.slotsOfCharacter.size() || sss.slotsOfCharacter[character].empty()) return false;
    for (int slot : sss.slotsOfCharacter[character]) {
        const auto found = std::find_if(sss.slots.begin(), sss.slots.end(), [slot](const SssSlotPlan& s) { return s.slot == slot; });
        if (found == sss.slots.end() || !scattersInLightingPass(*found)) return false;
    }
    return true;
}

}  // namespace

void bindShadowMaps(const FrameContext& frame, const graph::PassResources& resources,
                    const std::vector<graph::TextureHandle>& shadowMaps) {
    for (size_t slot = 0; slot < DERMIS_MAX_SHADOWED_LIGHTS; ++slot) {
        const GLuint map = slot < shadowMaps.size() ? resources.texture(shadowMaps[slot]) : frame.gl->whiteTexture;
        glBindTextureUnit(static_cast<GLuint>(4 + slot), map);
    }
}

Lighting addLightingPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                         const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle ambientOcclusion,
                         bool shadowVisibility) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    return graph
        .addPass<LightingData>(
            "lighting",
            [&](graph::PassBuilder& builder, LightingData& d) {
                d.gbuffer.depthStencil = builder.read(gbuffer.depthStencil);
                d.gbuffer.albedo = builder.read(gbuffer.albedo);
                d.gbuffer.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.ambientOcclusion = builder.read(ambientOcclusion);
                if (gbuffer.hasLean()) d.leanCross = builder.read(gbuffer.leanCross);
                if (gbuffer.environment.isValid()) d.gbuffer.environment = builder.read(gbuffer.environment);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                if (frame.plan.sss.anyScattersInLighting()) {
                    d.scatter = builder.read(gbuffer.scatter);
                }
                d.out.irradiance = builder.create("irradiance", {w, h, graph::TextureFormat::Rgba16F});
                d.out.specular = builder.create("specular", {w, h, graph::TextureFormat::Rgba16F});
                if (shadowVisibility) d.out.visibility = builder.create("shadow visibility", {w, h, graph::TextureFormat::Rgba8});
            },
            [frame, regions = characterRegions(frame.plan,
                                               [&sss = frame.plan.sss](size_t c) { return !onlyScattersInLighting(sss, c); }),
             scatterRegions = lightingScatterRegions(frame.plan.sss)](const graph::PassResources& resources,
                                                                      const LightingData& d) {
                const bool lean = d.leanCross.isValid();
                const Programs& programs = *frame.gl->programs;
                const LightingPrograms& variants = lean ? programs.lightingLean : programs.lighting;
                const bool environmentLit = frame.plan.environment.enabled();
                beginFullscreenPass(frame, resources, {{d.out.irradiance, d.out.specular, d.out.visibility}},
                                    variants.get(environmentLit, frame.plan.lights.shadowCode, false),
                                    {d.gbuffer.depthStencil, d.gbuffer.albedo, d.gbuffer.normalMaterial,
                                     d.ambientOcclusion});
                bindShadowMaps(frame, resources, d.shadowMaps);
                if (lean) glBindTextureUnit(8, resources.texture(d.leanCross));
                if (d.gbuffer.environment.isValid()) glBindTextureUnit(9, resources.texture(d.gbuffer.environment));
                if (d.scatter.isValid()) {
                    glBindTextureUnit(10, resources.texture(d.scatter));
                    glBindTextureUnit(DERMIS_UNIT_FIRST_PASS_EXTRA, frame.gl->lightingTables);
                }
                // The background's irradiance, specular and visibility are 0 (lighting.frag).
                drawCharacterPixels(frame, regions, d.out.visibility.isValid() ? 3 : 2, glm::vec4(0.0f));
                if (d.scatter.isValid()) {
                    glUseProgram(variants.get(environmentLit, frame.plan.lights.shadowCode, true));
                    frame.gl->drawRegions(scatterRegions);
                }
            })
        .out;
}

}  // namespace dermis
