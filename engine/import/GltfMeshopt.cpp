#include "import/GltfMeshopt.h"

#include <meshoptimizer.h>

#include <cstring>

namespace dermis {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";
// Four zero bytes: tinygltf refuses an empty data URI.
constexpr const char* kPlaceholderDataUri = "data:application/octet-stream;base64,AAAAAA==";
constexpr size_t kPlaceholderBytes = 4;
// A fallback buffer is allocated at its stated length; bounded so that a hostile
// file cannot ask for any size (a 100k-triangle character needs a few MB).
constexpr size_t kMaxFallbackBytes = size_t(1) << 30;

// A member of a tinygltf object, or null.
const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
    if (!object.IsObject() || !object.Has(key)) return nullptr;
    return &object.Get(key);
}

Result<size_t> readSize(const tinygltf::Value& object, const char* key, const std::string& where, const std::string& path,
                        bool required) {
    const tinygltf::Value* value = member(object, key);
    if (!value) {
        if (required) return makeError(path, where + ": " + kExtension + " has no " + key);
        return size_t(0);
    }
    if (!value->IsNumber() || value->GetNumberAsDouble() < 0.0 || value->GetNumberAsDouble() > 4294967295.0 ||
        value->GetNumberAsDouble() != double(size_t(value->GetNumberAsDouble())))
        return makeError(path, where + ": " + kExtension + " " + key + " must be a non-negative integer");
    return size_t(value->GetNumberAsDouble());
}

std::string readString(const tinygltf::Value& object, const char* key, const char* fallback) {
    const tinygltf::Value* value = member(object, key);
    return value && value->IsString() ? value->Get<std::string>() : fallback;
}

}  // namespace

Status setAsideMeshoptFallbacks(nlohmann::json& document, MeshoptFallbacks& fallbacks, const std::string& path) {
    fallbacks = {};
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array())
        return success();  // tinygltf reports what is wrong with it
    nlohmann::json& buffers = document["buffers"];
    for (size_t i = 0; i < buffers.size(); ++i) {
        nlohmann::json& buffer = buffers[i];
        // With or without a `uri` (gltfpack -cf writes a .fallback.bin): Dermis
        // decodes every view into it and never reads the file, which may be absent.
        if (!buffer.is_object()) continue;
        const auto extensions = buffer.find("extensions");
        if (extensions == buffer.end() || !extensions->is_object()) continue;
        const auto extension = extensions->find(kExtension);
        if (extension == extensions->end() || !extension->is_object()) continue;
        const auto fallback = extension->find("fallback");
        if (fallback == extension->end() || !fallback->is_boolean() || !fallback->get<bool>()) continue;
        const auto length = buffer.find("byteLength");
        if (length == buffer.end() || !length->is_number_unsigned())
            return makeError(path, "buffer " + std::to_string(i) + " (an " + kExtension +
                                       " fallback) has no valid byteLength");
        const size_t bytes = length->get<size_t>();
        if (bytes > kMaxFallbackBytes)
            return makeError(path, "buffer " + std::to_string(i) + " (an " + kExtension + " fallback) of " +
                                       std::to_string(bytes) + " bytes is larger than " +
                                       std::to_string(kMaxFallbackBytes));
        fallbacks.buffers.emplace_back(i, bytes);
        buffer["byteLength"] = kPlaceholderBytes;
        buffer["uri"] = kPlaceholderDataUri;
    }
    return success();
}

