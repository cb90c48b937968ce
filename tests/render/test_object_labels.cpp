// Every GL object the renderer makes has a name (gl/GlObjects.h), so that a
// frame capture shows "character 'head': vertices", not "Buffer 17"
// (docs/profiling.md, "RenderDoc"). GL cannot list objects, so every name
// from 1 up is asked: is it a buffer, texture, framebuffer, vertex array,
// program or query? Names are small integers handed out in order in Mesa;
// the scan stops after a long run of names that are nothing.
#include "RenderFixture.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace dermis {
namespace {

constexpr GLuint kGapThatEndsTheScan = 4096;

struct Unlabelled {
    const char* kind;
    GLuint name;
};

// Fills `labels` with "kind: label" of every labelled object (the docs quote them).
std::vector<Unlabelled> unlabelledObjects(size_t* seen, std::vector<std::string>* labels) {
    struct Kind {
        const char* name;
        GLenum identifier;
        GLboolean (*exists)(GLuint);
    };
    // glIs* are function pointers loaded by glad: wrap each to call through.
    static const Kind kinds[] = {
        {"buffer", GL_BUFFER, [](GLuint n) { return glIsBuffer(n); }},
        {"texture", GL_TEXTURE, [](GLuint n) { return glIsTexture(n); }},
        {"framebuffer", GL_FRAMEBUFFER, [](GLuint n) { return glIsFramebuffer(n); }},
        {"vertex array", GL_VERTEX_ARRAY, [](GLuint n) { return glIsVertexArray(n); }},
        {"program", GL_PROGRAM, [](GLuint n) { return glIsProgram(n); }},
        {"query", GL_QUERY, [](GLuint n) { return glIsQuery(n); }},
    };
    std::vector<Unlabelled> out;
    *seen = 0;
    for (const Kind& kind : kinds) {
        GLuint gap = 0;
        for (GLuint name = 1; gap < kGapThatEndsTheScan; ++name) {
            if (!kind.exists(name)) {
                ++gap;
                continue;
            }
            gap = 0;
            ++*seen;
            char label[256] = {};
            GLsizei length = 0;
            glGetObjectLabel(kind.identifier, name, sizeof label, &length, label);
            if (length == 0) out.push_back({kind.name, name});
            if (length > 0) labels->push_back(std::string(kind.name) + ": " + std::string(label, size_t(length)));
        }
    }
    return out;
}

class ObjectLabels : public test::RenderFixture {};

// Both modes, an environment (its maps and transfer buffers), the nodding
// head (skinning buffers) and the timers' queries.
TEST_F(ObjectLabels, EveryObjectTheRendererMakesHasAName) {
    struct Case {
        const char* scene;
        std::vector<std::string> overrides;
    };
    const Case cases[] = {
        {"default.json", {"environment={\"source\":\"sky\"}"}},
        {"default.json", {"mode=ts"}},
        {"nodding.json", {}},
    };
    for (const Case& c : cases) {
        load(c.scene, c.overrides);
        render(Aov::Final, 64, 36, 2);
        mRenderer->finishTimings();
        size_t seen = 0;
        std::vector<std::string> labels;
        const std::vector<Unlabelled> unlabelled = unlabelledObjects(&seen, &labels);
        std::printf("%s %s: %zu objects\n", c.scene, c.overrides.empty() ? "" : c.overrides[0].c_str(), seen);
        for (const std::string& label : labels) std::printf("  %s\n", label.c_str());
        EXPECT_GT(seen, 30u) << c.scene << ": the scan should find the renderer's objects";
        for (const Unlabelled& object : unlabelled)
            ADD_FAILURE() << c.scene << " " << (c.overrides.empty() ? "" : c.overrides[0]) << ": " << object.kind << " "
                          << object.name << " has no label";
    }
}

}  // namespace
}  // namespace dermis
