#pragma once
// Arbitrary output variables: what `dermis render --aov` writes. Ids match
// the AOV_* defines in shaders/aov.frag.

#include <optional>
#include <string>
#include <string_view>

namespace dermis {

enum class Aov { Final = 0, Albedo = 1, Normal = 2, Depth = 3, Diffuse = 4, Specular = 5, Irradiance = 6, Ao = 7, Transmittance = 8, Thickness = 9, Object = 10 };

std::optional<Aov> parseAov(std::string_view name);
std::string_view aovName(Aov aov);
std::string aovNameList();  // "final|albedo|..." for help and errors

}  // namespace dermis
