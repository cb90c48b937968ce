// The time `loadGltf` takes on a head of more than 100k triangles, written as
// a plain glTF and compressed by the encoders users have (gltfpack -c and -cc,
// EXT_meshopt_compression; draco_transcoder, KHR_draco_mesh_compression). The
// head is the procedural one (56 704 triangles) split once at its edges'
// midpoints (226 816). The files take turns within each iteration, so a slow
// spell of the shared machine hits all of them; the summary gives medians.
// An encoder that is not installed is skipped with a line saying so.
#include "GltfDecodeBenchmarks.h"

#include "import/GltfLoader.h"
#include "procedural/Procedural.h"

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

namespace fs = std::filesystem;

struct DecodeFigures {
    size_t triangles = 0;
    std::vector<double> ms;
};
std::map<std::string, DecodeFigures> sDecode;  // by file
std::vector<std::string> sSkipped;

// Each triangle split in four at its edges' midpoints (shared midpoints once per edge).
MeshData subdivided(const MeshData& mesh) {
    MeshData out;
    out.vertices = mesh.vertices;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
        const auto key = std::minmax(a, b);
        const auto it = midpoints.find(key);
        if (it != midpoints.end()) return it->second;
        Vertex v = mesh.vertices[a];
        const Vertex& w = mesh.vertices[b];
        v.position = 0.5f * (v.position + w.position);
        v.normal = glm::normalize(v.normal + w.normal);
        v.uv = 0.5f * (v.uv + w.uv);
        out.vertices.push_back(v);
        const uint32_t index = uint32_t(out.vertices.size() - 1);
        midpoints.emplace(key, index);
        return index;
    };
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    return out;
}

// A plain glTF of positions, normals, UVs and 32-bit indices.
void writePlainGltf(const MeshData& mesh, const fs::path& path) {
    std::vector<unsigned char> bin;
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
    auto add = [&](const void* data, size_t bytes, int componentType, const char* type, size_t count) {
        while (bin.size() % 4) bin.push_back(0);
        const size_t offset = bin.size();
        bin.resize(offset + bytes);
        std::memcpy(bin.data() + offset, data, bytes);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        doc["accessors"].push_back(
            {{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", componentType}, {"count", count}, {"type", type}});
        return int(doc["accessors"].size() - 1);
    };
    std::vector<float> positions, normals, uvs;
    glm::vec3 low(1e30f), high(-1e30f);
    for (const Vertex& v : mesh.vertices) {
        positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
        normals.insert(normals.end(), {v.normal.x, v.normal.y, v.normal.z});
        uvs.insert(uvs.end(), {v.uv.x, v.uv.y});
        low = glm::min(low, v.position);
        high = glm::max(high, v.position);
    }
    const size_t n = mesh.vertices.size();
    const int position = add(positions.data(), positions.size() * 4, 5126, "VEC3", n);
    doc["accessors"][position]["min"] = {low.x, low.y, low.z};
    doc["accessors"][position]["max"] = {high.x, high.y, high.z};
    const int normal = add(normals.data(), normals.size() * 4, 5126, "VEC3", n);
    const int uv = add(uvs.data(), uvs.size() * 4, 5126, "VEC2", n);
    const int indices = add(mesh.indices.data(), mesh.indices.size() * 4, 5125, "SCALAR", mesh.indices.size());
    nlohmann::json primitive;
    primitive["attributes"] = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}};
    primitive["indices"] = indices;
    nlohmann::json meshJson;
    meshJson["primitives"] = nlohmann::json::array({primitive});
    doc["meshes"] = nlohmann::json::array({meshJson});
    doc["nodes"] = {{{"mesh", 0}}};
    doc["scenes"] = {{{"nodes", {0}}}};
    doc["scene"] = 0;
    const std::string binName = path.stem().string() + ".bin";
    doc["buffers"] = {{{"byteLength", bin.size()}, {"uri", binName}}};
    std::ofstream(path.parent_path() / binName, std::ios::binary).write(reinterpret_cast<const char*>(bin.data()),
                                                                        std::streamsize(bin.size()));
    std::ofstream(path) << doc.dump();
}

bool have(const char* tool) { return std::system((std::string("command -v ") + tool + " > /dev/null 2>&1").c_str()) == 0; }

// The files to load, made once: name -> path.
const std::map<std::string, fs::path>& files() {
    static const std::map<std::string, fs::path> made = [] {
        std::map<std::string, fs::path> out;
        const fs::path dir = fs::temp_directory_path() / "dermis_gltf_decode_bench";
        fs::create_directories(dir);
        auto head = makeProceduralModel("head");
        if (!head.ok()) return out;
        writePlainGltf(subdivided(head->mesh), dir / "head.gltf");
        out["plain .gltf"] = dir / "head.gltf";
        const std::string source = (dir / "head.gltf").string();
        if (have("gltfpack")) {
            for (const auto& [name, options] : {std::pair{"gltfpack (quantized)", ""}, std::pair{"gltfpack -c", "-c"},
                                                std::pair{"gltfpack -cc", "-cc"}}) {
                const fs::path packed = dir / (std::string("head_") + (*options ? options + 1 : "q") + ".glb");
                if (std::system(("gltfpack -i " + source + " -o " + packed.string() + " " + options + " > /dev/null 2>&1").c_str()) == 0)
                    out[name] = packed;
            }
        } else {
            sSkipped.push_back("gltfpack is not installed");
        }
        if (have("draco_transcoder")) {
            const fs::path packed = dir / "head_draco.glb";
            if (std::system(("draco_transcoder -i " + source + " -o " + packed.string() + " > /dev/null 2>&1").c_str()) == 0)
                out["draco_transcoder"] = packed;
        } else {
            sSkipped.push_back("draco_transcoder is not installed");
        }
        return out;
    }();
    return made;
}

void gltfDecode(benchmark::State& state) {
    const auto& paths = files();
    if (paths.empty()) {
        state.SkipWithError("the procedural head could not be made");
        return;
    }
    for (auto _ : state) {
        for (const auto& [name, path] : paths) {
            const auto start = std::chrono::steady_clock::now();
            auto model = loadGltf(path.string());
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (!model.ok()) {
                state.SkipWithError((name + ": " + model.error().message()).c_str());
                return;
            }
            sDecode[name].triangles = model->mesh.triangleCount();
            sDecode[name].ms.push_back(ms);
        }
    }
}

BENCHMARK(gltfDecode)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

void printGltfDecodeSummary() {
    if (sDecode.empty()) return;
    std::printf("\nLoading the subdivided procedural head (loadGltf, median of 3, ms):\n");
    for (const auto& [name, figures] : sDecode) {
        std::vector<double> ms = figures.ms;
        std::sort(ms.begin(), ms.end());
        std::error_code error;
        const uintmax_t bytes = fs::file_size(files().at(name), error);
        std::printf("  %-22s %8zu triangles  %8.1f ms  (file %ju KiB)\n", name.c_str(), figures.triangles,
                    ms[ms.size() / 2], error ? uintmax_t(0) : bytes / 1024);
    }
    for (const std::string& skipped : sSkipped) std::printf("  skipped: %s\n", skipped.c_str());
}

}  // namespace dermis::bench
