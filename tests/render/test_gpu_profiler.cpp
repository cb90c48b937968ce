// The GPU profiler gives each pass its own time when passes share a
// framebuffer. llvmpipe bins the commands of a batch per tile and runs each
// tile's list in turn, so without a break between two such passes the first
// one's end stamp is read when the last tile reaches it: the first pass
// showed the whole batch's time and the second almost none (in the budget
// crowd, `sss skin disk` read 0.1 ms and the separable pass before it 22 ms,
// against 17 and 5 ms alone).
#include "GlTestEnvironment.h"

#include "gl/Gl.h"
#include "gl/GlObjects.h"
#include "gl/GpuProfiler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

using namespace dermis;

namespace {

class GpuProfilerTest : public test::GlTest {};

GLuint compile(GLenum stage, const std::string& text) {
    const GLuint shader = glCreateShader(stage);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE) << text;
    return shader;
}

// A full-screen triangle whose fragment shader loops `iterations` times.
GLuint fullscreenProgram(int iterations) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, R"(#version 450
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})");
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, "#version 450\nconst int kIterations = " +
                                                            std::to_string(iterations) + R"(;
layout(location = 0) out vec4 colour;
void main() {
    float v = gl_FragCoord.x * 1e-3;
    for (int i = 0; i < kIterations; ++i) v = sin(v * 1.0001 + 0.5);
    colour = vec4(v, 0.0, 0.0, 1.0);
})");
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return program;
}

}  // namespace

// Three passes into one framebuffer: cheap, 400 times dearer, cheap. The
// dear pass's GPU time must agree with the wall time of its draw run alone
// between two glFinish calls (the median of three), and be several times
// either cheap pass's. The bounds are loose (a factor of two; 5x where the
// shaders differ 400x) because llvmpipe's times vary by tens of percent from
// run to run and each pass's time also holds its recording; misattributed,
// the dear pass read 3.5 ms against 29.5 ms (setSplitBatches(false) on
// llvmpipe, 320x180), far outside them.
TEST_F(GpuProfilerTest, PassesThatShareAFramebufferEachGetTheirOwnTime) {
    const GLuint cheap = fullscreenProgram(1);
    const GLuint dear = fullscreenProgram(400);
    gl::Texture target = gl::createTexture(GL_TEXTURE_2D, "test: profiler target");
    glTextureStorage2D(target.get(), 1, GL_RGBA8, 320, 180);
    gl::Framebuffer framebuffer = gl::createFramebuffer("test: profiler target");
    glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, target.get(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    glViewport(0, 0, 320, 180);
    GLuint vertexArray = 0;
    glCreateVertexArrays(1, &vertexArray);
    glBindVertexArray(vertexArray);

    gl::GpuProfiler profiler;
    const std::vector<std::pair<std::string, GLuint>> passes = {{"cheap before", cheap}, {"dear", dear}, {"cheap after", cheap}};
    constexpr int kFrames = 4;  // the first compiles the shaders' variants: only the last is read
    for (int frame = 0; frame < kFrames; ++frame) {
        profiler.beginFrame(uint64_t(frame));
        for (const auto& [name, program] : passes) {
            profiler.beginPass(name);
            glUseProgram(program);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            profiler.endPass();
        }
    }
    profiler.drain();
    std::map<std::string, double> lastFrameMs;
    for (const gl::PassTiming& timing : profiler.takeCompleted())
        if (timing.frame == kFrames - 1) lastFrameMs[timing.pass] = timing.gpuMs;
    ASSERT_EQ(lastFrameMs.size(), 3u);
    std::vector<double> aloneMs;
    for (int run = 0; run < 3; ++run) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        glUseProgram(dear);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
        aloneMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(aloneMs.begin(), aloneMs.end());
    EXPECT_GT(lastFrameMs["dear"], 0.5 * aloneMs[1]) << "run alone: " << aloneMs[1] << " ms";
    EXPECT_LT(lastFrameMs["dear"], 2.0 * aloneMs[1]) << "run alone: " << aloneMs[1] << " ms";
    const double cheapest = std::max(lastFrameMs["cheap before"], lastFrameMs["cheap after"]);
    EXPECT_GT(lastFrameMs["dear"], 5.0 * cheapest)
        << "dear " << lastFrameMs["dear"] << " ms, cheap before " << lastFrameMs["cheap before"] << " ms, cheap after "
        << lastFrameMs["cheap after"] << " ms";

    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    glDeleteProgram(cheap);
    glDeleteProgram(dear);
}
