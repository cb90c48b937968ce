#pragma once
// KHR_draco_mesh_compression (what `draco_transcoder` writes): a primitive
// whose attributes and indices are one Draco-compressed buffer view, decoded
// with the Draco library (Google, Debian libdraco-dev). Each decoded primitive
// gets a new buffer with plain float attributes and 32-bit indices, and its
// accessors are pointed at it, so the rest of the loader reads it as any
// other primitive. Skin attributes (JOINTS_n, WEIGHTS_n) decode the same way;
// the extension has no morph targets (draco_transcoder 1.5.5 refuses them).

#include "core/Result.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <string>

namespace dermis {

// tinygltf refuses a primitive whose indices accessor has no bufferView, as a compressed
// primitive's has: before tinygltf reads `document`, such primitives lose their "indices"
// (decodeDracoPrimitives gives them decoded ones). True if anything changed.
bool detachDracoIndices(nlohmann::json& document);

// Decodes every compressed primitive of `gltf` in place; the buffer view, the
// attribute ids and each decoded attribute's size are checked, and a failure
// names the mesh and primitive.
Status decodeDracoPrimitives(tinygltf::Model& gltf, const std::string& path);

}  // namespace dermis
