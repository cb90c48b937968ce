#pragma once
// KHR_texture_transform: an offset, a rotation and a scale applied to a
// texture's coordinates, uv' = T(offset) R(rotation) S(scale) uv (the
// extension's specification, Khronos 2017-2022). gltfpack writes it to scale
// quantized UVs (KHR_mesh_quantization) back to [0, 1], and ignoring it draws
// every texture from one corner of its image.
//
// Dermis draws a primitive with one set of UVs for all its maps, so the
// transform is applied to the primitive's TEXCOORD_0 at load: the transform of
// the material's base colour texture, or of its first textured map. When the
// material's maps disagree, one warning names them (the others then read
// through the first one's transform).

#include "core/Result.h"

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <string>

namespace dermis {

struct UvTransform {
    glm::mat3 uvFromFile{1.0f};  // homogeneous 2-D: apply to (u, v, 1)
    bool identity = true;
    glm::vec2 apply(const glm::vec2& uv) const { return glm::vec2(uvFromFile * glm::vec3(uv, 1.0f)); }
};

// The transform of one texture reference's extensions (identity without the extension);
// malformed values are refused, naming `where`.
Result<UvTransform> readTextureTransform(const tinygltf::ExtensionMap& extensions, const std::string& where,
                                         const std::string& path);

// The transform to apply to the UVs of primitives drawn with material `material`
// (-1: the default material, identity).
Result<UvTransform> materialUvTransform(const tinygltf::Model& gltf, int material, const std::string& path);

}  // namespace dermis
