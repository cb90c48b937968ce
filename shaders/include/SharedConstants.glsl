// Constants shared by C++ and GLSL: limits, the ids of closed sets that reach
// shaders, texture units and physical constants. Only #defines, so that C++
// code of any layer may include it as "include/SharedConstants.glsl"; GLSL
// gets it from UniformBlocks.glsl or with `#include "SharedConstants.glsl"`.
// C++ ties its enums to these ids with static_asserts
// (gpu/UniformBlocks.h, plan/Aov.cpp).

#ifndef DERMIS_SHARED_CONSTANTS_GLSL
#define DERMIS_SHARED_CONSTANTS_GLSL

// Limits of the uniform blocks.
#define DERMIS_MAX_LIGHTS 64
#define DERMIS_MAX_SHADOWED_LIGHTS 4   // shadow maps per frame; a point light's cube atlas takes one
#define DERMIS_MAX_CHARACTERS 255       // object ids 1..255 in the G-buffer (0 = background)
#define DERMIS_MAX_PROFILES 8           // profile slots per frame; the stencil holds the slot (0 = no SSS)
#define DERMIS_MAX_PROFILE_GAUSSIANS 8
// Hemisphere samples of SSAO per pixel (settings.ssao.samples).
#define DERMIS_MIN_SSAO_SAMPLES 8
#define DERMIS_MAX_SSAO_SAMPLES 128
// Taps per direction of a separable blur kernel (odd counts from 3 up to this).
#define DERMIS_MIN_BLUR_TAPS 3
#define DERMIS_MAX_BLUR_TAPS 33
// Samples per direction of the Separable SSS kernel (Jimenez et al. 2015), odd.
#define DERMIS_MIN_SEPARABLE_SAMPLES 7
#define DERMIS_MAX_SEPARABLE_SAMPLES 33
// Samples per pixel of the disk-sampled Burley technique (Christensen & Burley 2015).
#define DERMIS_MIN_DISK_SAMPLES 8
#define DERMIS_MAX_DISK_SAMPLES 128
#define DERMIS_MAX_SCREEN_REGIONS 64     // rectangles one fullscreen draw may cover (engine/plan/ScreenRegions.h)

// Light types (GpuLight::type); C++: LightType.
#define DERMIS_LIGHT_DIRECTIONAL 0
#define DERMIS_LIGHT_SPOT 1
#define DERMIS_LIGHT_POINT 2

// Shadow filters (GpuLight::shadowFilter); C++: ShadowFilter.
#define DERMIS_SHADOW_FILTER_PCF4X4 0
#define DERMIS_SHADOW_FILTER_POISSON 1
#define DERMIS_SHADOW_FILTER_PCSS 2
// Which filters a program that reads shadow maps compiles (DERMIS_SHADOW_CODE,
// include/Shadows.glsl); C++: ShadowCode, chosen per frame from its lights
// (engine/plan/LightSetup.h). Hard edges: every shadowed light is a delta
// light with a 2-D map under the PCSS filter (its bilinear test); soft
// edges: those and lights with a size under the PCSS filter; every filter:
// the rest (PCF 4x4, Poisson, delta point lights).
#define DERMIS_SHADOW_CODE_HARD_EDGES 0
#define DERMIS_SHADOW_CODE_SOFT_EDGES 1
#define DERMIS_SHADOW_CODE_EVERY_FILTER 2
// PCSS (Fernando 2005): the fixed taps of its blocker search and of its
// filter, on a Vogel disc (include/Shadows.glsl).
#define DERMIS_PCSS_BLOCKER_SAMPLES 16
#define DERMIS_PCSS_FILTER_SAMPLES 64
// The widest PCSS search and filter radius, in shadow-map texels.
#define DERMIS_PCSS_MAX_RADIUS_TEXELS 256

// Edge handling of the screen-space SSS blur (SssBlurBlock::edges.x); C++:
// SssBlur. Bilateral: depth-weighted taps; control: Jimenez et al. 2009's lerp
// to the centre; fetch-only: the same fetches unweighted (a benchmark floor).
#define DERMIS_BLUR_EDGES_BILATERAL 0
#define DERMIS_BLUR_EDGES_CONTROL 1
#define DERMIS_BLUR_EDGES_FETCH_ONLY 2

