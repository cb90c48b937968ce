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
        {&Programs::composite, "fullscreen.vert", "composite.frag"},
        {&Programs::tonemap, "fullscreen.vert", "tonemap.frag"},
        {&Programs::aov, "fullscreen.vert", "aov.frag"},
        {&Programs::ssao, "fullscreen.vert", "ssao.frag"},
        {&Programs::ssaoBlur, "fullscreen.vert", "ssao_blur.frag"},
        {&Programs::transmittance, "fullscreen.vert", "transmittance.frag"},
        {&Programs::sssInit, "fullscreen.vert", "sss_init.frag"},
        {&Programs::sssBlur, "fullscreen.vert", "sss_blur.frag"},
        {&Programs::sssDisk, "fullscreen.vert", "sss_disk.frag"},
        {&Programs::tsTsm, "ts_tsm.vert", "ts_tsm.frag"},
        {&Programs::tsStretch, "ts_uv.vert", "ts_stretch.frag"},
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
    for (const auto& [member, compute] : {std::pair{&Programs::skinning, "skinning.comp"},
                                          std::pair{&Programs::transferRotate, "transfer_rotate.comp"}}) {
        auto program = gl::buildProgram({"", "", defines, compute});
        if (!program.ok()) return program.error();
        programs.*member = std::move(*program);
    }
    // Variants of shaders by a define: the LEAN variants (render/SssVariant.h)
    // with their LEAN outputs, the LEAN specular pass, the G-buffer with the
    // environment transfer, and the skybox (a full-screen triangle on the far
    // plane, so the depth test keeps it to the background).
    struct VariantEntry {
        gl::Program Programs::*member;
        const char* vertex;
        const char* fragment;
        gl::ShaderDefine define;
    };
    const std::string leanTargets = std::to_string(kLeanSssTargets);
    const VariantEntry variantEntries[] = {
        {&Programs::gbufferLean, "gbuffer.vert", "gbuffer.frag", {"GBUFFER_LEAN", "1"}},
        {&Programs::sssInitLean, "fullscreen.vert", "sss_init.frag", {"SSS_EXTRA_TARGETS", leanTargets}},
        {&Programs::sssBlurLean, "fullscreen.vert", "sss_blur.frag", {"SSS_EXTRA_TARGETS", leanTargets}},
        {&Programs::sssDiskLean, "fullscreen.vert", "sss_disk.frag", {"SSS_EXTRA_TARGETS", leanTargets}},
        {&Programs::gbufferTransfer, "gbuffer.vert", "gbuffer.frag", {"GBUFFER_TRANSFER", "3"}},
        {&Programs::skybox, "fullscreen.vert", "skybox.frag", {"FULLSCREEN_AT_FAR_PLANE", "1"}},
    };
    for (const VariantEntry& e : variantEntries) {
        std::vector<gl::ShaderDefine> variantDefines = defines;
        if (!e.define.name.empty()) variantDefines.push_back(e.define);
        auto program = gl::buildProgram({e.vertex, e.fragment, variantDefines, {}});
        if (!program.ok()) return program.error();
        programs.*(e.member) = std::move(*program);
    }
    // The programs that light with the environment, with and without its code.
    struct EnvironmentEntry {
        EnvironmentPrograms Programs::*member;
        const char* vertex;
        const char* fragment;
        gl::ShaderDefine define;
    };
    const EnvironmentEntry environmentEntries[] = {
        {&Programs::lighting, "fullscreen.vert", "lighting.frag", {}},
        {&Programs::lightingLean, "fullscreen.vert", "lighting.frag", {"LIGHTING_LEAN", "1"}},
        {&Programs::leanSpecular, "fullscreen.vert", "lean_specular.frag", {}},
        {&Programs::compositeLean, "fullscreen.vert", "composite.frag", {"COMPOSITE_LEAN", "1"}},
        {&Programs::tsIrradiance, "ts_uv.vert", "ts_irradiance.frag", {}},
    };
    for (const EnvironmentEntry& e : environmentEntries) {
        for (const bool lit : {true, false}) {
            std::vector<gl::ShaderDefine> environmentDefines = defines;
            if (!e.define.name.empty()) environmentDefines.push_back(e.define);
            environmentDefines.push_back({"DERMIS_ENVIRONMENT", lit ? "1" : "0"});
            auto program = gl::buildProgram({e.vertex, e.fragment, environmentDefines, {}});
            if (!program.ok()) return program.error();
            EnvironmentPrograms& pair = programs.*(e.member);
            (lit ? pair.lit : pair.unlit) = std::move(*program);
        }
    }
    struct SeparableEntry {
        gl::Program Programs::*member;
        const char* extraTargets;
        const char* last;
    };
    const SeparableEntry separableEntries[] = {
        {&Programs::sssSeparableH, "0", "0"},
        {&Programs::sssSeparableV, "0", "1"},
        {&Programs::sssSeparableLeanH, leanTargets.c_str(), "0"},
        {&Programs::sssSeparableLeanV, leanTargets.c_str(), "1"},
    };
    for (const SeparableEntry& e : separableEntries) {
        std::vector<gl::ShaderDefine> separableDefines = defines;
        separableDefines.push_back({"SSS_EXTRA_TARGETS", e.extraTargets});
        separableDefines.push_back({"SEPARABLE_SSS_LAST", e.last});
        auto program = gl::buildProgram({"fullscreen.vert", "sss_separable.frag", separableDefines, {}});
        if (!program.ok()) return program.error();
        programs.*(e.member) = std::move(*program);
    }
    std::vector<gl::ShaderDefine> leanLast = defines;
    leanLast.push_back({"SSS_EXTRA_TARGETS", leanTargets});
    leanLast.push_back({"SSS_PACKED_OUT", "0"});
    auto sssBlurLeanLast = gl::buildProgram({"fullscreen.vert", "sss_blur.frag", leanLast, {}});
    if (!sssBlurLeanLast.ok()) return sssBlurLeanLast.error();
    programs.sssBlurLeanLast = std::move(*sssBlurLeanLast);
    std::vector<gl::ShaderDefine> leanTransfer = defines;
    leanTransfer.push_back({"GBUFFER_LEAN", "1"});
    leanTransfer.push_back({"GBUFFER_TRANSFER", "5"});  // after the LEAN targets 3 and 4
    auto gbufferLeanTransfer = gl::buildProgram({"gbuffer.vert", "gbuffer.frag", leanTransfer, {}});
    if (!gbufferLeanTransfer.ok()) return gbufferLeanTransfer.error();
    programs.gbufferLeanTransfer = std::move(*gbufferLeanTransfer);
    return programs;
}

}  // namespace dermis
