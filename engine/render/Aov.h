#pragma once
// Arbitrary output variables: what `dermis render --aov` writes. Ids match
// the AOV_* defines in shaders/aov.frag.

#include <optional>
#include <string>
#include <string_view>

namespace dermis {

enum class Aov {
    Final = 0,
    Albedo = 1,
    Normal = 2,
    Depth = 3,
    Diffuse = 4,
    Specular = 5,
    Irradiance = 6,
    Ao = 7,
    Transmittance = 8,
    Thickness = 9,
    Object = 10,
    // Texture-space mode's UV-space textures of the first SSS character on
    // screen (passes/TextureSpacePasses.h, addTsAovPasses), in either mode.
    Stretch = 11,
    IrradianceTexture = 12,
};

std::optional<Aov> parseAov(std::string_view name);
std::string_view aovName(Aov aov);
std::string aovNameList();  // "final|albedo|..." for help and errors
// What the AOV holds and in which unit, one line, for help texts.
std::string_view aovDescription(Aov aov);
// One "name  description" line per AOV, each line starting with `indent`.
std::string aovHelpLines(std::string_view indent);
// The AOV shows a UV layout, not the frame: the unit UV square, as large as
// the frame allows and centred (letterboxed), v upwards.
bool aovIsUvLayout(Aov aov);

}  // namespace dermis