// The depth distance (mm) between two pixels of different profile slots: large
// enough that every depth weight of it is 0. Compare against half of it.
#define DERMIS_OTHER_PROFILE_DISTANCE_MM 1e30

// Transmittance (include/Transmittance.glsl, include/TextureSpace.glsl): a
// point less than this (mm) behind the first surface its light meets is that
// surface itself, lit directly, and takes no transmitted light. The shadow
// maps' texels and depth filtering blur where that surface is by about this
// much; at the light's silhouette a point can even be in front of it (or the
// texel empty). Thin parts (ears, 2-5 mm) lie well above it.
#define DERMIS_SELF_THICKNESS_MM 0.25
// The transmittance's integral over the lit surface behind a point
// (include/Transmittance.glsl): its centre disc, in units of the widest
// Gaussian's sigma, is the slab at the point's own thickness; a tap whose
// surface lies less than DERMIS_SELF_THICKNESS_MM behind the point's tangent
// plane is the point's own surface, and up to this many mm it counts in part.
#define DERMIS_TRANSMITTANCE_CENTRE_DISC_SIGMAS 0.1
#define DERMIS_OWN_SURFACE_RAMP_END_MM 0.75
// Where the widest Gaussian spans fewer pixels, the slab's closed form stands in for the integral.
#define DERMIS_TRANSMITTANCE_SLAB_BELOW_PX 1.0
// A point whose every back surface within the rings' reach lies at least this
// many of the widest Gaussian's sigmas in front of it (by the shadow map's
// max-depth mips) skips the rings: they could carry at most exp(-6^2 / 2) =
// 1.5e-8 of the light (FrameBlock::transmittanceSkipSigmas; 0 never skips).
#define DERMIS_TRANSMITTANCE_SKIP_SIGMAS 6.0
// What a shadow map stores where no caster covers a texel (m, "infinitely far").
#define DERMIS_SHADOW_NO_SURFACE_M 1e30

// Outputs of the aov pass (FrameBlock::aov); C++: Aov.
#define DERMIS_AOV_FINAL 0
#define DERMIS_AOV_ALBEDO 1
#define DERMIS_AOV_NORMAL 2
#define DERMIS_AOV_DEPTH 3
#define DERMIS_AOV_DIFFUSE 4
#define DERMIS_AOV_SPECULAR 5
#define DERMIS_AOV_IRRADIANCE 6
#define DERMIS_AOV_AO 7
#define DERMIS_AOV_TRANSMITTANCE 8
#define DERMIS_AOV_THICKNESS 9
#define DERMIS_AOV_OBJECT 10               // the object id (scene character index + 1; 0 for the background)
#define DERMIS_AOV_STRETCH 11              // the UV-space AOVs: a texture-space texture of one character,
#define DERMIS_AOV_IRRADIANCE_TEXTURE 12   // its UV square letterboxed in the frame
#define DERMIS_AOV_RADIANCE 13             // the composited frame before exposure and tone mapping
#define DERMIS_AOV_SCATTER 14              // the G-buffer's scattering share s and volume thickness (docs/materials.md)

// The tone map of the final image (shaders/tonemap.frag, settings.tone_map).
#define DERMIS_TONE_MAP_ACES 0          // Narkowicz 2016's fit of the ACES reference rendering transform
#define DERMIS_TONE_MAP_PBR_NEUTRAL 1   // Khronos PBR Neutral (Khronos 2024)
#define DERMIS_TONE_MAP_AGX 2           // AgX (Sobotka 2022), Wrensch 2023's polynomial fit
#define DERMIS_TONE_MAP_NONE 3          // clamped to [0, 1]

// The shader storage binding of the sanitise counters (include/Sanitise.glsl).
#define DERMIS_BINDING_SANITISE_COUNTERS 0

