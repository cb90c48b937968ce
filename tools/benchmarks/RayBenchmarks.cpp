// Intel Embree (raytrace/EmbreeBvh.h) against the in-house BVH (raytrace/Bvh.h)
// on the rays the CPU reference and the SH transfer cast, over the default
// head and the head scan (skipped when its content is absent):
//   occlusion  any-hit rays from points spread over the surface, cosine-
//              distributed about the face normal, unbounded: the environment's
//              visibility rays (ReferenceLighting) and the SH transfer's
//   camera     closest hits of the scene camera's rays at 320x180
// One thread; the two take turns within each iteration so that a slow spell of
// the shared machine hits both. Every answer of one is checked against the
// other's (disagreements are counted and printed: they must be grazing rays only).
#include "BenchContext.h"
#include "RayBenchmarks.h"

#include "core/Hash.h"
#include "import/ModelLoader.h"
#include "raytrace/Bvh.h"
#include "raytrace/EmbreeBvh.h"
#include "raytrace/Sampling.h"
#include "reference/CharacterSurface.h"
#include "reference/PixelSampling.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace dermis::bench {
namespace {

constexpr size_t kOcclusionRays = 400'000;
constexpr int kCameraWidth = 320;
constexpr int kCameraHeight = 180;
constexpr float kOffsetM = 1e-5f;  // as the reference's shadow rays

struct RayFigures {
    size_t triangles = 0;
    double buildMs[2] = {0, 0};       // in-house, Embree
    double occlusionMs[2] = {0, 0};
    double cameraMs[2] = {0, 0};
    size_t occlusionDisagreements = 0;
    size_t cameraDisagreements = 0;
};
std::map<std::string, RayFigures> sFigures;

}  // namespace

bool loadRayWorkload(const std::string& sceneName, RayWorkload* out) {
    const Scene& scene = contentScene(sceneName);
    for (const Character& character : scene.characters) {
        auto model = loadCharacterModel(character);
        if (!model.ok()) return false;
        auto surface = reference::CharacterSurface::create(character, std::move(*model));
        if (!surface.ok()) return false;
        for (size_t t = 0; t < surface->triangleCount(); ++t) {
            for (int i = 0; i < 3; ++i) out->cornersM.push_back(surface->corner(t, i));
        }
    }
    const size_t triangles = out->cornersM.size() / 3;
    if (triangles == 0) return false;
    for (size_t r = 0; r < kOcclusionRays; ++r) {
        const uint32_t hash = lowbias32(uint32_t(r) * 0x9e3779b9u + 17u);
        const size_t t = hash % triangles;
        const glm::vec3 a = out->cornersM[3 * t], b = out->cornersM[3 * t + 1], c = out->cornersM[3 * t + 2];
        glm::vec3 n = glm::cross(b - a, c - a);
        if (!(glm::length(n) > 0.0f)) continue;
        n = glm::normalize(n);
        float u = raytrace::unitFloatFromHash(lowbias32(hash + 1u));
        float v = raytrace::unitFloatFromHash(lowbias32(hash + 2u));
        if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        const glm::vec3 p = a + u * (b - a) + v * (c - a);
        const glm::vec2 disc = raytrace::concentricDisc(glm::vec2(raytrace::unitFloatFromHash(lowbias32(hash + 3u)),
                                                                  raytrace::unitFloatFromHash(lowbias32(hash + 4u))));
        const glm::vec3 tangent = glm::normalize(glm::cross(n, std::fabs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
        const glm::vec3 bitangent = glm::cross(n, tangent);
        const float up = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disc, disc)));
        out->occlusion.push_back(raytrace::Ray{p + kOffsetM * n, disc.x * tangent + disc.y * bitangent + up * n});
    }
    const reference::CameraRays camera(scene.camera, kCameraWidth, kCameraHeight);
    for (int y = 0; y < kCameraHeight; ++y) {
        for (int x = 0; x < kCameraWidth; ++x) out->camera.push_back(camera.through(float(x) + 0.5f, float(y) + 0.5f));
    }
    out->nearM = scene.camera.nearM;
    out->farM = scene.camera.farM;
    return true;
}

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

