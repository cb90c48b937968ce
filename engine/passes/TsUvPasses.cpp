// The texture-space passes that work in a character's UV layout (TextureSpacePasses.h).
#include "passes/FullscreenPass.h"
#include "passes/LightingPass.h"
#include "passes/TextureSpacePasses.h"
#include "passes/TsPassSteps.h"

#include <algorithm>
#include <cstdio>

namespace dermis {
namespace {

struct TsmData {
    graph::TextureHandle tsm, depth;
};
struct StretchData {
    graph::TextureHandle stretch;
};
struct IrradianceData {
    graph::TextureHandle tsm, ambientOcclusion, depthKey, out;
    std::vector<graph::TextureHandle> shadowMaps;
};
struct FilterData {
    graph::TextureHandle in, stretch, out;
};

// Empty texels look this far for a chart. The head's gutters are 8 texels
// wide at 1024 (procedural/ProceduralHead.cpp); size / 128 fills them from either
// side at every size.
int dilationRadiusTexels(int size) { return std::clamp(size / 128, 2, 16); }

graph::TextureDesc uvDesc(const TsCharacterPlan& plan, graph::TextureFormat format) {
    const auto side = static_cast<uint32_t>(std::max(plan.size, 1));
    return {side, side, format};
}

// A pass that rasterises the mesh into its UV layout: the texels no triangle
// covers stay 0 (alpha 0 is how the dilation finds empty irradiance texels),
// and both faces count.
void beginUvRaster(const FrameContext& frame, GLuint texture, int size) {
    gl::Attachments attachments;
    attachments.colour[0] = texture;
    frame.gl->framebuffers->bind(attachments);
    frame.gl->setViewport(size, size);
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

// The mean of f (1 - f) for f uniform in [0, 1].
constexpr float kBilinearVarianceTexels2 = 1.0f / 6.0f;

}  // namespace

gpu::TextureSpaceBlock textureSpaceBlock(const FrameContext& frame, const TsCharacterPlan& plan) {
    const TextureSpaceSettings& ts = frame.plan.scene->settings.ts;
    gpu::TextureSpaceBlock block{};
    block.tsmClipFromWorld = plan.tsmClipFromWorld;
    block.tsmOriginM = plan.tsmOriginM;
    block.tsmAlongAxis = plan.tsmAlongAxis ? 1.0f : 0.0f;
    block.tsmAxis = plan.tsmAxis;
    block.hasTsm = plan.tsmLight >= 0 ? 1.0f : 0.0f;
    const float strength = ts.tsmStrength * frame.plan.scene->settings.transmittance.strength;
    // Chappuis 2011 listing 2.11 adds the TSM terms for the three widest of six
    // Gaussians: the narrow ones fade within a fraction of a millimetre and
    // only add speckle where the thickness vanishes at the light's silhouette.
    const float firstTsmGaussian = float(std::max<int>(1, static_cast<int>(plan.gaussians.size()) - kTsmGaussians));
    block.tsmPerMm = kTsThicknessPerMm;
    block.tsmStrength = strength;
    block.tsmSideTexels = float(plan.tsmSize);
    block.tsmFirstGaussian = firstTsmGaussian;
    block.sideTexels = float(plan.size);
    block.texelUv = 1.0f / float(std::max(plan.size, 1));
    block.seamBlendStdDevs = ts.seamBlend;
    block.gaussianCount = float(std::min<size_t>(plan.gaussians.size(), DERMIS_MAX_PROFILE_GAUSSIANS));
    const glm::mat4& worldFromObject = frame.plan.characters[static_cast<size_t>(plan.character)].worldFromObject;
    block.dilationTexels = float(dilationRadiusTexels(plan.size));
    block.metresPerObjectUnit = glm::length(glm::vec3(worldFromObject[0]));
    for (size_t i = 0; i < plan.gaussians.size() && i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
        block.gaussians[i] = plan.gaussians[i];
    }
    return block;
}

void uploadTsBlocks(const FrameContext& frame, const TsCharacterPlan& plan, const gpu::TextureSpaceBlock& block) {
    frame.gl->uploadObject(frame.objectBlock(static_cast<size_t>(plan.character)));
    frame.gl->uploadPassBlock(&block, sizeof block);
}

void drawTsMesh(const FrameContext& frame, const TsCharacterPlan& plan, TsDraw what) {
    const auto index = static_cast<size_t>(plan.character);
    const TsMesh& mesh = frame.gl->tsMeshes->get(index);
    if (what == TsDraw::WholeCharacter) {
        mesh.draw();
        return;
    }
    const GpuCharacter& character = frame.gl->gpuScene->characters()[index];
    glBindVertexArray(mesh.vertexArray.get());
    for (size_t s : plan.submeshes) {
        frame.gl->uploadObject(frame.objectBlock(index, s));
        if (what == TsDraw::SurfaceWithMaps) {
            const GpuMaterial& material = character.material(character.submeshes[s].material);
            bindMaterialMaps(material);
            glBindTextureUnit(DERMIS_UNIT_TS_LEAN_MAP, material.leanMap1.get());
        }
        character.submeshes[s].draw();
    }
}

std::string tsPassName(const TsCharacterPlan& plan, const std::string& step) { return "ts " + plan.label + " " + step; }

graph::TextureHandle addTsmPass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                graph::TextureHandle black) {
    const auto side = static_cast<uint32_t>(std::max(plan.tsmSize, 1));
    const std::string name = tsPassName(plan, "tsm");
    return graph
        .addPass<TsmData>(
            name,
            [&](graph::PassBuilder& builder, TsmData& d) {
                d.tsm = builder.create(name, {side, side, graph::TextureFormat::Rgba32F});
                d.depth = builder.create(name + " depth", {side, side, graph::TextureFormat::Depth32F});
                builder.passThrough(d.tsm, black);
                builder.skipIf(!plan.runs(), plan.skipReason());
                builder.skipIf(!frame.plan.scene->settings.ts.tsm, "translucent shadow map off");
                builder.skipIf(!frame.plan.scene->settings.transmittance.enabled, "transmittance disabled");
                builder.skipIf(plan.tsmLight < 0, "no shadow-casting light behind the character");
            },
            [frame, plan](const graph::PassResources& resources, const TsmData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.tsm);
                attachments.depth = resources.texture(d.depth);
                frame.gl->framebuffers->bind(attachments);
                frame.gl->setViewport(plan.tsmSize, plan.tsmSize);
                const float empty[4] = {1e30f, 0.0f, 0.0f, 0.0f};
                glClearBufferfv(GL_COLOR, 0, empty);
                const float farDepth = 1.0f;
                glDepthMask(GL_TRUE);
                glClearBufferfv(GL_DEPTH, 0, &farDepth);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                glDepthMask(GL_TRUE);
                glDisable(GL_CULL_FACE);  // thin ears need both faces
                glUseProgram(frame.gl->programs->tsTsm.get());
                uploadTsBlocks(frame, plan, textureSpaceBlock(frame, plan));
                drawTsMesh(frame, plan, TsDraw::WholeCharacter);  // light crosses every submesh
                glDisable(GL_DEPTH_TEST);
            })
        .tsm;
}

