// dermis_test_content DIR: writes the glTF test content of
// tests/support/TestContent.h into DIR (for the docs' images and for trying
// the engine on skinned content by hand).
#include "TestContent.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

int main(int argc, char** argv) {
    if (argc != 2 || std::string(argv[1]) == "--help") {
        std::fprintf(argc == 2 ? stdout : stderr, "usage: dermis_test_content DIR\n"
                                                  "Writes into DIR (tests/support/TestContent.h):\n"
                                                  "  bending_cylinder.gltf        the skinned, animated test cylinder\n"
                                                  "  bending_cylinder_atlas.gltf  the same with its UVs in 1/16 of the square\n"
                                                  "  multi_material.gltf          skin, cloth and wax primitives, factors, COLOR_0\n"
                                                  "  avatar.gltf                  the head as skin, hair, eye and cloth materials,\n"
                                                  "                               with avatar_albedo.png and avatar_normal.png\n");
        return argc == 2 ? 0 : 2;
    }
    const std::filesystem::path dir(argv[1]);
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) {
        std::fprintf(stderr, "error: %s: %s\n", argv[1], error.message().c_str());
        return 1;
    }
    std::string message;
    using Writer = bool (*)(const std::string&, std::string*);
    const std::pair<const char*, Writer> files[] = {
        {"bending_cylinder.gltf", [](const std::string& p, std::string* e) { return dermis::test::writeBendingCylinder(p, e); }},
        {"bending_cylinder_atlas.gltf",
         [](const std::string& p, std::string* e) { return dermis::test::writeBendingCylinder(p, e, 0.25f); }},
        {"multi_material.gltf", dermis::test::writeMultiMaterialStrip},
        {"avatar.gltf", [](const std::string& p, std::string* e) { return dermis::test::writeAvatar(p, e, true); }}};
    for (const auto& [name, write] : files) {
        const std::string path = (dir / name).string();
        if (!write(path, &message)) {
            std::fprintf(stderr, "error: %s\n", message.c_str());
            return 1;
        }
        std::printf("wrote %s\n", path.c_str());
    }
    return 0;
}