template <class Tracer>
void trace(const Tracer& tracer, const RayWorkload& work, std::vector<uint8_t>& occluded, std::vector<raytrace::BvhHit>& hits,
           double* occlusionMs, double* cameraMs) {
    auto start = std::chrono::steady_clock::now();
    occluded.resize(work.occlusion.size());
    for (size_t r = 0; r < work.occlusion.size(); ++r) {
        occluded[r] = tracer.anyHit(work.occlusion[r], 0.0f, std::numeric_limits<float>::infinity());
    }
    *occlusionMs = msSince(start);
    start = std::chrono::steady_clock::now();
    hits.assign(work.camera.size(), raytrace::BvhHit{-1.0f, 0, 0, 0});
    for (size_t r = 0; r < work.camera.size(); ++r) tracer.closestHit(work.camera[r], work.nearM, work.farM, &hits[r]);
    *cameraMs = msSince(start);
}

void rayTracers(benchmark::State& state, const std::string& sceneName) {
    RayWorkload work;
    if (!loadRayWorkload(sceneName, &work)) {
        state.SkipWithError(("cannot load " + sceneName + " (the scan's content absent?)").c_str());
        return;
    }
    RayFigures& figures = sFigures[sceneName];
    figures.triangles = work.cornersM.size() / 3;
    std::vector<double> build[2], occlusion[2], camera[2];
    for (auto _ : state) {
        auto start = std::chrono::steady_clock::now();
        const raytrace::Bvh bvh = raytrace::Bvh::build(work.cornersM);
        build[0].push_back(msSince(start));
        start = std::chrono::steady_clock::now();
        const raytrace::EmbreeBvh embree = raytrace::EmbreeBvh::build(work.cornersM);
        build[1].push_back(msSince(start));
        std::vector<uint8_t> occluded[2];
        std::vector<raytrace::BvhHit> hits[2];
        double ms[2][2];
        trace(bvh, work, occluded[0], hits[0], &ms[0][0], &ms[0][1]);
        trace(embree, work, occluded[1], hits[1], &ms[1][0], &ms[1][1]);
        for (int k = 0; k < 2; ++k) {
            occlusion[k].push_back(ms[k][0]);
            camera[k].push_back(ms[k][1]);
        }
        figures.occlusionDisagreements = 0;
        for (size_t r = 0; r < occluded[0].size(); ++r) figures.occlusionDisagreements += occluded[0][r] != occluded[1][r];
        figures.cameraDisagreements = 0;
        for (size_t r = 0; r < hits[0].size(); ++r) {
            figures.cameraDisagreements += hits[0][r].triangle != hits[1][r].triangle || (hits[0][r].t < 0) != (hits[1][r].t < 0);
        }
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    for (int k = 0; k < 2; ++k) {
        figures.buildMs[k] = median(build[k]);
        figures.occlusionMs[k] = median(occlusion[k]);
        figures.cameraMs[k] = median(camera[k]);
    }
    state.counters["embree_speedup_occlusion"] = figures.occlusionMs[0] / std::max(figures.occlusionMs[1], 1e-9);
}

BENCHMARK_CAPTURE(rayTracers, default_head, std::string("default.json"))->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rayTracers, scan, std::string("lee_perry_smith.json"))->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

void printRaySummary() {
    if (sFigures.empty()) return;
    std::printf("\nRay tracers, one thread (median ms; in-house BVH / Embree = speed-up):\n");
    std::printf("%-22s %9s  %-26s %-26s %-26s %s\n", "scene", "triangles", "build", "occlusion (400k rays)",
                "camera (320x180)", "disagreements (occl., camera)");
    for (const auto& [scene, f] : sFigures) {
        auto cell = [](const double ms[2]) {
            char text[64];
            std::snprintf(text, sizeof text, "%7.1f / %6.1f = %5.2fx", ms[0], ms[1], ms[0] / std::max(ms[1], 1e-9));
            return std::string(text);
        };
        std::printf("%-22s %9zu  %-26s %-26s %-26s %zu, %zu\n", scene.c_str(), f.triangles, cell(f.buildMs).c_str(),
                    cell(f.occlusionMs).c_str(), cell(f.cameraMs).c_str(), f.occlusionDisagreements,
                    f.cameraDisagreements);
    }
}

}  // namespace dermis::bench