// GPU skinning (shaders/skinning.comp): its storage buffers (seven: GL 4.5
// guarantees eight per compute shader), the floats of one source vertex
// (engine/mesh/Mesh.h's Vertex: position 3, normal 3, tangent 4, uv 2; then
// the bind pose's dP/du and dP/dv, 3 each, for the texture-space stretch),
// of one output vertex (a Vertex), of one morph delta (position, normal,
// tangent: 3 each) and of one output derivative pair, and the work-group size.
#define DERMIS_BINDING_SKIN_SOURCE 1
#define DERMIS_BINDING_SKIN_INFLUENCES 2
#define DERMIS_BINDING_SKIN_MORPHS 3
#define DERMIS_BINDING_SKIN_PALETTE 4
#define DERMIS_BINDING_SKIN_MORPH_WEIGHTS 5
#define DERMIS_BINDING_SKIN_OUTPUT 6
#define DERMIS_BINDING_SKIN_DERIVATIVES 7
#define DERMIS_SKIN_SOURCE_FLOATS 18
#define DERMIS_VERTEX_FLOATS 12
#define DERMIS_MORPH_DELTA_FLOATS 9
#define DERMIS_SKIN_DERIVATIVE_FLOATS 6
#define DERMIS_SKINNING_GROUP_SIZE 64

// Where a draw's roughness comes from (ObjectBlock.roughnessSource, include/Material.glsl).
#define DERMIS_ROUGHNESS_SCALAR 0   // the material's roughness m
#define DERMIS_ROUGHNESS_MAP 1      // the scene's roughness_map: R is m
#define DERMIS_ROUGHNESS_GLTF 2     // glTF metallic-roughness G x roughnessFactor = r, m = r^2

// Texture units of a material's grey maps (include/Material.glsl).
#define DERMIS_UNIT_ROUGHNESS 12
#define DERMIS_UNIT_SPECULAR 13

// The surface's scattering share s and KHR_materials_volume thickness
// (docs/materials.md): the G-buffer's scatter target (shaders/gbuffer.frag,
// RG16F: R = s, G = thickness in mm, 0 = the shadow maps' estimate), the units
// of the material's scatter and thickness maps in the G-buffer pass, and the
// units where the composite and the diffuse AOV (include/OutgoingDiffuse.glsl)
// read s and the unscattered irradiance that s mixes with the scattered.
#define DERMIS_GBUFFER_SCATTER_LOCATION 3
#define DERMIS_UNIT_SCATTER_MAP 4
#define DERMIS_UNIT_THICKNESS_MAP 5
#define DERMIS_UNIT_UNSCATTERED 7
#define DERMIS_UNIT_SCATTER 8

// Texture units of the tables every shading pass may read, bound once per frame.
#define DERMIS_UNIT_BECKMANN 14
#define DERMIS_UNIT_ENERGY 15

// Environment light (scene/SceneEnums.h kEnvironmentOcclusions and
// kEnvironmentSpeculars, include/Environment.glsl): the ids reaching shaders,
// the SH coefficients (bands 0-2), the vertex attributes holding a vertex's
// transfer (three vec3), and the texture unit of the environment map.
#define DERMIS_ENV_OCCLUSION_NONE 0
#define DERMIS_ENV_OCCLUSION_SSAO 1
#define DERMIS_ENV_OCCLUSION_TRANSFER 2
#define DERMIS_ENV_SPECULAR_OFF 0
#define DERMIS_ENV_SPECULAR_SH 1
#define DERMIS_ENV_SPECULAR_PREFILTERED 2
#define DERMIS_ENV_DIFFUSE_SH 0   // kEnvironmentDiffuses: nine SH coefficients
#define DERMIS_ENV_DIFFUSE_MAP 1  // the irradiance map (env/IrradianceMap.h)
#define DERMIS_SH_COEFFICIENTS 9
#define DERMIS_LOCATION_TRANSFER 8      // 8, 9, 10: coefficients 0-2, 3-5, 6-8
// Texture space's own vertex attributes past the transfer's (render/TsMeshes.h).
#define DERMIS_LOCATION_TS_SEAM 11      // the seam continuation (mesh/UvLayout.h)
#define DERMIS_LOCATION_TS_BURIED 12    // 1 inside the body (mesh/UvLayout.h)
#define DERMIS_UNIT_ENVIRONMENT 11
#define DERMIS_UNIT_ENVIRONMENT_IRRADIANCE 16  // env/IrradianceMap.h, bound with the map

