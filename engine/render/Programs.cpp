#include "render/Programs.h"

#include "brdf/BeckmannTable.h"
#include "render/SssVariant.h"

#include <string>

namespace dermis {

Result<Programs> Programs::build() {
    const std::vector<gl::ShaderDefine> defines = {{"DERMIS_BECKMANN_SIZE", std::to_string(kBeckmannTableSize)}};
    struct Entry {
        gl::Program Programs::*member;
        const char* vertex;
        const char* fragment;
    };
    const Entry entries[] = {
        {&Programs::shadow, "shadow.vert", "shadow.frag"},
        {&Programs::gbuffer, "gbuffer.vert", "gbuffer.frag"},
        {&Programs::lighting, "fullscreen.vert", "lighting.frag"},
        {&Programs::composite, "fullscreen.vert", "composite.frag"},
        {&Programs::tonemap, "fullscreen.vert", "tonemap.frag"},
        {&Programs::aov, "fullscreen.vert", "aov.frag"},
        {&Programs::ssao, "fullscreen.vert", "ssao.frag"},
        {&Programs::ssaoBlur, "fullscreen.vert", "ssao_blur.frag"},
        {&Programs::transmittance, "fullscreen.vert", "transmittance.frag"},
        {&Programs::sssInit, "fullscreen.vert", "sss_init.frag"},
        {&Programs::sssBlur, "fullscreen.vert", "sss_blur.frag"},
        {&Programs::tsTsm, "ts_tsm.vert", "ts_tsm.frag"},
        {&Programs::tsStretch, "ts_uv.vert", "ts_stretch.frag"},
        {&Programs::tsIrradiance, "ts_uv.vert", "ts_irradiance.frag"},
        {&Programs::tsDilate, "fullscreen.vert", "ts_dilate.frag"},
        {&Programs::tsBlur, "fullscreen.vert", "ts_blur.frag"},
        {&Programs::tsGather, "ts_gather.vert", "ts_gather.frag"},
    };
    Programs programs;
    for (const Entry& e : entries) {
        auto program = gl::buildProgram({e.vertex, e.fragment, defines, {}});
        if (!program.ok()) return program.error();
        programs.*(e.member) = std::move(*program);
    }
    auto skinning = gl::buildProgram({"", "", defines, "skinning.comp"});
    if (!skinning.ok()) return skinning.error();
    programs.skinning = std::move(*skinning);
    // The LEAN variants (render/SssVariant.h): the same shaders with their
    // LEAN outputs, and the LEAN specular pass.
    struct LeanEntry {
        gl::Program Programs::*member;
        const char* vertex;
        const char* fragment;
        gl::ShaderDefine define;
    };
    const std::string leanTargets = std::to_string(kLeanSssTargets);
    const LeanEntry leanEntries[] = {
        {&Programs::gbufferLean, "gbuffer.vert", "gbuffer.frag", {"GBUFFER_LEAN", "1"}},
        {&Programs::lightingLean, "fullscreen.vert", "lighting.frag", {"LIGHTING_LEAN", "1"}},
        {&Programs::sssInitLean, "fullscreen.vert", "sss_init.frag", {"SSS_EXTRA_TARGETS", leanTargets}},
        {&Programs::sssBlurLean, "fullscreen.vert", "sss_blur.frag", {"SSS_EXTRA_TARGETS", leanTargets}},
        {&Programs::leanSpecular, "fullscreen.vert", "lean_specular.frag", {}},
        {&Programs::compositeLean, "fullscreen.vert", "composite.frag", {"COMPOSITE_LEAN", "1"}},
    };
    for (const LeanEntry& e : leanEntries) {
        std::vector<gl::ShaderDefine> leanDefines = defines;
        if (!e.define.name.empty()) leanDefines.push_back(e.define);
        auto program = gl::buildProgram({e.vertex, e.fragment, leanDefines, {}});
        if (!program.ok()) return program.error();
        programs.*(e.member) = std::move(*program);
    }
    return programs;
}

}  // namespace dermis
