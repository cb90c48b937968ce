#pragma once
// The limits of scene settings, one definition each: the scene loader's range
// checks, the viewer's sliders, the blur kernels and the shaders use these.
// Those a shader needs come from shaders/include/SharedConstants.glsl.

#include "include/SharedConstants.glsl"

namespace dermis {

// Taps per direction of a separable blur kernel, odd (sss.taps, ts.taps).
constexpr int kMinBlurTaps = DERMIS_MIN_BLUR_TAPS;
constexpr int kMaxBlurTaps = DERMIS_MAX_BLUR_TAPS;
static_assert(kMinBlurTaps % 2 == 1 && kMaxBlurTaps % 2 == 1, "tap counts are odd");

// Samples per direction of the Separable SSS kernel, odd (sss.separable_samples).
constexpr int kMinSeparableSamples = DERMIS_MIN_SEPARABLE_SAMPLES;
constexpr int kMaxSeparableSamples = DERMIS_MAX_SEPARABLE_SAMPLES;
static_assert(kMinSeparableSamples % 2 == 1 && kMaxSeparableSamples % 2 == 1, "sample counts are odd");

// Samples per pixel of the disk-sampled Burley technique (sss.disk_samples).
constexpr int kMinDiskSamples = DERMIS_MIN_DISK_SAMPLES;
constexpr int kMaxDiskSamples = DERMIS_MAX_DISK_SAMPLES;

// Gaussians per diffusion profile (sss.gaussians: use at most this many).
constexpr int kMaxProfileGaussians = DERMIS_MAX_PROFILE_GAUSSIANS;

// SSAO hemisphere samples (ssao.samples, the per-character override).
constexpr int kMinSsaoSamples = DERMIS_MIN_SSAO_SAMPLES;
constexpr int kMaxSsaoSamples = DERMIS_MAX_SSAO_SAMPLES;

// Shadow-map side in texels (shadow.map_size).
constexpr int kMinShadowMapSize = 64;
constexpr int kMaxShadowMapSize = 8192;

// Light sizes (a light's angular_diameter_deg and radius_m): at most a
// 30-degree disc of directions and a 1 m sphere, far past the sun (0.53
// degrees) and studio softboxes, where PCSS's one-blocker-depth assumption
// (Fernando 2005) still holds roughly.
constexpr double kMaxLightAngularDiameterDeg = 30.0;

// The camera and exposure values that render right. Measured failures past
// them: a near plane of 1e-5 m darkens and speckles the head (mean diffuse
// red 0.058 against 0.147) and far / near of 2e38 renders nothing (depth
// precision); a field of view of 1e-10 degrees breaks the projection; an
// exposure of 1e20 overflows the tone curve, so the brightest pixels turn black.
constexpr double kMinNearM = 1e-4;
// World coordinates (the camera's position and target, lights' positions,
// characters' translations), metres. float32 steps by 8 mm at 1e5 m, already
// coarser than a skin feature. Measured past it: a camera at 1e38 m crashed
// the reference's ray tracer (Embree refused the rays) and rendered an empty
// frame.
constexpr double kMaxWorldCoordinateM = 1e5;
// The camera's target must be at least this far from its position: a view
// direction 1e-30 m long underflowed in float and rendered an empty frame.
constexpr double kMinCameraTargetDistanceM = 1e-6;
constexpr double kMaxFarOverNear = 1e5;
constexpr double kMinVerticalFovDeg = 1.0;
constexpr double kMaxVerticalFovDeg = 179.0;
constexpr double kMaxExposure = 1e4;
// sss.width_scale and a material's width_scale: 1e4 times skin's widths is
// metres, every blur long saturated. Measured: from 2e19 the screen-space
// blurs scattered nothing while texture space still did.
constexpr double kMaxWidthScale = 1e4;
// settings.lod.max_error_px: beyond a few pixels a level of detail is a visible change of shape.
constexpr double kMaxLodErrorPx = 8.0;
constexpr double kMaxLightRadiusM = 1.0;

// Light values and sizes that stay inside float32 everywhere the renderer
// sums them. A light's colour x intensity (per channel), the ambient and the
// background: up to 64 lights, each times a Beckmann peak 1 / (pi m^2) of
// 3e11 at m = 1e-6 (Kelemen & Szirmay-Kalos 2001), stay below float32's 3.4e38
// with a factor 1e4 to spare. Measured: colour 3e38 x intensity 3e38
// overflowed to Inf and turned the pixels lit only by ambient black.
constexpr double kMaxLightRadiance = 1e20;
// Metres per mesh unit, transform.scale x metres_per_unit: from a micrometre
// to 1000 km, so that positions, their squares (distances, areas) and the
// scattering widths in mesh units stay finite and normal in float32. Measured:
// a product beyond float range rendered nothing.
constexpr double kMinMetresPerMeshUnit = 1e-6;
constexpr double kMaxMetresPerMeshUnit = 1e6;
// A character's animation (Character::animation): play times past 1e6 s
// (11 days) leave a float clip time too coarse for keyframes 1/30 s apart.
constexpr double kMaxAnimationTimeS = 1e6;
constexpr double kMaxAnimationSpeed = 1e3;

// Environment light (Scene::environment): SH bands 1..3 (1, 4 or 9
// coefficients, Ramamoorthi & Hanrahan 2001), and an intensity that keeps the
// map's radiance inside the same float32 headroom as a light's.
constexpr int kMaxShBands = 3;
constexpr double kMaxEnvironmentIntensity = kMaxLightRadiance;
constexpr double kMaxEnvironmentSpeedDegPerS = 1e4;
constexpr double kMaxEnvironmentAngleDeg = 1e6;
// The dominant light's threshold (Environment::extractThreshold), a multiple
// of the map's mean luminance: near 1 much of the sky would be a "light".
constexpr double kMinEnvironmentExtractThreshold = 2.0;
constexpr double kMaxEnvironmentExtractThreshold = 1e9;

// Texture-space irradiance texture side in texels, a power of two (ts.min_size, ts.max_size).
constexpr int kMinTsSize = 64;
constexpr int kMaxTsSize = 4096;

// Array lengths a scene file may have; the renderer uses at most
// DERMIS_MAX_LIGHTS lights of them. Characters: as many as the G-buffer's
// 8-bit object ids tell apart (DERMIS_MAX_CHARACTERS, static_asserted in
// frame/Renderer.cpp), so that the file is refused where it says so.
constexpr int kMaxSceneLights = 1024;
constexpr int kMaxSceneCharacters = 255;

}  // namespace dermis
