#include "render/Aov.h"

#include <algorithm>
#include <array>

namespace dermis {
namespace {

struct AovInfo {
    Aov aov;
    std::string_view name;
    std::string_view description;
};

constexpr std::array<AovInfo, 13> kAovs{{
    {Aov::Final, "final", "the tone-mapped frame (sRGB)"},
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
}};

}  // namespace

std::optional<Aov> parseAov(std::string_view name) {
    for (const AovInfo& info : kAovs) {
        if (info.name == name) return info.aov;
    }
    return std::nullopt;
}

std::string_view aovName(Aov aov) {
    for (const AovInfo& info : kAovs) {
        if (info.aov == aov) return info.name;
    }
    return "?";
}

std::string_view aovDescription(Aov aov) {
    for (const AovInfo& info : kAovs) {
        if (info.aov == aov) return info.description;
    }
    return "";
}

std::string aovNameList() {
    std::string list;
    for (const AovInfo& info : kAovs) {
        if (!list.empty()) list += '|';
        list += info.name;
    }
    return list;
}

std::string aovHelpLines(std::string_view indent) {
    constexpr size_t kNameColumn = 20;
    std::string lines;
    for (const AovInfo& info : kAovs) {
        std::string name(info.name);
        name.resize(std::max(name.size() + 2, kNameColumn), ' ');
        lines += std::string(indent) + name + std::string(info.description) + '\n';
    }
    return lines;
}

bool aovIsUvLayout(Aov aov) { return aov == Aov::Stretch || aov == Aov::IrradianceTexture; }

}  // namespace dermis
