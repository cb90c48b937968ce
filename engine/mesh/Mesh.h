#pragma once
// CPU-side triangle meshes, in the character's own units (see
// Character::metresPerUnit). Every loader and procedural generator produces
// this one layout; the GPU upload does not care where a mesh came from.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dermis {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w = bitangent sign (glTF convention)
    glm::vec2 uv{0.0f};                         // glTF convention: v = 0 at the image's top row
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 centre() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
};

struct MeshData {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // triangle list

    size_t triangleCount() const { return indices.size() / 3; }
    Bounds bounds() const;
};

}  // namespace dermis
