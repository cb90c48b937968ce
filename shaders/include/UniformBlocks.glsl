// Uniform blocks shared by C++ and GLSL: the one definition of each block.
//
// C++ includes this file through engine/gpu/UniformBlocks.h, which maps
// the GLSL types onto glm and static_asserts every size; GLSL includes it
// with `#include "UniformBlocks.glsl"`. Layout is std140, so:
//   - members are vec4, ivec4 and mat4, or named scalars and vec2s in
//     groups that fill 16 bytes each (a vec2 and two scalars, or four
//     scalars, or a vec3 and one scalar), so that C++ and std140 place every
//     one at the same offset (the frame block's ambient and background are
//     colours in vec4s);
//   - arrays only of vec4 or of structs made of them.
// Matrix names read destination-from-source: clipFromWorld maps world-space
// positions to clip space.

#ifndef DERMIS_UNIFORM_BLOCKS_GLSL
#define DERMIS_UNIFORM_BLOCKS_GLSL

#ifdef __cplusplus
#define DERMIS_BLOCK(Name, Binding) struct Name
#define DERMIS_BLOCK_END(instance) ;
#else
#define DERMIS_BLOCK(Name, Binding) layout(std140, binding = Binding) uniform Name
#define DERMIS_BLOCK_END(instance) instance;
#endif

// Limits and the ids of closed sets (DERMIS_MAX_*, DERMIS_LIGHT_*, ...).
#include "SharedConstants.glsl"

#define DERMIS_BINDING_FRAME 0
#define DERMIS_BINDING_LIGHTS 1
#define DERMIS_BINDING_OBJECT 2
#define DERMIS_BINDING_CHARACTERS 3
#define DERMIS_BINDING_PROFILES 4
#define DERMIS_BINDING_PASS 5
#define DERMIS_BINDING_SCREEN_REGIONS 6
#define DERMIS_BINDING_ENVIRONMENT 7

// The depth-key target (R32UI) packs a pixel's profile slot in the top 4 bits
// and its view depth in the low 28, in units of 2^-20 m (about 1 micrometre,
// up to 256 m). Depth-aware passes compare keys: a different slot (another
// profile, an opaque object, the background) rejects a tap the same way a
// depth step does. A float key (depth + slot x stride) was tried first: at
// 1000 m strides its 0.12 mm rounding showed up in the thickness estimate.
#define DERMIS_KEY_DEPTH_BITS 28
#define DERMIS_KEY_UNITS_PER_M 1048576.0
#define DERMIS_BACKGROUND_SLOT 15
#define DERMIS_BACKGROUND_KEY 0xFFFFFFFFu

DERMIS_BLOCK(FrameBlock, DERMIS_BINDING_FRAME) {
    mat4 clipFromWorld;
    mat4 viewFromWorld;
    mat4 worldFromView;
    mat4 clipFromView;
    mat4 viewFromClip;
    vec4 cameraPositionM;   // xyz: camera position in world space (metres)
    vec2 viewportPx;        // width, height
    vec2 pixelSizeUv;       // 1/width, 1/height
    float nearM;
    float farM;
    int toneMap;            // DERMIS_TONE_MAP_*
    float transmittanceSkipSigmas;  // DERMIS_TRANSMITTANCE_SKIP_SIGMAS, or 0 (tests): include/Transmittance.glsl
    vec4 ambient;           // rgb: uniform ambient irradiance
    vec4 background;        // rgb: background radiance
    float exposure;
    float mixRatio;          // pre-scatter albedo^mix (Chappuis 2011 §2.2.4)
    int lightCount;
    int aov;                 // the output, DERMIS_AOV_*
    int energyConservation;  // 1: each light's diffuse share is 1 - rho_s rho_dt (Chappuis 2011 §2.6)
    float pixelsPerMetreAtUnitDepth;  // vertically, at 1 m view depth
    float ssaoStrength;
    float materialMipBias;   // of the material maps (0 but in tests)
} DERMIS_BLOCK_END(uFrame)

