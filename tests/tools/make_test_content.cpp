// dermis_test_content DIR: writes the glTF test content of
// tests/support/TestContent.h into DIR (for the docs' images and for trying
// the engine on skinned content by hand).
#include "TestContent.h"

#include <cstdio>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2 || std::string(argv[1]) == "--help") {
        std::fprintf(argc == 2 ? stdout : stderr, "usage: dermis_test_content DIR\n"
                                                  "Writes into DIR (tests/support/TestContent.h):\n"
                                                  "  bending_cylinder.gltf        the skinned, animated test cylinder\n"
                                                  "  bending_cylinder_atlas.gltf  the same with its UVs in 1/16 of the square\n");
        return argc == 2 ? 0 : 2;
    }
    const std::filesystem::path dir(argv[1]);
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) {
        std::fprintf(stderr, "error: %s: %s\n", argv[1], error.message().c_str());
        return 1;
    }
    const struct {
        const char* name;
        float uvScale;
    } files[] = {{"bending_cylinder.gltf", 1.0f}, {"bending_cylinder_atlas.gltf", 0.25f}};
    for (const auto& file : files) {
        std::string message;
        const std::string path = (dir / file.name).string();
        if (!dermis::test::writeBendingCylinder(path, &message, file.uvScale)) {
            std::fprintf(stderr, "error: %s\n", message.c_str());
            return 1;
        }
        std::printf("wrote %s\n", path.c_str());
    }
    return 0;
}
