#include "render/Programs.h"

#include "brdf/BeckmannTable.h"
#include "plan/SssVariant.h"
#include "render/LightingScatter.h"

#include <string>
#include <utility>
#include <vector>

namespace dermis {

Result<Programs> Programs::build(bool specialize) {
    Programs programs;
    // Every program as (where it goes, its source), built in one loop below.
    std::vector<std::pair<gl::Program*, gl::ProgramSource>> builds;
    const std::vector<gl::GeneratedInclude> generated = {lightingTechniquesGlsl()};
    auto source = [&generated](const char* vertex, const char* fragment, const std::vector<gl::ShaderDefine>& extra,
                               const char* compute = "") {
        std::vector<gl::ShaderDefine> defines = {{"DERMIS_BECKMANN_SIZE", std::to_string(kBeckmannTableSize)}};
        defines.insert(defines.end(), extra.begin(), extra.end());
        return gl::ProgramSource{vertex, fragment, std::move(defines), compute, generated};
    };
    auto add = [&builds, &source](gl::Program& into, const char* vertex, const char* fragment,
                                  const std::vector<gl::ShaderDefine>& extra = {}, const char* compute = "") {
        builds.push_back({&into, source(vertex, fragment, extra, compute)});
    };
    // The programs that light with the environment, with its code (DERMIS_ENVIRONMENT 1)
    // and without it (0), for frames with no environment.
    auto addBothEnvironments = [&add](EnvironmentPrograms& into, const char* vertex, const char* fragment,
                                      std::vector<gl::ShaderDefine> extra = {}) {
        extra.push_back({"DERMIS_ENVIRONMENT", "1"});
        add(into.lit, vertex, fragment, extra);
        extra.back().value = "0";
        add(into.unlit, vertex, fragment, extra);
    };

    auto addGBuffer = [&add, &source](GBufferPrograms& into, std::vector<gl::ShaderDefine> extra = {}) {
        add(into.withColours, "gbuffer.vert", "gbuffer.frag", extra);
        extra.push_back({"GBUFFER_VERTEX_COLOUR", "0"});
        into.white = gl::LazyProgram(source("gbuffer.vert", "gbuffer.frag", extra));
    };

    auto addShadowed = [&addBothEnvironments, &source, specialize](
                           ShadowedPrograms& into, const char* vertex, const char* fragment,
                           std::vector<gl::ShaderDefine> extra = {}) {
        extra.push_back({"DERMIS_SHADOW_CODE", std::to_string(int(ShadowCode::EveryFilter))});
        addBothEnvironments(into.everyFilter, vertex, fragment, extra);
        if (!specialize) return;
        for (size_t code = 0; code < into.specialized.size(); ++code) {
            extra.back().value = std::to_string(code);
            for (int lit = 0; lit < 2; ++lit) {
                std::vector<gl::ShaderDefine> defines = extra;
                defines.push_back({"DERMIS_ENVIRONMENT", std::to_string(lit)});
                into.specialized[code][size_t(lit)] = gl::LazyProgram(source(vertex, fragment, defines));
            }
        }
    };
    auto addLighting = [&addShadowed, specialize](LightingPrograms& into, std::vector<gl::ShaderDefine> extra) {
        into.specialized = specialize;
        extra.push_back({"LIGHTING_SCATTER", "0"});
        addShadowed(into.plain, "fullscreen.vert", "lighting.frag", extra);
        extra.back().value = "1";
        addShadowed(into.scatter, "fullscreen.vert", "lighting.frag", extra);
    };

    add(programs.shadow, "shadow.vert", "shadow.frag");
    addGBuffer(programs.gbuffer);
    add(programs.composite, "fullscreen.vert", "composite.frag");
    add(programs.tonemap, "fullscreen.vert", "tonemap.frag");
    add(programs.aov, "fullscreen.vert", "aov.frag");
    add(programs.ssao, "fullscreen.vert", "ssao.frag");
    add(programs.ssaoBlur, "fullscreen.vert", "ssao_blur.frag");
    add(programs.transmittance, "fullscreen.vert", "transmittance.frag");
    add(programs.backDepth, "gbuffer.vert", "back_depth.frag");
    add(programs.thinEdges, "fullscreen.vert", "thin_edges.frag");
    add(programs.sssInit, "fullscreen.vert", "sss_init.frag");
    add(programs.sssBlur, "fullscreen.vert", "sss_blur.frag");
    add(programs.sssDisk, "fullscreen.vert", "sss_disk.frag");
    add(programs.tsTsm, "ts_tsm.vert", "ts_tsm.frag");
    add(programs.tsStretch, "ts_uv.vert", "ts_stretch.frag");
    add(programs.tsDilate, "fullscreen.vert", "ts_dilate.frag");
    add(programs.tsBlur, "fullscreen.vert", "ts_blur.frag");
    add(programs.tsGather, "ts_gather.vert", "ts_gather.frag");
    add(programs.skinning, "", "", {}, "skinning.comp");
    add(programs.shadowMax, "", "", {}, "shadow_max.comp");
    add(programs.transferRotate, "", "", {}, "transfer_rotate.comp");

    // Variants of shaders by a define: the LEAN variants (plan/SssVariant.h)
    // with their LEAN outputs, the G-buffer with the environment transfer, and
    // the skybox (a full-screen triangle on the far plane, so the depth test
    // keeps it to the background).
    const std::string leanTargets = std::to_string(kLeanSssTargets);
    addGBuffer(programs.gbufferLean, {{"GBUFFER_LEAN", "1"}});
    add(programs.sssInitLean, "fullscreen.vert", "sss_init.frag", {{"SSS_EXTRA_TARGETS", leanTargets}});
    add(programs.sssBlurLean, "fullscreen.vert", "sss_blur.frag", {{"SSS_EXTRA_TARGETS", leanTargets}});
    add(programs.sssDiskLean, "fullscreen.vert", "sss_disk.frag", {{"SSS_EXTRA_TARGETS", leanTargets}});
    add(programs.sssBlurLeanLast, "fullscreen.vert", "sss_blur.frag",
        {{"SSS_EXTRA_TARGETS", leanTargets}, {"SSS_PACKED_OUT", "0"}});
    addGBuffer(programs.gbufferTransfer, {{"GBUFFER_TRANSFER", "4"}});
    addGBuffer(programs.gbufferLeanTransfer, {{"GBUFFER_LEAN", "1"}, {"GBUFFER_TRANSFER", "6"}});  // after the scatter target 3 and the LEAN targets 4 and 5
    add(programs.skybox, "fullscreen.vert", "skybox.frag", {{"FULLSCREEN_AT_FAR_PLANE", "1"}});
    add(programs.sssSeparableH, "fullscreen.vert", "sss_separable.frag",
        {{"SSS_EXTRA_TARGETS", "0"}, {"SEPARABLE_SSS_LAST", "0"}});
    add(programs.sssSeparableV, "fullscreen.vert", "sss_separable.frag",
        {{"SSS_EXTRA_TARGETS", "0"}, {"SEPARABLE_SSS_LAST", "1"}});
    add(programs.sssSeparableLeanH, "fullscreen.vert", "sss_separable.frag",
        {{"SSS_EXTRA_TARGETS", leanTargets}, {"SEPARABLE_SSS_LAST", "0"}});
    add(programs.sssSeparableLeanV, "fullscreen.vert", "sss_separable.frag",
        {{"SSS_EXTRA_TARGETS", leanTargets}, {"SEPARABLE_SSS_LAST", "1"}});

    addLighting(programs.lighting, {});
    addLighting(programs.lightingLean, {{"LIGHTING_LEAN", "1"}});
    addBothEnvironments(programs.leanSpecular, "fullscreen.vert", "lean_specular.frag");
    addBothEnvironments(programs.compositeLean, "fullscreen.vert", "composite.frag", {{"COMPOSITE_LEAN", "1"}});
    addShadowed(programs.tsIrradiance, "ts_uv.vert", "ts_irradiance.frag");

    for (auto& [into, source] : builds) {
        auto program = gl::buildProgram(source);
        if (!program.ok()) return program.error();
        *into = std::move(*program);
    }
    return programs;
}

}  // namespace dermis
