#include "render/Aov.h"

#include <array>
#include <utility>

namespace dermis {
namespace {
constexpr std::array<std::pair<Aov, std::string_view>, 11> kAovNames{{
    {Aov::Final, "final"},
    {Aov::Albedo, "albedo"},
    {Aov::Normal, "normal"},
    {Aov::Depth, "depth"},
    {Aov::Diffuse, "diffuse"},
    {Aov::Specular, "specular"},
    {Aov::Irradiance, "irradiance"},
    {Aov::Ao, "ao"},
    {Aov::Transmittance, "transmittance"},
    {Aov::Thickness, "thickness"},
    {Aov::Object, "object"},
}};
}  // namespace

std::optional<Aov> parseAov(std::string_view name) {
    for (const auto& [aov, text] : kAovNames) {
        if (text == name) return aov;
    }
    return std::nullopt;
}

std::string_view aovName(Aov aov) {
    for (const auto& [value, text] : kAovNames) {
        if (value == aov) return text;
    }
    return "?";
}

std::string aovNameList() {
    std::string list;
    for (const auto& entry : kAovNames) {
        if (!list.empty()) list += '|';
        list += entry.second;
    }
    return list;
}

}  // namespace dermis
