#pragma once
// C++ view of shaders/include/UniformBlocks.glsl (the single definition).

#include <glm/glm.hpp>

#include <cstddef>

namespace dermis::gpu {

using mat4 = glm::mat4;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using ivec2 = glm::ivec2;
using uint = unsigned int;

#include "include/UniformBlocks.glsl"
#include "include/Sanitise.glsl"

static_assert(sizeof(FrameBlock) == 5 * 64 + 7 * 16, "FrameBlock must match std140");
static_assert(sizeof(CharactersBlock) == (DERMIS_MAX_CHARACTERS + 1) * 16, "CharactersBlock must match std140");
static_assert(sizeof(ProfileParams) == (DERMIS_MAX_PROFILE_GAUSSIANS + 2) * 16, "ProfileParams must match std140");
static_assert(sizeof(ProfilesBlock) == (DERMIS_MAX_PROFILES + 1) * sizeof(ProfileParams) + 16, "ProfilesBlock must match std140");
static_assert(sizeof(GpuLight) == 64 + 6 * 16, "GpuLight must match std140");
static_assert(offsetof(GpuLight, type) == 64 + 12 && offsetof(GpuLight, shadowSlot) == 64 + 16 + 12 &&
                  offsetof(GpuLight, backLight) == 64 + 2 * 16 + 12 && offsetof(GpuLight, spotCosInner) == 64 + 3 * 16 &&
                  offsetof(GpuLight, shadowFilter) == 64 + 4 * 16 + 12 && offsetof(GpuLight, shadowOrthographic) == 64 + 5 * 16 + 8,
              "named fields sit at their std140 offsets");
static_assert(sizeof(LightsBlock) == DERMIS_MAX_LIGHTS * sizeof(GpuLight), "LightsBlock must match std140");
static_assert(sizeof(ObjectBlock) == 2 * 64 + (5 + DERMIS_SH_COEFFICIENTS) * 16, "ObjectBlock must match std140");
static_assert(offsetof(ObjectBlock, roughness) == 2 * 64 + 12 && offsetof(ObjectBlock, flipV) == 2 * 64 + 2 * 16 &&
                  offsetof(ObjectBlock, profileSlot) == 2 * 64 + 2 * 16 + 12 &&
                  offsetof(ObjectBlock, hasThicknessMap) == 2 * 64 + 4 * 16 + 8 &&
                  offsetof(ObjectBlock, environmentSh) == 2 * 64 + 5 * 16,
              "named fields sit at their std140 offsets");
static_assert(sizeof(EnvironmentBlock) ==
                  64 + (2 * DERMIS_SH_COEFFICIENTS + 2 + DERMIS_AVERAGE_ALBEDO_SIZE / 4 + DERMIS_AVERAGE_ALBEDO_SIZE) * 16,
              "EnvironmentBlock must match std140");
static_assert(sizeof(SssEdgeParams) == 16, "SssEdgeParams is one std140 group");
static_assert(sizeof(SssBlurBlock) == (DERMIS_MAX_BLUR_TAPS + 3) * 16, "SssBlurBlock must match std140");
static_assert(offsetof(SssBlurBlock, sigmaMm) == DERMIS_MAX_BLUR_TAPS * 16 + 8 &&
                  offsetof(SssBlurBlock, edges) == (DERMIS_MAX_BLUR_TAPS + 1) * 16 &&
                  offsetof(SeparableSssBlock, edges) == (DERMIS_MAX_SEPARABLE_SAMPLES + 1) * 16 &&
                  offsetof(DiskSssBlock, largestRadiusMm) == (2 * DERMIS_MAX_DISK_SAMPLES + 1) * 16 + 4,
              "named fields sit at their std140 offsets");
static_assert(offsetof(ProfileParams, gaussianCount) == DERMIS_MAX_PROFILE_GAUSSIANS * 16 + 12 &&
                  offsetof(ProfilesBlock, anyScattersInLighting) == (DERMIS_MAX_PROFILES + 1) * sizeof(ProfileParams) + 8,
              "named fields sit at their std140 offsets");
static_assert(offsetof(FrameBlock, pixelSizeUv) == 5 * 64 + 16 + 8 && offsetof(FrameBlock, farM) == 5 * 64 + 2 * 16 + 4 &&
                  offsetof(EnvironmentBlock, intensity) == DERMIS_SH_COEFFICIENTS * 16 + 64 + 12 &&
                  offsetof(EnvironmentBlock, skybox) == DERMIS_SH_COEFFICIENTS * 16 + 64 + 16 + 4 &&
                  offsetof(CharacterParams, hasLeanMaps) == 12,
              "named fields sit at their std140 offsets");
static_assert(offsetof(FrameBlock, aov) == 5 * 64 + 5 * 16 + 12 && offsetof(FrameBlock, materialMipBias) == 5 * 64 + 6 * 16 + 12,
              "named fields sit at their std140 offsets");
static_assert(offsetof(SsaoBlock, blurHalfWidthPx) == 16 && offsetof(SkinningBlock, writeDerivatives) == 8,
              "named fields sit at their std140 offsets");
static_assert(sizeof(SeparableSssBlock) == (DERMIS_MAX_SEPARABLE_SAMPLES + 2) * 16, "SeparableSssBlock must match std140");
static_assert(sizeof(DiskSssBlock) == (2 * DERMIS_MAX_DISK_SAMPLES + 2) * 16, "DiskSssBlock must match std140");
static_assert(sizeof(SsaoBlock) == 2 * 16, "SsaoBlock must match std140");
static_assert(offsetof(TextureSpaceBlock, hasTsm) == 64 + 16 + 12 && offsetof(TextureSpaceBlock, gaussianCount) == 64 + 3 * 16 + 12 &&
                  offsetof(TextureSpaceBlock, blurTaps) == 64 + 4 * 16 + 12 &&
                  offsetof(TextureSpaceBlock, omittedVarianceTexels2) == 64 + 5 * 16 + 12,
              "named fields sit at their std140 offsets");
static_assert(sizeof(TextureSpaceBlock) == 64 + (6 + DERMIS_MAX_BLUR_TAPS + DERMIS_MAX_PROFILE_GAUSSIANS) * 16,
              "TextureSpaceBlock must match std140");
static_assert(sizeof(SkinningBlock) == 16, "SkinningBlock must match std140");
static_assert(sizeof(ScreenRegionsBlock) == DERMIS_MAX_SCREEN_REGIONS * 16, "ScreenRegionsBlock must match std140");
static_assert(sizeof(SanitiseBlock) == 8 * 4, "SanitiseBlock must match std430");
static_assert(sizeof(FrameBlock) % 16 == 0 && sizeof(ObjectBlock) % 16 == 0, "std140 blocks are vec4-aligned");

}  // namespace dermis::gpu
