#pragma once
// Arbitrary output variables: what `dermis render --aov` writes. Ids are the
// DERMIS_AOV_* constants the aov pass's shader reads
// (shaders/include/SharedConstants.glsl).

#include "core/EnumTable.h"
#include "include/SharedConstants.glsl"

namespace dermis {

enum class Aov {
    Final = DERMIS_AOV_FINAL,
    Albedo = DERMIS_AOV_ALBEDO,
    Normal = DERMIS_AOV_NORMAL,
    Depth = DERMIS_AOV_DEPTH,
    Diffuse = DERMIS_AOV_DIFFUSE,
    Specular = DERMIS_AOV_SPECULAR,
    Irradiance = DERMIS_AOV_IRRADIANCE,
    Ao = DERMIS_AOV_AO,
    Transmittance = DERMIS_AOV_TRANSMITTANCE,
    Thickness = DERMIS_AOV_THICKNESS,
    Object = DERMIS_AOV_OBJECT,
    // Texture-space mode's UV-space textures of the first SSS character on
    // screen (passes/TextureSpacePasses.h, addTsAovPasses), in either mode.
    Stretch = DERMIS_AOV_STRETCH,
    IrradianceTexture = DERMIS_AOV_IRRADIANCE_TEXTURE,
    // The final frame before exposure and tone mapping: what `--aov final`
    // writes to an EXR.
    Radiance = DERMIS_AOV_RADIANCE,
    // The share s of the diffuse light that scatters (red; 0 where nothing
    // scatters) and the file's volume thickness in mm (green; 0: none).
    Scatter = DERMIS_AOV_SCATTER,
};

// Names and one-line descriptions (what the AOV holds and in which unit) for
// the command line, help texts and the viewer.
inline constexpr EnumTable<Aov, 15> kAovs{
    "AOV",
    {{{Aov::Final, "final", "the tone-mapped frame (sRGB)"},
      {Aov::Albedo, "albedo", "surface albedo"},
      {Aov::Normal, "normal", "world-space normal"},
      {Aov::Depth, "depth", "view depth in metres"},
      {Aov::Diffuse, "diffuse", "after SSS, times albedo^(1-mix)"},
      {Aov::Specular, "specular", "specular light"},
      {Aov::Irradiance, "irradiance", "diffuse irradiance before SSS"},
      {Aov::Ao, "ao", "ambient occlusion"},
      {Aov::Transmittance, "transmittance", "back-lit light through thin regions"},
      {Aov::Thickness, "thickness", "mm, through the first back light"},
      {Aov::Object, "object", "character index + 1, 0 for the background"},
      {Aov::Stretch, "stretch", "stretch map: mm per UV unit, u red, v green"},
      {Aov::IrradianceTexture, "irradiance-texture", "irradiance texture, before the blurs"},
      {Aov::Radiance, "radiance", "the final frame before exposure and tone mapping (linear)"},
      {Aov::Scatter, "scatter", "the share of diffuse light that scatters (red), volume thickness in mm (green)"}}}};
static_assert(kAovs.isOneToOne(), "every AOV and every name appears once");

// The AOV shows a UV layout, not the frame: the unit UV square, as large as
// the frame allows and centred (letterboxed), v upwards.
bool aovIsUvLayout(Aov aov);

}  // namespace dermis
