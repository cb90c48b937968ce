#pragma once
// The `settings` object of the scene format, one list of fields per group:
// each field's key, its member and the values it may take. The loader reads
// (SceneLoader.cpp), the writer writes (SceneWriter.cpp) and the known-key
// lists are collected by visiting the same lists, so a setting is added here
// once, plus its line in Scene.h and in content/scenes/README.md.
//
// A visitor V has, each taking the key first:
//   number(key, float&, Range)      integer(key, int&, Range)
//   rule(key, int&, IntegerRule)    boolean(key, bool&)
//   vec3(key, glm::vec3&, Range)    choice(key, EnumTable, E&)
//   group(key, G&, visit)           visit(G&, V&) lists the group's fields
//   path(key, std::string&)         a file path, relative to the scene file in the file, resolved in memory
// S is a settings struct, const when writing.

#include "core/Limits.h"
#include "scene/IntegerRule.h"
#include "scene/JsonReader.h"
#include "scene/Scene.h"
#include "scene/SssTechniques.h"

#include <string>

namespace dermis {

template <typename S, typename V>
void visitShadowFields(S& s, V& v) {
    v.integer("map_size", s.mapSize, Range::closed(kMinShadowMapSize, kMaxShadowMapSize));
    v.number("bias_constant_m", s.biasConstantM, Range::atLeast(0.0));
    v.number("bias_slope_texels", s.biasSlopeTexels, Range::atLeast(0.0));
    v.choice("filter", kShadowFilters, s.filter);
}

template <typename S, typename V>
void visitSssFields(S& s, V& v) {
    v.boolean("enabled", s.enabled);
    v.choice("variant", kSssVariants, s.variant);
    v.choice("blur", kSssBlurs, s.blur);
    v.choice("technique", kSssTechniques, s.technique);
    for (const SssTechniqueInfo& technique : sssTechniques()) {
        for (const SssSampleSetting& setting : technique.settings) v.rule(setting.key, s.*setting.setting, setting.rule());
    }
    v.number("bilateral_depth_mm", s.bilateralDepthMm, Range::above(0.0));
    v.number("control_depth_scale_per_mm", s.controlDepthScalePerMm, Range::atLeast(0.0));
    v.number("width_scale", s.widthScale, Range::closed(0.0, kMaxWidthScale));
    v.number("min_width_px", s.minWidthPx, Range::atLeast(0.0));
    v.number("mix", s.mix, Range::closed(0.0, 1.0));
    v.number("lean_moment_width_mm", s.leanMomentWidthMm, Range::atLeast(0.0));
}

template <typename S, typename V>
void visitTransmittanceFields(S& s, V& v) {
    v.boolean("enabled", s.enabled);
    v.number("shrink_mm", s.shrinkMm, Range::atLeast(0.0));
    v.number("strength", s.strength, Range::atLeast(0.0));
    v.boolean("thin_edges", s.thinEdges);
}

template <typename S, typename V>
void visitSsaoFields(S& s, V& v) {
    v.boolean("enabled", s.enabled);
    v.integer("samples", s.samples, Range::closed(kMinSsaoSamples, kMaxSsaoSamples));
    v.number("radius_m", s.radiusM, Range::above(0.0));
    v.number("strength", s.strength, Range::closed(0.0, 1.0));
    v.boolean("blur", s.blur);
}

// ts.min_size <= ts.max_size is checked by the loader after the fields.
template <typename S, typename V>
void visitTextureSpaceFields(S& s, V& v) {
    v.rule("taps", s.taps, blurTapsRule());
    v.rule("min_size", s.minSize, tsSizeRule());
    v.rule("max_size", s.maxSize, tsSizeRule());
    v.boolean("tsm", s.tsm);
    v.number("tsm_strength", s.tsmStrength, Range::atLeast(0.0));
    v.number("seam_blend", s.seamBlend, Range::atLeast(0.0));
}

// The table is read and checked by the loader after the fields (QualityTable.h).
template <typename S, typename V>
void visitQualityFields(S& s, V& v) {
    v.number("error_budget", s.errorBudget, Range::rightOpen(0.0, 1.0));
    v.path("table", s.table);
}

template <typename S, typename V>
void visitLodFields(S& s, V& v) {
    v.number("max_error_px", s.maxErrorPx, Range::closed(0.0, kMaxLodErrorPx));
}

template <typename S, typename V>
void visitSettingsFields(S& s, V& v) {
    v.number("exposure", s.exposure, Range::leftOpen(0.0, kMaxExposure));
    v.choice("tone_map", kToneMaps, s.toneMap);
    v.vec3("ambient", s.ambient, Range::closed(0.0, kMaxLightRadiance));
    v.boolean("energy_conservation", s.energyConservation);
    v.boolean("cull_back_faces", s.cullBackFaces);
    v.choice("mode", kSssModes, s.mode);
    v.group("shadow", s.shadow, [](auto& g, auto& w) { visitShadowFields(g, w); });
    v.group("sss", s.sss, [](auto& g, auto& w) { visitSssFields(g, w); });
    v.group("transmittance", s.transmittance, [](auto& g, auto& w) { visitTransmittanceFields(g, w); });
    v.group("ssao", s.ssao, [](auto& g, auto& w) { visitSsaoFields(g, w); });
    v.group("ts", s.ts, [](auto& g, auto& w) { visitTextureSpaceFields(g, w); });
    v.group("quality", s.quality, [](auto& g, auto& w) { visitQualityFields(g, w); });
    v.group("lod", s.lod, [](auto& g, auto& w) { visitLodFields(g, w); });
}

// The keys a group's visit lists, in order: the loader's known keys.
class FieldKeys {
public:
    template <typename T, typename... Rest>
    void number(const char* key, T&, Rest&&...) { mKeys.emplace_back(key); }
    template <typename T, typename... Rest>
    void integer(const char* key, T&, Rest&&...) { mKeys.emplace_back(key); }
    template <typename T, typename... Rest>
    void rule(const char* key, T&, Rest&&...) { mKeys.emplace_back(key); }
    template <typename T>
    void boolean(const char* key, T&) { mKeys.emplace_back(key); }
    template <typename T, typename... Rest>
    void vec3(const char* key, T&, Rest&&...) { mKeys.emplace_back(key); }
    template <typename Table, typename T>
    void choice(const char* key, const Table&, T&) { mKeys.emplace_back(key); }
    template <typename G, typename Visit>
    void group(const char* key, G&, Visit&&) { mKeys.emplace_back(key); }
    template <typename T>
    void path(const char* key, T&) { mKeys.emplace_back(key); }

    const std::vector<std::string>& keys() const { return mKeys; }

private:
    std::vector<std::string> mKeys;
};

template <typename G, typename Visit>
std::vector<std::string> fieldKeys(G& group, Visit&& visit) {
    FieldKeys keys;
    visit(group, keys);
    return keys.keys();
}

}  // namespace dermis