graph::TextureHandle addTsStretchPass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan) {
    const std::string name = tsPassName(plan, "stretch");
    return graph
        .addPass<StretchData>(
            name,
            [&](graph::PassBuilder& builder, StretchData& d) {
                d.stretch = builder.create(name, uvDesc(plan, graph::TextureFormat::Rg16F));
                builder.skipIf(!plan.runs(), plan.skipReason());
            },
            [frame, plan](const graph::PassResources& resources, const StretchData& d) {
                beginUvRaster(frame, resources.texture(d.stretch), plan.size);
                glUseProgram(frame.gl->programs->tsStretch.get());
                uploadTsBlocks(frame, plan, textureSpaceBlock(frame, plan));
                drawTsMesh(frame, plan, TsDraw::Surface);
            })
        .stretch;
}

graph::TextureHandle addIrradiancePass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                       const GBuffer& gbuffer, const std::vector<graph::TextureHandle>& shadowMaps,
                                       graph::TextureHandle ambientOcclusion, graph::TextureHandle tsm,
                                       BuriedTexels buried) {
    const std::string name = tsPassName(plan, "irradiance");
    return graph
        .addPass<IrradianceData>(
            name,
            [&](graph::PassBuilder& builder, IrradianceData& d) {
                d.tsm = builder.read(tsm);
                d.ambientOcclusion = builder.read(ambientOcclusion);
                d.depthKey = builder.read(gbuffer.depthKey);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                d.out = builder.create(name, uvDesc(plan, graph::TextureFormat::Rgba16F));
                builder.skipIf(!plan.runs(), plan.skipReason());
            },
            [frame, plan, buried](const graph::PassResources& resources, const IrradianceData& d) {
                beginUvRaster(frame, resources.texture(d.out), plan.size);
                glUseProgram(frame.gl->programs->tsIrradiance.get(frame.plan.environment.enabled(), frame.plan.lights.shadowCode));
                // The normal the G-buffer takes: the LEAN mean normal in LEAN frames (gbuffer.frag).
                glUniform1i(DERMIS_LOCATION_TS_LEAN_NORMALS, frame.plan.lean ? 1 : 0);
                glUniform1i(DERMIS_LOCATION_TS_BURIED_EMPTY, buried == BuriedTexels::Empty ? 1 : 0);
                glBindTextureUnit(2, resources.texture(d.tsm));
                glBindTextureUnit(3, resources.texture(d.ambientOcclusion));
                bindShadowMaps(frame, resources, d.shadowMaps);
                glBindTextureUnit(8, resources.texture(d.depthKey));
                uploadTsBlocks(frame, plan, textureSpaceBlock(frame, plan));
                drawTsMesh(frame, plan, TsDraw::SurfaceWithMaps);
            })
        .out;
}