// Every field is a float (ids too) so that plan/ShadowCache.cpp can key on the raw floats.
struct GpuLight {
    mat4 shadowClipFromWorld;  // light's clip space, for shadow-map lookups
    vec3 positionM;
    float type;                // DERMIS_LIGHT_*
    vec3 direction;            // unit direction the light travels
    float shadowSlot;          // shadow-map slot, or -1
    vec3 radiance;             // colour * intensity
    float backLight;           // 1: a back light, for the transmittance (plan/FramePlan.cpp)
    float spotCosInner;
    float spotCosOuter;
    float size;                // 0 for a delta light; directional: tan(angular radius); spot, point: sphere radius (m)
    float cubeShadow;          // 1: the shadow map is a point light's cube atlas
    float shadowBiasM;         // constant
    float shadowSlopeBiasTexels;
    float shadowTexelM;        // texel size: m at 1 m (perspective) or m (orthographic)
    float shadowFilter;        // DERMIS_SHADOW_FILTER_*
    float shadowNearM;
    float shadowFarM;
    float shadowOrthographic;  // 1: orthographic (directional), 0: perspective
    float unused0;
};

DERMIS_BLOCK(LightsBlock, DERMIS_BINDING_LIGHTS) {
    GpuLight lights[DERMIS_MAX_LIGHTS];
} DERMIS_BLOCK_END(uLights)

DERMIS_BLOCK(ObjectBlock, DERMIS_BINDING_OBJECT) {
    mat4 worldFromObject;
    mat4 normalWorldFromObject;  // inverse transpose of worldFromObject
    vec3 albedo;                 // albedo tint x glTF baseColorFactor (linear)
    float roughness;             // Beckmann m (the scalar)
    float rhoS;
    float objectId;              // 1..255
    float hasAlbedoMap;          // 1/0, as every has... below
    float hasNormalMap;
    float flipV;                 // 1: sample at 1 - v
    float lightIndex;            // the shadow pass's light
    float cubeFace;              // the shadow pass's cube face, 0..5
    float profileSlot;           // of this draw (0 = opaque)
    float roughnessSource;       // DERMIS_ROUGHNESS_* (include/Material.glsl)
    float roughnessFactor;       // glTF's
    float hasSpecularMap;
    float scatteringShare;       // s (docs/materials.md)
    float hasScatterMap;
    float thicknessMm;           // KHR_materials_volume thickness (0: the shadow maps')
    float hasThicknessMap;
    float unused0;
    vec4 environmentSh[DERMIS_SH_COEFFICIENTS];  // rgb: uEnvironment.sh in this object's space, for its vertices' transfer
} DERMIS_BLOCK_END(uObject)

// The frame's environment light (plan/EnvironmentPlan.h, include/Environment.glsl).
DERMIS_BLOCK(EnvironmentBlock, DERMIS_BINDING_ENVIRONMENT) {
    vec4 sh[DERMIS_SH_COEFFICIENTS];  // rgb: radiance's SH coefficients (world space) x intensity; 0 past the scene's sh_bands
    mat4 mapFromWorld;                // a world direction to the map's (rotation; the skybox and the specular)
    float lit;           // 1: an environment lights the frame
    float occlusion;     // DERMIS_ENV_OCCLUSION_*
    float specularMode;  // DERMIS_ENV_SPECULAR_*
    float intensity;
    float lastMipLevel;  // of the map
    float skybox;        // 1: the map is drawn behind everything
    float diffuseMode;   // DERMIS_ENV_DIFFUSE_*
    float unused1;
    vec4 averageAlbedo[DERMIS_AVERAGE_ALBEDO_SIZE / 4];  // rho_dt(mu, m) averaged 2 int mu dmu, at m = i / (SIZE - 1)
    vec4 hotSh[DERMIS_SH_COEFFICIENTS];  // rgb: sh's hot, windowed part (env/RingingFreeSh.h), which occlusion
                                         // "transfer" lights at the normal, times the vertices' visible share
    vec4 rhoDtFits[DERMIS_AVERAGE_ALBEDO_SIZE];  // rho_dt(mu, m) ~ c0 + c1 mu + c2 mu^2 + c3 mu^3 at m = i / (SIZE - 1)
} DERMIS_BLOCK_END(uEnvironment)

