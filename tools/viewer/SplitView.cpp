#include "viewer/SplitView.h"

#include <algorithm>
#include <string>

namespace dermis::viewer {
namespace {

// The viewer's one program lives here rather than in shaders/: it is part of
// the tool, not of the renderer, and must work even while shaders/ is broken.
const char* const kVertexSource = R"(#version 450
const vec2 kCorners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
void main() { gl_Position = vec4(kCorners[gl_VertexID], 0.0, 1.0); }
)";

const char* const kFragmentSource = R"(#version 450
layout(binding = 0) uniform sampler2D uA;
layout(binding = 1) uniform sampler2D uB;
layout(location = 0) uniform ivec2 uOrigin;
layout(location = 1) uniform int uMode;        // 0 single, 1 split, 2 difference
layout(location = 2) uniform float uDividerPx;
layout(location = 3) uniform int uTransform;   // 0 as stored, 1 range, 2 range + sRGB
layout(location = 4) uniform vec2 uRange;
layout(location = 5) uniform float uDifferenceScale;
layout(location = 0) out vec4 oColour;

vec3 encodeSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec3 toDisplay(vec3 v) {
    if (uTransform == 0) return clamp(v, 0.0, 1.0);
    v = clamp((v - uRange.x) / max(uRange.y - uRange.x, 1e-20), 0.0, 1.0);
    return uTransform == 2 ? encodeSrgb(v) : v;
}

// Black, blue, cyan, green, yellow, red: small differences stay dark.
vec3 falseColour(float t) {
    const vec3 stops[6] = vec3[](vec3(0.0), vec3(0.1, 0.1, 0.8), vec3(0.0, 0.7, 0.8), vec3(0.2, 0.8, 0.1),
                                 vec3(1.0, 0.85, 0.0), vec3(1.0, 0.1, 0.0));
    float x = clamp(t, 0.0, 1.0) * 5.0;
    int i = min(int(x), 4);
    return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy) - uOrigin;
    vec3 a = toDisplay(texelFetch(uA, pixel, 0).rgb);
    if (uMode == 0) {
        oColour = vec4(a, 1.0);
        return;
    }
    vec3 b = toDisplay(texelFetch(uB, pixel, 0).rgb);
    if (uMode == 1) {
        oColour = vec4(float(pixel.x) < uDividerPx ? a : b, 1.0);
        return;
    }
    vec3 d = abs(a - b);
    oColour = vec4(falseColour(max(d.r, max(d.g, d.b)) * uDifferenceScale), 1.0);
}
)";

Result<GLuint> compile(GLenum stage, const char* source, const char* name) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE) return shader;
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    return makeError(std::string("viewer ") + name + " shader", log.c_str());
}

}  // namespace

Result<SplitView> SplitView::create() {
    auto vertex = compile(GL_VERTEX_SHADER, kVertexSource, "vertex");
    if (!vertex.ok()) return vertex.error();
    auto fragment = compile(GL_FRAGMENT_SHADER, kFragmentSource, "fragment");
    if (!fragment.ok()) {
        glDeleteShader(*vertex);
        return fragment.error();
    }
    SplitView view;
    view.mProgram = gl::Program(glCreateProgram());
    glAttachShader(view.mProgram.get(), *vertex);
    glAttachShader(view.mProgram.get(), *fragment);
    glLinkProgram(view.mProgram.get());
    glDeleteShader(*vertex);
    glDeleteShader(*fragment);
    GLint linked = GL_FALSE;
    glGetProgramiv(view.mProgram.get(), GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) return makeError("viewer shader", "the display program did not link");
    view.mVertexArray = gl::createVertexArray("viewer: split view");
    return view;
}

void SplitView::draw(const PixelRect& area, GLuint a, GLuint b, const DisplaySettings& settings) const {
    if (area.width <= 0 || area.height <= 0 || a == 0) return;
    const GLuint program = mProgram.get();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(area.x, area.y, area.width, area.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const int mode = settings.mode == ViewMode::Single || b == 0 ? 0 : settings.mode == ViewMode::Split ? 1 : 2;
    glProgramUniform2i(program, 0, area.x, area.y);
    glProgramUniform1i(program, 1, mode);
    glProgramUniform1f(program, 2, settings.dividerPx);
    glProgramUniform1i(program, 3, static_cast<int>(settings.transform));
    glProgramUniform2f(program, 4, settings.range.x, settings.range.y);
    glProgramUniform1f(program, 5, settings.differenceScale);
    glUseProgram(program);
    glBindTextureUnit(0, a);
    glBindTextureUnit(1, mode == 0 ? a : b);
    glBindVertexArray(mVertexArray.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace dermis::viewer