graph::TextureHandle addDilatePass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                   graph::TextureHandle irradiance) {
    const std::string name = tsPassName(plan, "dilate");
    return graph
        .addPass<FilterData>(
            name,
            [&](graph::PassBuilder& builder, FilterData& d) {
                d.in = builder.read(irradiance);
                d.out = builder.create(tsPassName(plan, "dilated"), uvDesc(plan, graph::TextureFormat::Rgba16F));
                builder.skipIf(!plan.runs(), plan.skipReason());
            },
            [frame, plan](const graph::PassResources& resources, const FilterData& d) {
                uploadTsBlocks(frame, plan, textureSpaceBlock(frame, plan));
                runFullscreenPass(frame, resources, {{d.out}}, frame.gl->programs->tsDilate.get(), {d.in});
            })
        .out;
}

std::vector<graph::TextureHandle> addBlurPasses(graph::RenderGraph& graph, const FrameContext& frame,
                                                const TsCharacterPlan& plan, graph::TextureHandle stretch,
                                                graph::TextureHandle dilated) {
    const BlurKernel& kernel = frame.plan.tsKernel;
    std::vector<graph::TextureHandle> textures;
    const float kernelVariance = kernelVarianceSigma2(kernel);
    bool firstBlur = true;
    for (const TsStep& step : plan.steps) {
        const std::string name = tsPassName(plan, "g" + std::to_string(step.gaussian));
        const graph::TextureHandle previous = textures.empty() ? dilated : textures.back();
        // The kernel's own variance is a little over 1 sigma^2 (BlurKernel.h), so
        // sigma is scaled for the step to blur by exactly its variance.
        gpu::TextureSpaceBlock block = textureSpaceBlock(frame, plan);
        const int taps = writeKernelTaps(kernel, block.kernel);
        const float sigmaMm = std::sqrt(std::max(step.stepVarianceMm2, 0.0f) / kernelVariance);
        char narrow[96];
        std::snprintf(narrow, sizeof narrow, "%.2f texels wide where the layout is densest (under %.2f)",
                      double(step.widthTexels), double(kMinStepTexels));
        const std::string why = !plan.runs() ? plan.skipReason() : std::string(narrow);
        const auto run = [frame, plan](const graph::PassResources& resources, const FilterData& d,
                                        const gpu::TextureSpaceBlock& b) {
            uploadTsBlocks(frame, plan, b);
            runFullscreenPass(frame, resources, {{d.out}}, frame.gl->programs->tsBlur.get(), {d.in, d.stretch});
        };
        block.stepSigmaMm = std::sqrt(std::max(step.stepVarianceMm2, 0.0f));
        // The gather reads the blurred textures bilinearly, which blurs by
        // f (1 - f) texels^2 more at fraction f between texel centres, 1/6 on
        // average; the first blur leaves that much out (ts_blur.frag).
        block.omittedVarianceTexels2 = firstBlur && !step.skipped ? kBilinearVarianceTexels2 : 0.0f;
        firstBlur = firstBlur && step.skipped;
        block.blurDirection = glm::vec2(1.0f, 0.0f);
        block.blurSigmaMm = sigmaMm;
        block.blurTaps = float(taps);
        const FilterData& u = graph.addPass<FilterData>(
            name + " u",
            [&](graph::PassBuilder& builder, FilterData& d) {
                d.in = builder.read(previous);
                d.stretch = builder.read(stretch);
                d.out = builder.create(name + " u", uvDesc(plan, graph::TextureFormat::Rgba16F));
                builder.skipIf(step.skipped, why);
            },
            [run, block](const graph::PassResources& resources, const FilterData& d) { run(resources, d, block); });
        block.blurDirection = glm::vec2(0.0f, 1.0f);
        block.blurSigmaMm = sigmaMm;
        block.blurTaps = float(taps);
        const FilterData& v = graph.addPass<FilterData>(
            name + " v",
            [&](graph::PassBuilder& builder, FilterData& d) {
                d.in = builder.read(u.out);
                d.stretch = builder.read(stretch);
                d.out = builder.create(name, uvDesc(plan, graph::TextureFormat::Rgba16F));
                builder.passThrough(d.out, previous);
                builder.skipIf(step.skipped, why);
            },
            [run, block](const graph::PassResources& resources, const FilterData& d) { run(resources, d, block); });
        textures.push_back(v.out);
    }
    return textures;
}

}  // namespace dermis
