#include "render/Programs.h"

#include "render/BeckmannTable.h"

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
        auto program = gl::buildProgram({e.vertex, e.fragment, defines});
        if (!program.ok()) return program.error();
        programs.*(e.member) = std::move(*program);
    }
    return programs;
}

}  // namespace dermis