Status decodeMeshoptViews(tinygltf::Model& gltf, const MeshoptFallbacks& fallbacks, const std::string& path) {
    for (const auto& [index, bytes] : fallbacks.buffers) {
        if (index < gltf.buffers.size()) gltf.buffers[index].data.assign(bytes, 0);
    }
    for (size_t v = 0; v < gltf.bufferViews.size(); ++v) {
        tinygltf::BufferView& view = gltf.bufferViews[v];
        const auto found = view.extensions.find(kExtension);
        if (found == view.extensions.end()) continue;
        const tinygltf::Value& extension = found->second;
        const std::string where = "bufferView " + std::to_string(v);
        Result<size_t> source = readSize(extension, "buffer", where, path, true);
        if (!source) return source.error();
        Result<size_t> offset = readSize(extension, "byteOffset", where, path, false);
        if (!offset) return offset.error();
        Result<size_t> length = readSize(extension, "byteLength", where, path, true);
        if (!length) return length.error();
        Result<size_t> stride = readSize(extension, "byteStride", where, path, true);
        if (!stride) return stride.error();
        Result<size_t> count = readSize(extension, "count", where, path, true);
        if (!count) return count.error();
        const std::string mode = readString(extension, "mode", "");
        const std::string filter = readString(extension, "filter", "NONE");

        if (*source >= gltf.buffers.size())
            return makeError(path, where + ": " + kExtension + " buffer " + std::to_string(*source) + " is out of range");
        const std::vector<unsigned char>& compressed = gltf.buffers[*source].data;
        if (*offset > compressed.size() || *length > compressed.size() - *offset)
            return makeError(path, where + ": " + kExtension + " data (" + std::to_string(*length) + " bytes at " +
                                       std::to_string(*offset) + ") is outside buffer " + std::to_string(*source) +
                                       " of " + std::to_string(compressed.size()) + " bytes");
        if (view.buffer < 0 || size_t(view.buffer) >= gltf.buffers.size())
            return makeError(path, where + ": buffer " + std::to_string(view.buffer) + " is out of range");
        std::vector<unsigned char>& target = gltf.buffers[size_t(view.buffer)].data;
        const size_t decodedBytes = *count * *stride;
        if (*stride == 0 || (*count != 0 && decodedBytes / *count != *stride) || decodedBytes > view.byteLength ||
            view.byteOffset > target.size() || view.byteLength > target.size() - view.byteOffset)
            return makeError(path, where + ": " + kExtension + " count " + std::to_string(*count) + " x byteStride " +
                                       std::to_string(*stride) + " does not fit the view (" +
                                       std::to_string(view.byteLength) + " bytes at " + std::to_string(view.byteOffset) +
                                       " of a buffer of " + std::to_string(target.size()) + ")");
        unsigned char* destination = target.data() + view.byteOffset;
        const unsigned char* data = compressed.data() + *offset;
        int failed = 0;
        if (mode == "ATTRIBUTES") {
            if (*stride % 4 != 0 || *stride > 256)
                return makeError(path, where + ": " + kExtension + " ATTRIBUTES byteStride " + std::to_string(*stride) +
                                           " is not a multiple of 4 up to 256");
            failed = meshopt_decodeVertexBuffer(destination, *count, *stride, data, *length);
        } else if (mode == "TRIANGLES" || mode == "INDICES") {
            if (*stride != 2 && *stride != 4)
                return makeError(path, where + ": " + kExtension + " " + mode + " byteStride must be 2 or 4");
            if (mode == "TRIANGLES" && *count % 3 != 0)
                return makeError(path, where + ": " + kExtension + " TRIANGLES count " + std::to_string(*count) +
                                           " is not a multiple of 3");
            failed = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(destination, *count, *stride, data, *length)
                                         : meshopt_decodeIndexSequence(destination, *count, *stride, data, *length);
        } else {
            return makeError(path, where + ": " + kExtension + " mode '" + mode +
                                       "' is not ATTRIBUTES, TRIANGLES or INDICES");
        }
        if (failed != 0)
            return makeError(path, where + ": " + kExtension + " data does not decode (meshoptimizer error " +
                                       std::to_string(failed) + ")");
        if (filter == "OCTAHEDRAL" || filter == "QUATERNION" || filter == "EXPONENTIAL") {
            if (mode != "ATTRIBUTES")
                return makeError(path, where + ": " + kExtension + " filter " + filter + " needs mode ATTRIBUTES");
            if (filter == "OCTAHEDRAL" && *stride != 4 && *stride != 8)
                return makeError(path, where + ": " + kExtension + " OCTAHEDRAL needs byteStride 4 or 8");
            if (filter == "QUATERNION" && *stride != 8)
                return makeError(path, where + ": " + kExtension + " QUATERNION needs byteStride 8");
            if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(destination, *count, *stride);
            if (filter == "QUATERNION") meshopt_decodeFilterQuat(destination, *count, *stride);
            if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(destination, *count, *stride);
        } else if (filter != "NONE") {
            return makeError(path, where + ": " + kExtension + " filter '" + filter + "' is not known");
        }
    }
    return success();
}

}  // namespace dermis