// Units 11-16 above are bound outside the passes (per frame or per draw), so a
// pass binds its own inputs below 11 or from DERMIS_UNIT_FIRST_PASS_EXTRA up;
// binding one of them leaves the wrong texture there for the passes after it
// (the texture-space gather once took unit 11, and the skybox then drew its
// input instead of the sky). tests/unit/test_texture_units.cpp checks the shaders.
#define DERMIS_UNIT_FIRST_PASS_EXTRA 17
#define DERMIS_UNIT_TS_PIXEL_IRRADIANCE 17  // ts_gather.frag: the lighting pass's irradiance
#define DERMIS_UNIT_TS_LEAN_MAP 18  // ts_irradiance.frag: the LEAN map the G-buffer's mean normal comes from
#define DERMIS_LOCATION_TS_LEAN_NORMALS 0  // ts_irradiance.frag: 1 when the G-buffer takes the LEAN mean normal
#define DERMIS_LOCATION_TS_BURIED_EMPTY 1  // ts_irradiance.frag: 1 leaves the texels inside the body empty
#define DERMIS_UNIT_HIDDEN_SIDE 19  // include/ThinEdges.glsl: the thin-edge pass's target, read by every SSS technique and the ts gather
#define DERMIS_AVERAGE_ALBEDO_SIZE 64   // rho_dt averaged over the hemisphere, per m (EnvironmentBlock)
// The irradiance map's cosine powers E_1 .. E_4 stacked in one texture (env/IrradianceMap.h
// kIrradiancePowers; Environment.glsl irradiancePower): one per coefficient of rho_dt's cubic.
#define DERMIS_IRRADIANCE_POWERS 4

// Fresnel reflectance at normal incidence for skin (d'Eon & Luebke 2007, after
// Donner & Jensen): Schlick's F0 of the specular and of its energy table.
#define DERMIS_SKIN_F0 0.028

// The prefiltered environment map of the split-sum specular (Karis 2013;
// env/PrefilteredEnvironment.h, include/EnvironmentSpecular.glsl): a lat-long
// mip chain of DERMIS_PREFILTERED_LEVELS levels from a base of
// 2 DERMIS_PREFILTERED_BASE_HEIGHT x DERMIS_PREFILTERED_BASE_HEIGHT texels.
// Level 0 is the map itself (a mirror, m = 0); level k >= 1 holds the Beckmann
// lobe of roughness m_k = DERMIS_PREFILTERED_MAX_ROUGHNESS 2^(k - LEVELS + 1),
// so m doubles as the texels do and every level's lobe (angular standard
// deviation sqrt(2) m about R) spans 3.6 of its own texels; the level is linear
// in m between levels 0 and 1 and clamps beyond the last level.
// The two mappings below are the one definition that C++ and GLSL share: they
// use only log2, exp2 and clamp, which GLSL has built in and C++ takes from std.
#define DERMIS_PREFILTERED_LEVELS 6
#define DERMIS_PREFILTERED_BASE_HEIGHT 256
#define DERMIS_PREFILTERED_MAX_ROUGHNESS 1.0
#define DERMIS_PREFILTERED_FIRST_ROUGHNESS (DERMIS_PREFILTERED_MAX_ROUGHNESS * exp2(2.0 - DERMIS_PREFILTERED_LEVELS))
#define DERMIS_PREFILTERED_LEVEL_OF_ROUGHNESS(m) \
    clamp((m) < DERMIS_PREFILTERED_FIRST_ROUGHNESS \
              ? (m) / DERMIS_PREFILTERED_FIRST_ROUGHNESS \
              : (DERMIS_PREFILTERED_LEVELS - 1.0) + log2((m) / DERMIS_PREFILTERED_MAX_ROUGHNESS), \
          0.0, DERMIS_PREFILTERED_LEVELS - 1.0)
#define DERMIS_PREFILTERED_ROUGHNESS_OF_LEVEL(level) \
    ((level) < 1.0 ? (level) * DERMIS_PREFILTERED_FIRST_ROUGHNESS \
                   : DERMIS_PREFILTERED_MAX_ROUGHNESS * exp2((level) - (DERMIS_PREFILTERED_LEVELS - 1.0)))

#endif
