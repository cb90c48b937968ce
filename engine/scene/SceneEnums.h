#pragma once
// The closed sets of the scene format, each an enum with its one table of
// names (core/EnumTable.h). The loader, the writer, `--set`, the viewer, the
// bench and the command line take names from these tables; ids that reach a
// shader come from shaders/include/SharedConstants.glsl.

#include "core/EnumTable.h"
#include "include/SharedConstants.glsl"

namespace dermis {

enum class LightType { Directional = DERMIS_LIGHT_DIRECTIONAL, Spot = DERMIS_LIGHT_SPOT, Point = DERMIS_LIGHT_POINT };

inline constexpr EnumTable<LightType, 3> kLightTypes{
    "light type",
    {{{LightType::Directional, "directional", "parallel light along `direction`; irradiance scale"},
      {LightType::Spot, "spot", "cone from `position_m` along `direction`; radiant intensity"},
      {LightType::Point, "point", "from `position_m` in every direction; radiant intensity"}}}};

// The subsurface-scattering technique of the frame. Each has its own passes,
// shaders and tests; code that handles every technique loops over the table.
enum class SssMode { ScreenSpace, TextureSpace };

inline constexpr EnumTable<SssMode, 2> kSssModes{
    "SSS mode",
    {{{SssMode::ScreenSpace, "ss", "screen-space SSS chain (Jimenez et al. 2009)"},
      {SssMode::TextureSpace, "ts", "texture-space SSS (d'Eon & Luebke 2007)"}}}};

// The screen-space SSS technique (settings.sss.technique): how the
// irradiance is spread by the profile. Each has its own descriptor
// (scene/SssTechniques.h: its settings, its tuner candidates), its own passes
// (passes/SssTechniquePasses.cpp) or lighting-pass hook (render/LightingScatter.h)
// and its own shaders.
enum class SssTechnique {
    Gaussians,
    Separable,
    Disk,
    Preintegrated,
};

inline constexpr EnumTable<SssTechnique, 4> kSssTechniques{
    "SSS technique",
    {{{SssTechnique::Gaussians, "gaussians",
       "d'Eon & Luebke 2007's sum of Gaussians, one separable pair each (sss.taps, sss.gaussians)"},
      {SssTechnique::Separable, "separable",
       "Jimenez et al. 2015's one pre-integrated separable pair (sss.separable_samples)"},
      {SssTechnique::Disk, "disk", "the profile sampled on a disk in one pass (sss.disk_samples)"},
      {SssTechnique::Preintegrated, "preintegrated",
       "Penner & Borshukov 2011's falloff over N.L and curvature from a table, in the lighting pass; no blur"}}}};

// Vila Verde 2015 §5.1's three versions of the screen-space frame (plan/SssVariant.h).
enum class SssVariant { C, Lcb, Lbb };

inline constexpr EnumTable<SssVariant, 3> kSssVariants{
    "SSS variant",
    {{{SssVariant::C, "c", "Jimenez: control blur, KS specular"},
      {SssVariant::Lcb, "lcb", "LEAN specular, control blur"},
      {SssVariant::Lbb, "lbb", "LEAN specular, bilateral blur"}}}};

// Edge handling of the screen-space blur. Variant is the setting "the
// variant's own" (control for c and lcb, bilateral for lbb); the others are
// the shader's ids.
enum class SssBlur {
    Variant = -1,
    Bilateral = DERMIS_BLUR_EDGES_BILATERAL,
    Control = DERMIS_BLUR_EDGES_CONTROL,
    FetchOnly = DERMIS_BLUR_EDGES_FETCH_ONLY,
};

inline constexpr EnumTable<SssBlur, 4> kSssBlurs{
    "SSS blur",
    {{{SssBlur::Variant, "variant", "the variant's: control for c and lcb, bilateral for lbb"},
      {SssBlur::Bilateral, "bilateral", "taps weighted by their depth difference to the centre"},
      {SssBlur::Control, "control", "Jimenez et al. 2009's lerp towards the centre"},
      {SssBlur::FetchOnly, "fetch-only", "the same fetches, unweighted: the benchmarks' bandwidth floor"}}}};

enum class ShadowFilter {
    Pcf4x4 = DERMIS_SHADOW_FILTER_PCF4X4,
    Poisson = DERMIS_SHADOW_FILTER_POISSON,
    Pcss = DERMIS_SHADOW_FILTER_PCSS
};

inline constexpr EnumTable<ShadowFilter, 3> kShadowFilters{
    "shadow filter",
    {{{ShadowFilter::Pcf4x4, "pcf4x4", "4x4 percentage-closer filtering (Chappuis 2011)"},
      {ShadowFilter::Poisson, "poisson", "rotated Poisson-disc taps (Papanikolaou 2013)"},
      {ShadowFilter::Pcss, "pcss",
       "penumbrae as wide as the light's size implies (Fernando 2005); for a delta light the four nearest texels' tests, bilinearly weighted"}}}};

// What darkens the environment's diffuse light where the character hides it
// from itself (docs/environment.md, "Occlusion"). SSAO then darkens only the
// uniform ambient, never the same light twice.
enum class EnvironmentOcclusion { None, Ssao, Transfer };

inline constexpr EnumTable<EnvironmentOcclusion, 3> kEnvironmentOcclusions{
    "environment occlusion",
    {{{EnvironmentOcclusion::None, "none", "unoccluded SH irradiance at the pixel's normal"},
      {EnvironmentOcclusion::Ssao, "ssao", "SH irradiance at the pixel's normal times the SSAO"},
      {EnvironmentOcclusion::Transfer, "transfer",
       "per-vertex SH transfer of visibility x cosine (Chappuis 2011 §3.3)"}}}};

// The environment's specular light.
enum class EnvironmentSpecular { Off, Sh, Prefiltered };

inline constexpr EnumTable<EnvironmentSpecular, 3> kEnvironmentSpeculars{
    "environment specular",
    {{{EnvironmentSpecular::Off, "off", "no specular from the environment"},
      {EnvironmentSpecular::Sh, "sh", "the SH light's radiance towards the reflection (cheap, blurry)"},
      {EnvironmentSpecular::Prefiltered, "prefiltered",
       "the map prefiltered per roughness for the Beckmann lobe, split sum"}}}};

// Where the environment's diffuse light comes from (docs/environment.md,
// "Diffuse light: the irradiance map"). Occlusion "transfer" darkens either by
// the vertices' SH transfer: "sh" adds it as L.T, "map" multiplies the map's
// irradiance by the share of L.T that occlusion leaves.
enum class EnvironmentDiffuse { Sh = DERMIS_ENV_DIFFUSE_SH, Map = DERMIS_ENV_DIFFUSE_MAP };

inline constexpr EnumTable<EnvironmentDiffuse, 2> kEnvironmentDiffuses{
    "environment diffuse",
    {{{EnvironmentDiffuse::Sh, "sh", "nine SH coefficients (Ramamoorthi & Hanrahan 2001): blurs a soft box's terminator"},
      {EnvironmentDiffuse::Map, "map", "the map's exact cosine-convolved irradiance, read per pixel"}}}};

// Whether the environment's dominant light is taken out of the map
// (docs/environment.md, "The dominant light", env/DominantLight.h).
enum class EnvironmentLightExtraction { Off, Auto };

inline constexpr EnumTable<EnvironmentLightExtraction, 2> kEnvironmentLightExtractions{
    "environment light extraction",
    {{{EnvironmentLightExtraction::Off, "off", "the whole map stays in the SH and the prefiltered specular"},
      {EnvironmentLightExtraction::Auto, "auto",
       "the brightest compact region becomes a sized directional light with a shadow, when the map has one"}}}};

// How the final image maps radiance to display values (shaders/tonemap.frag).
enum class ToneMap { Aces = DERMIS_TONE_MAP_ACES, PbrNeutral = DERMIS_TONE_MAP_PBR_NEUTRAL, Agx = DERMIS_TONE_MAP_AGX, None = DERMIS_TONE_MAP_NONE };

inline constexpr EnumTable<ToneMap, 4> kToneMaps{
    "tone map",
    {{{ToneMap::Aces, "aces", "Narkowicz's fit of the ACES filmic curve: contrasty, hues shift toward white"},
      {ToneMap::PbrNeutral, "pbr-neutral", "Khronos PBR Neutral: base colours kept up to 0.8, only highlights compressed"},
      {ToneMap::Agx, "agx", "AgX: a gentle log curve that desaturates highlights evenly"},
      {ToneMap::None, "none", "linear, clamped to [0, 1]: what a display shows of the radiance as it is"}}}};

static_assert(kEnvironmentOcclusions.isOneToOne() && kEnvironmentSpeculars.isOneToOne() && kEnvironmentDiffuses.isOneToOne() &&
                  kEnvironmentLightExtractions.isOneToOne(),
              "every value and every name appears once");

static_assert(kLightTypes.isOneToOne() && kSssModes.isOneToOne() && kSssTechniques.isOneToOne() && kSssVariants.isOneToOne() &&
                  kSssBlurs.isOneToOne() && kShadowFilters.isOneToOne(),
              "every value and every name appears once");

}  // namespace dermis
