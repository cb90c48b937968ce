#include "render/FrameResources.h"

#include "gl/TexturePool.h"
#include "brdf/BeckmannTable.h"
#include "brdf/EnergyTable.h"
#include "scene/SssTechniques.h"

#include <algorithm>

namespace dermis {
namespace {

gl::Texture makeTableTexture(const std::vector<float>& table, int size, std::string_view label) {
    const auto side = static_cast<uint32_t>(size);
    gl::Texture texture = gl::createTexture2D({side, side, graph::TextureFormat::R32F}, label);
    glTextureSubImage2D(texture.get(), 0, 0, 0, size, size, GL_RED, GL_FLOAT, table.data());
    return texture;
}

gl::Texture makeSolidTexture(float value, std::string_view label) {
    gl::Texture texture = gl::createTexture2D({1, 1, graph::TextureFormat::Rgba8}, label);
    const float texel[4] = {value, value, value, value};
    glTextureSubImage2D(texture.get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, texel);
    return texture;
}

gl::Buffer makeUniformBuffer(size_t bytes, std::string_view label) {
    gl::Buffer buffer = gl::createBuffer(label);
    glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

}  // namespace

FrameResources::FrameResources(const GpuScene& gpuScene, const Programs& programs, gl::FramebufferCache& framebuffers)
    : mGpuScene(gpuScene) {
    mFrameUniforms = makeUniformBuffer(sizeof(gpu::FrameBlock), "frame: FrameBlock");
    mLightUniforms = makeUniformBuffer(sizeof(gpu::LightsBlock), "frame: LightsBlock");
    mObjectUniforms = makeUniformBuffer(sizeof(gpu::ObjectBlock), "frame: ObjectBlock");
    mCharacterUniforms = makeUniformBuffer(sizeof(gpu::CharactersBlock), "frame: CharactersBlock");
    mProfileUniforms = makeUniformBuffer(sizeof(gpu::ProfilesBlock), "frame: ProfilesBlock");
    mPassUniforms = makeUniformBuffer(kMaxPassBlockBytes, "frame: pass blocks");
    mRegionUniforms = makeUniformBuffer(sizeof(gpu::ScreenRegionsBlock), "frame: ScreenRegionsBlock");
    mEmptyVertexArray = gl::createVertexArray("frame: empty vertex array (full-screen passes)");
    mBeckmann = makeTableTexture(makeBeckmannTable(kBeckmannTableSize), kBeckmannTableSize, "frame: Beckmann table");
    mEnergy = makeTableTexture(makeEnergyTable(kEnergyTableSize), kEnergyTableSize, "frame: energy table");
    mWhite = makeSolidTexture(1.0f, "frame: white");
    mBlack = makeSolidTexture(0.0f, "frame: black");

    mServices.gpuScene = &mGpuScene;
    mServices.programs = &programs;
    mServices.framebuffers = &framebuffers;
    mServices.tsMeshes = &mTsMeshes;
    mServices.environment = &mEnvironment;
    mServices.objectUniforms = mObjectUniforms.get();
    mServices.passUniforms = mPassUniforms.get();
    mServices.regionUniforms = mRegionUniforms.get();
    mServices.emptyVertexArray = mEmptyVertexArray.get();
    mServices.whiteTexture = mWhite.get();
    mServices.blackTexture = mBlack.get();
}

Status FrameResources::prepare(const FramePlan& plan, SceneGeometry& geometry) {
    GLint maxTexture = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    if (plan.width > maxTexture || plan.height > maxTexture) {
        return makeError("frame size", "larger than this GL's maximum texture size " + std::to_string(maxTexture));
    }
    uploadFrameBlocks(plan);
    uploadSssBlocks(plan);
    prepareOutput(plan);
    prepareShadowMaps(plan);
    mEnvironment.prepare(plan.environment, *plan.scene);
    if (plan.environment.transfer) {
        for (size_t c = 0; c < plan.characters.size(); ++c) {
            const bool animated = !mGpuScene.characters()[c].rig.empty();
            if (const Status made = mEnvironment.prepareTransfer(c, geometry.mesh(c), animated, plan.environment,
                                                                 glm::mat3(plan.characters[c].worldFromObject));
                !made.ok())
                return made;
            GpuEnvironment::attachTransfer(mGpuScene.characters()[c].mesh.vertexArray.get(), mEnvironment.drawnTransfer(c));
        }
    }
    for (const TsCharacterPlan& character : plan.ts.characters) {
        const auto index = static_cast<size_t>(character.character);
        mTsMeshes.prepare(index, mGpuScene.characters()[index], geometry.uvLayout(index, plan.characters[index].metresPerUnit()));
        if (plan.environment.transfer) {
            GpuEnvironment::attachTransfer(mTsMeshes.get(index).vertexArray.get(), mEnvironment.drawnTransfer(index));
        }
    }
    return success();
}

void FrameResources::uploadFrameBlocks(const FramePlan& plan) {
    const Scene& scene = *plan.scene;
    const Camera& camera = scene.camera;
    const RenderSettings& settings = scene.settings;
    gpu::FrameBlock frame{};
    frame.viewFromWorld = plan.view.viewFromWorld;
    frame.worldFromView = glm::inverse(frame.viewFromWorld);
    frame.clipFromView = plan.view.clipFromView;
    frame.viewFromClip = glm::inverse(frame.clipFromView);
    frame.clipFromWorld = frame.clipFromView * frame.viewFromWorld;
    frame.cameraPositionM = glm::vec4(camera.positionM, 1.0f);
    frame.viewportPx = glm::vec2(plan.width, plan.height);
    frame.pixelSizeUv = 1.0f / frame.viewportPx;
    frame.nearM = camera.nearM;
    frame.farM = camera.farM;
    frame.ambient = glm::vec4(settings.ambient, 0.0f);
    frame.background = glm::vec4(scene.background.colour, 1.0f);
    frame.exposure = settings.exposure;
    frame.toneMap = static_cast<int>(settings.toneMap);
    frame.mixRatio = settings.sss.mix;
    frame.lightCount = int(plan.lights.lightCount);
    frame.aov = int(plan.aov);
    frame.energyConservation = settings.energyConservation ? 1 : 0;
    frame.pixelsPerMetreAtUnitDepth = plan.view.pixelsPerMetreAtUnitDepth();
    frame.ssaoStrength = settings.ssao.strength;
    frame.materialMipBias = plan.materialMipBias;
    frame.transmittanceSkipSigmas = plan.transmittanceSkipSigmas;
    glNamedBufferSubData(mFrameUniforms.get(), 0, sizeof frame, &frame);
    glNamedBufferSubData(mLightUniforms.get(), 0, sizeof(gpu::LightsBlock), &plan.lights.block);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_FRAME, mFrameUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_LIGHTS, mLightUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_OBJECT, mObjectUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_CHARACTERS, mCharacterUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PROFILES, mProfileUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PASS, mPassUniforms.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_SCREEN_REGIONS, mRegionUniforms.get());
    glBindTextureUnit(kBeckmannUnit, mBeckmann.get());
    glBindTextureUnit(kEnergyUnit, mEnergy.get());
}

void FrameResources::uploadSssBlocks(const FramePlan& plan) {
    const Scene& scene = *plan.scene;
    const SsaoSettings& ssao = scene.settings.ssao;
    gpu::CharactersBlock characters{};
    const size_t count = std::min<size_t>(scene.characters.size(), DERMIS_MAX_CHARACTERS);
    for (size_t c = 0; c < count; ++c) {
        const Character& character = scene.characters[c];
        const float radiusM = character.ssao.radiusM > 0.0f ? character.ssao.radiusM : ssao.radiusM;
        const int samples = character.ssao.samples > 0 ? character.ssao.samples : ssao.samples;
        const bool lean = c < mGpuScene.characters().size() && mGpuScene.characters()[c].hasLeanMaps();
        gpu::CharacterParams& params = characters.characters[c + 1];
        params.ssaoRadiusM = radiusM;
        params.ssaoSamples = float(samples);
        params.hasLeanMaps = lean ? 1.0f : 0.0f;
    }
    glNamedBufferSubData(mCharacterUniforms.get(), 0, sizeof characters, &characters);

    gpu::ProfilesBlock profiles{};
    // The lighting pass reads the tables (and binds them) only where a visible slot needs them.
    const bool lightingTables = mLightingTables.prepare(plan.sss) && plan.sss.anyScattersInLighting();
    mServices.lightingTables = lightingTables ? mLightingTables.texture() : 0;
    for (const SssSlotPlan& slot : plan.sss.slots) {
        gpu::ProfileParams& p = profiles.profiles[slot.slot];
        const auto& gaussians = slot.profile->gaussians();
        const size_t n = std::min<size_t>(gaussians.size(), DERMIS_MAX_PROFILE_GAUSSIANS);
        for (size_t i = 0; i < n; ++i) p.gaussians[i] = glm::vec4(gaussians[i].weight, gaussians[i].varianceMm2);
        p.gaussianCount = int(n);
        p.initWeight = slot.initWeight;
        const SssLightingScatter& lighting = sssTechniqueInfo(slot.choice.technique).lighting;
        p.lightingTechnique = lightingTechniqueId(slot.choice.technique);
        p.lightingParameter = lighting.slotParameter ? lighting.slotParameter(*slot.profile, slot.widthScale) : 0.0f;
    }
    profiles.transmittanceShrinkMm = scene.settings.transmittance.shrinkMm;
    profiles.transmittanceStrength = scene.settings.transmittance.strength;
    profiles.anyScattersInLighting = lightingTables ? 1 : 0;
    glNamedBufferSubData(mProfileUniforms.get(), 0, sizeof profiles, &profiles);
}

void FrameResources::prepareOutput(const FramePlan& plan) {
    const graph::TextureDesc desc = frameOutputDesc(plan);
    if (mOutput.isValid() && desc == mOutputDesc) return;
    if (mOutput.isValid()) mServices.framebuffers->forget(mOutput.get());
    mOutput = gl::createTexture2D(desc, "frame: output");
    mOutputDesc = desc;
}

void FrameResources::prepareShadowMaps(const FramePlan& plan) {
    mShadowMapsUsed = plan.shadows.size();
    for (size_t slot = 0; slot < plan.shadows.size(); ++slot) {
        ShadowMap& map = mShadowMaps[slot];
        const graph::TextureDesc& desc = plan.shadows[slot].desc;
        if (map.texture.isValid() && map.desc == desc) continue;
        // With a max-depth mip chain (shaders/shadow_max.comp); lookups read level 0.
        map.texture = gl::createTexture2D(desc, "shadow map " + std::to_string(slot), gl::fullMipLevelCount(desc.width, desc.height));
        // Outside the map means "unoccluded": clamp to a far border.
        glTextureParameteri(map.texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(map.texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        map.desc = desc;
    }
}

FrameInputs FrameResources::inputs() const {
    FrameInputs inputs;
    inputs.output = mOutput.get();
    inputs.white = mWhite.get();
    inputs.black = mBlack.get();
    for (size_t slot = 0; slot < mShadowMapsUsed; ++slot) inputs.shadowMaps.push_back(mShadowMaps[slot].texture.get());
    inputs.services = &mServices;
    return inputs;
}

}  // namespace dermis