// Per character, indexed by object id (G-buffer albedo alpha x 255).
struct CharacterParams {
    float unused0;      // (the profile slot is per draw: ObjectBlock.profileSlot)
    float ssaoRadiusM;  // 0: the scene's
    float ssaoSamples;  // 0: the scene's
    float hasLeanMaps;  // 1: the LEAN variants take its specular from passes/LeanSpecularPass
};

DERMIS_BLOCK(CharactersBlock, DERMIS_BINDING_CHARACTERS) {
    CharacterParams characters[DERMIS_MAX_CHARACTERS + 1];  // [0] is the background
} DERMIS_BLOCK_END(uCharacters)

// A diffusion profile (engine/sss/DiffusionProfile.h) as the GPU sees it.
struct ProfileParams {
    vec4 gaussians[DERMIS_MAX_PROFILE_GAUSSIANS];  // rgb: weight (normalised per channel), a: variance (mm^2)
    vec3 initWeight;       // the SSS accumulation starts with it: the identity plus skipped narrow Gaussians
    int gaussianCount;
    int lightingTechnique;    // 0, or its technique's id + 1 where it scatters in the lighting pass (render/LightingScatter.h)
    float lightingParameter;  // that technique's per-slot value (SssLightingScatter::slotParameter)
    int unused1;
    int unused2;
};

DERMIS_BLOCK(ProfilesBlock, DERMIS_BINDING_PROFILES) {
    ProfileParams profiles[DERMIS_MAX_PROFILES + 1];  // [slot]; [0] is unused (no SSS)
    float transmittanceShrinkMm;
    float transmittanceStrength;
    int anyScattersInLighting;  // 1: some visible slot scatters in the lighting pass (it binds the tables)
    int unused;
} DERMIS_BLOCK_END(uProfiles)

// How a screen-space SSS step treats a tap across a depth step or another
// profile slot (include/SssEdges.glsl); one 16-byte group.
struct SssEdgeParams {
    int mode;                 // DERMIS_BLUR_EDGES_*
    float bilateralDepthMm;   // std dev of the bilateral weight in tap-to-centre depth difference
    float controlScalePerMm;  // the control blur lerps to the centre by min(1, scale x |depth difference|)
    int slot;                 // the profile slot the step blurs (the stencil's value)
};

// Per-pass blocks share DERMIS_BINDING_PASS; a shader defines the macro of
// the one it uses before including this file.
#if defined(__cplusplus) || defined(DERMIS_USE_SSS_BLUR_BLOCK)
DERMIS_BLOCK(SssBlurBlock, DERMIS_BINDING_PASS) {
    vec4 kernel[DERMIS_MAX_BLUR_TAPS];  // x: tap offset in standard deviations (y: its CPU weight; the shader integrates its own)
    vec2 direction;  // (1, 0) or (0, 1)
    float sigmaMm;   // standard deviation of this step
    int taps;
    SssEdgeParams edges;
    int readsIrradiance;  // 1: the step reads the unblurred irradiance (texels are boxes), 0: a blurred chain
    int unused0;
    int unused1;
    int unused2;
} DERMIS_BLOCK_END(uSssBlur)
#endif

// Separable SSS (Jimenez et al. 2015), one direction of one profile slot
// (passes/SssSeparablePasses.cpp; the manual is include/SeparableSss.glsl).
#if defined(__cplusplus) || defined(DERMIS_USE_SEPARABLE_SSS_BLOCK)
DERMIS_BLOCK(SeparableSssBlock, DERMIS_BINDING_PASS) {
    vec4 taps[DERMIS_MAX_SEPARABLE_SAMPLES];  // rgb: weight (per channel, each sums to 1), a: offset (mm, widthScale applied), ascending
    ivec2 direction;  // (1, 0) or (0, 1)
    int tapCount;
    int isVertical;   // 1: the vertical pass, the last: its output is the result
    SssEdgeParams edges;
} DERMIS_BLOCK_END(uSeparableSss)
#endif

