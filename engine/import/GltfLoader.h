#pragma once
// glTF 2.0 (.gltf and .glb) through tinygltf. Every primitive of every mesh
// node in the default scene is merged into one Model with its node transform
// applied. Tangents are generated (MikkTSpace-style) when the file has none.
// Images decode through OpenImageIO, so any format it reads works.

#include "core/Result.h"
#include "mesh/Model.h"

#include <string>

namespace dermis {

// The glTF extensions a file may list in extensionsRequired (docs/gltf.md says what each
// does); a file requiring any other is refused in one line naming it.
inline constexpr const char* kSupportedGltfExtensions[] = {"KHR_mesh_quantization", "KHR_texture_transform",
                                                             "EXT_meshopt_compression", "KHR_draco_mesh_compression",
                                                             // the surface beneath (import/MaterialScattering.h)
                                                             "KHR_materials_diffuse_transmission", "KHR_materials_volume",
                                                             // read as far as it can be: each KTX2 texture is skipped
                                                             // with a warning (no Debian decoder), the rest loads
                                                             "KHR_texture_basisu"};

Result<Model> loadGltf(const std::string& path);

}  // namespace dermis
