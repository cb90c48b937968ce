#pragma once
// EXT_meshopt_compression (what `gltfpack -c` and `-cc` write): buffer views
// whose bytes are meshoptimizer's vertex or index codec, decoded with the
// library's own decoders (Kapoulkine, meshoptimizer) into the views' buffer.
//
// The decoded data's buffer is a "fallback" buffer that holds no bytes in the
// file. tinygltf would refuse it (no uri; in a GLB a byteLength past the BIN
// chunk), so the document is rewritten before tinygltf reads it, the fallback
// buffers' lengths set aside, and the buffers are filled after the load.

#include "core/Result.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <string>
#include <vector>

namespace dermis {

struct MeshoptFallbacks {
    std::vector<std::pair<size_t, size_t>> buffers;  // buffer index, the byteLength the file gives it
    bool empty() const { return buffers.empty(); }
};

// `document` rewritten so that tinygltf accepts its fallback buffers (a placeholder data URI
// each), and what was set aside; the document unchanged when it has none.
Status setAsideMeshoptFallbacks(nlohmann::json& document, MeshoptFallbacks& fallbacks, const std::string& path);

// Gives each fallback buffer its length back and decodes every compressed buffer view
// into its buffer; every offset, length, count, stride, mode and filter is checked first.
Status decodeMeshoptViews(tinygltf::Model& gltf, const MeshoptFallbacks& fallbacks, const std::string& path);

}  // namespace dermis