// The disk technique, one slot (passes/SssDiskPass.cpp; the manual is include/DiskSss.glsl).
#if defined(__cplusplus) || defined(DERMIS_USE_DISK_SSS_BLOCK)
DERMIS_BLOCK(DiskSssBlock, DERMIS_BINDING_PASS) {
    vec4 samples[DERMIS_MAX_DISK_SAMPLES];  // xy: offset on the golden-angle spiral (mm, before the pixel's rotation); z: radius (mm); w: moments' scalar weight
    vec4 weights[DERMIS_MAX_DISK_SAMPLES];  // rgb: weight (each channel sums to 1 over the samples); a: 0
    SssEdgeParams edges;
    int sampleCount;
    float largestRadiusMm;
    float unused0;
    float unused1;
} DERMIS_BLOCK_END(uDiskSss)
#endif

// SSAO and its blur (passes/SsaoPass.cpp; the manual is shaders/ssao.frag).
#if defined(__cplusplus) || defined(DERMIS_USE_SSAO_BLOCK)
DERMIS_BLOCK(SsaoBlock, DERMIS_BINDING_PASS) {
    float radiusM;         // where a character's params.y is 0
    float samples;         // where a character's params.z is 0
    float biasFraction;    // of the radius
    float fadeEndRadii;    // the range check fades an occluder's weight out by here
    int blurHalfWidthPx;   // 0..4
    float blurDepthTolerance;  // a fraction of the view depth
    float unused0;
    float unused1;
} DERMIS_BLOCK_END(uSsao)
#endif

// The rectangles a fullscreen pass covers in one draw (shaders/fullscreen.vert,
// engine/plan/ScreenRegions.h): disjoint, in pixels.
#if defined(__cplusplus) || defined(DERMIS_USE_SCREEN_REGIONS_BLOCK)
DERMIS_BLOCK(ScreenRegionsBlock, DERMIS_BINDING_SCREEN_REGIONS) {
    ivec4 regions[DERMIS_MAX_SCREEN_REGIONS];  // x, y, width, height (pixels, y up)
} DERMIS_BLOCK_END(uScreenRegions)
#endif

// GPU skinning of one character (passes/SkinningPass.cpp, shaders/skinning.comp).
#if defined(__cplusplus) || defined(DERMIS_USE_SKINNING_BLOCK)
DERMIS_BLOCK(SkinningBlock, DERMIS_BINDING_PASS) {
    int vertexCount;
    int morphSlots;
    int writeDerivatives;  // 1: also the deformed dP/du and dP/dv (texture-space draws)
    int unused0;
} DERMIS_BLOCK_END(uSkinning)
#endif

// Texture-space SSS, every pass of one character (passes/TextureSpacePasses.cpp;
// the manual is include/TextureSpace.glsl).
#if defined(__cplusplus) || defined(DERMIS_USE_TS_BLOCK)
DERMIS_BLOCK(TextureSpaceBlock, DERMIS_BINDING_PASS) {
    mat4 tsmClipFromWorld;  // the character's translucent shadow map (plan/TsPlan.h)
    vec3 tsmOriginM;        // TSM depth is measured from here
    float tsmAlongAxis;     // 1: along tsmAxis, 0: the distance to tsmOriginM
    vec3 tsmAxis;           // unit axis of the TSM light
    float hasTsm;           // 1: a TSM is bound
    float tsmPerMm;         // c of the stored exp(-c d)
    float tsmStrength;
    float tsmSideTexels;
    float tsmFirstGaussian; // the Gaussian the TSM terms start at
    float sideTexels;       // of the irradiance texture
    float texelUv;          // 1 / sideTexels
    float seamBlendStdDevs;
    float gaussianCount;
    vec2 blurDirection;     // (1, 0) U or (0, 1) V
    float blurSigmaMm;      // std dev of this step over the kernel's own
    float blurTaps;
    float dilationTexels;
    float metresPerObjectUnit;
    float stepSigmaMm;      // std dev of this blur step
    float omittedVarianceTexels2;  // the variance it leaves out
    vec4 kernel[DERMIS_MAX_BLUR_TAPS];  // x: tap offset in standard deviations, y: weight (they sum to 1)
    vec4 gaussians[DERMIS_MAX_PROFILE_GAUSSIANS];  // rgb: weight, a: variance (mm^2); [i] is blurred texture i
} DERMIS_BLOCK_END(uTs)
#endif

#endif
