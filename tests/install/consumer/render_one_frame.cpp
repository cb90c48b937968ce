// Renders one frame of a scene with the installed engine and writes it as a
// PNG: render_one_frame SCENE WIDTHxHEIGHT OUT.png. Prints the shader folder
// the engine read (core/DataDirectory.h), for the test to check.
#include "core/DataDirectory.h"
#include "core/Image.h"
#include "frame/Renderer.h"
#include "gl/GlContext.h"
#include "scene/SceneLoader.h"

#include <cstdio>
#include <string>

namespace {

int fail(const dermis::Error& error) {
    std::fprintf(stderr, "error: %s\n", error.message().c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: render_one_frame SCENE WIDTHxHEIGHT OUT.png\n");
        return 2;
    }
    int width = 0, height = 0;
    if (std::sscanf(argv[2], "%dx%d", &width, &height) != 2) {
        std::fprintf(stderr, "error: size '%s' is not WIDTHxHEIGHT\n", argv[2]);
        return 2;
    }
    auto scene = dermis::loadScene(argv[1]);
    if (!scene.ok()) return fail(scene.error());
    auto context = dermis::gl::createHeadlessContext({});
    if (!context.ok()) return fail(context.error());
    auto renderer = dermis::Renderer::create(*scene);
    if (!renderer.ok()) return fail(renderer.error());
    if (const dermis::Status status = (*renderer)->renderFrame({width, height}); !status.ok()) return fail(status.error());
    auto image = (*renderer)->readOutput();
    if (!image.ok()) return fail(image.error());
    if (const dermis::Status saved = dermis::saveImage(argv[3], *image); !saved.ok()) return fail(saved.error());
    std::printf("shaders: %s\n", dermis::dataDirectory(dermis::DataKind::Shaders).c_str());
    return 0;
}
