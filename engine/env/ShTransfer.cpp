#include "env/ShTransfer.h"

#include "core/Hash.h"
#include "core/Luminance.h"
#include "env/PrefilteredEnvironment.h"
#include "env/RingingFreeSh.h"
#include "raytrace/EmbreeBvh.h"
#include "raytrace/ParallelFor.h"
#include "raytrace/Sampling.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dermis {
namespace {

constexpr float kPi = 3.14159265f;

// The ray origin sits this far (relative to the mesh's bounding-box
// diagonal) off the surface along the normal. From exactly the vertex, a
// ray meets the triangles sharing that vertex at t ~ 0, on either side of 0
// by rounding, and grazing rays meet them along their whole length if
// rounding puts the origin under them: false occlusion. 1e-4 of a 0.25 m
// head is 25 um, far above float rounding at its coordinates (~1e-8 m) and
// far below its thinnest features (ears, ~1 mm).
constexpr float kRayOffsetPerDiagonal = 1e-4f;

// Duff et al. 2017, "Building an orthonormal basis, revisited": tangent and
// bitangent of a unit normal, without a branch on its direction.
void orthonormalBasis(const glm::vec3& n, glm::vec3& tangent, glm::vec3& bitangent) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    tangent = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    bitangent = glm::vec3(b, sign + n.y * n.y * a, -n.y);
}

Status checkInputs(const MeshData& mesh, int raysPerVertex, int strataPerSide) {
    if (raysPerVertex <= 0 || strataPerSide * strataPerSide != raysPerVertex)
        return makeError(mesh.name, "SH transfer rays per vertex must be a positive square number (e.g. 256), not " +
                                        std::to_string(raysPerVertex));
    if (mesh.indices.size() % 3 != 0)
        return makeError(mesh.name, "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3");
    for (size_t i = 0; i < mesh.indices.size(); ++i)
        if (mesh.indices[i] >= mesh.vertices.size())
            return makeError(mesh.name, "index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) +
                                            ", outside the " + std::to_string(mesh.vertices.size()) + " vertices");
    return success();
}

// Calls visit(i, direction) for the vertex's rays, in the same order every
// time: the cosine-weighted directions the class comment describes.
template <class Visit>
void forEachTransferRay(size_t vertexIndex, const glm::vec3& normal, int strataPerSide, Visit&& visit) {
    glm::vec3 tangent, bitangent;
    orthonormalBasis(normal, tangent, bitangent);
    const uint32_t seed = lowbias32(uint32_t(vertexIndex) * 0x9e3779b9U + 0x632be5abU);
    const float turn = 2.0f * kPi * raytrace::unitFloatFromHash(lowbias32(seed));
    const glm::vec3 turnedTangent = std::cos(turn) * tangent + std::sin(turn) * bitangent;
    const glm::vec3 turnedBitangent = glm::cross(normal, turnedTangent);
    int i = 0;
    for (const glm::vec2& square : raytrace::jitteredGrid(strataPerSide, seed)) {
        const glm::vec2 disc = raytrace::concentricDisc(square);
        const float cosine = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disc, disc)));  // Malley's method
        visit(i++, disc.x * turnedTangent + disc.y * turnedBitangent + cosine * normal);
    }
}

// The vertex's unit normal, or false when it has none (no direction to integrate about: no light).
bool unitNormal(const Vertex& vertex, glm::vec3& normal) {
    const float normalLength = glm::length(vertex.normal);
    if (!(normalLength > 0.0f)) return false;
    normal = vertex.normal / normalLength;
    return true;
}

// The luminance of a lat-long map on the six faces of a cube, for lookups by
// direction without the lat-long's trigonometry (the visible share reads one
// per ray). Each texel holds the map's texel at its centre direction.
class LuminanceCube {
public:
    static constexpr int kFaceSize = 32;  // 2.8 degrees per texel at a face's centre, like a 128-wide lat-long

    explicit LuminanceCube(const Image& latLong) : mTexels(6 * kFaceSize * kFaceSize) {
        for (int face = 0; face < 6; ++face)
            for (int y = 0; y < kFaceSize; ++y)
                for (int x = 0; x < kFaceSize; ++x) {
                    const glm::vec2 uv = latLongUv(direction(face, (float(x) + 0.5f) / float(kFaceSize) * 2.0f - 1.0f,
                                                             (float(y) + 0.5f) / float(kFaceSize) * 2.0f - 1.0f));
                    const int u = std::clamp(int(uv.x * float(latLong.width)), 0, latLong.width - 1);
                    const int v = std::clamp(int(uv.y * float(latLong.height)), 0, latLong.height - 1);
                    mTexels[size_t((face * kFaceSize + y) * kFaceSize + x)] = relativeLuminance(glm::vec3(latLong.at(u, v)));
                }
    }

    float at(const glm::vec3& d) const {
        const glm::vec3 a = glm::abs(d);
        int face;
        float s, t;
        if (a.x >= a.y && a.x >= a.z) {
            face = d.x > 0.0f ? 0 : 1;
            s = d.z / a.x;
            t = d.y / a.x;
        } else if (a.y >= a.z) {
            face = d.y > 0.0f ? 2 : 3;
            s = d.x / a.y;
            t = d.z / a.y;
        } else {
            face = d.z > 0.0f ? 4 : 5;
            s = d.x / a.z;
            t = d.y / a.z;
        }
        const int x = std::clamp(int((s * 0.5f + 0.5f) * kFaceSize), 0, kFaceSize - 1);
        const int y = std::clamp(int((t * 0.5f + 0.5f) * kFaceSize), 0, kFaceSize - 1);
        return mTexels[size_t((face * kFaceSize + y) * kFaceSize + x)];
    }

private:
    // The inverse of at()'s face and (s, t) in [-1, 1]^2.
    static glm::vec3 direction(int face, float s, float t) {
        switch (face) {
            case 0: return glm::normalize(glm::vec3(1.0f, t, s));
            case 1: return glm::normalize(glm::vec3(-1.0f, t, s));
            case 2: return glm::normalize(glm::vec3(s, 1.0f, t));
            case 3: return glm::normalize(glm::vec3(s, -1.0f, t));
            case 4: return glm::normalize(glm::vec3(s, t, 1.0f));
            default: return glm::normalize(glm::vec3(s, t, -1.0f));
        }
    }

    std::vector<float> mTexels;
};

// fillBuriedFromNeighbours on `stride` floats per vertex.
void fillFromNeighbours(const MeshData& mesh, const std::vector<uint8_t>& buried, size_t stride, float* values) {
    if (buried.size() != mesh.vertices.size()) return;
    std::vector<uint8_t> known(buried.size());
    size_t unknown = 0;
    for (size_t v = 0; v < buried.size(); ++v) {
        known[v] = buried[v] ? 0 : 1;
        unknown += buried[v] ? 1 : 0;
    }
    if (unknown == 0) return;
    std::vector<float> sum(mesh.vertices.size() * stride);
    std::vector<uint32_t> count(mesh.vertices.size());
    while (unknown > 0) {
        std::fill(sum.begin(), sum.end(), 0.0f);
        std::fill(count.begin(), count.end(), 0u);
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) {
                    const uint32_t to = mesh.indices[t + size_t(a)], from = mesh.indices[t + size_t(b)];
                    if (known[to] || !known[from]) continue;
                    for (size_t k = 0; k < stride; ++k) sum[to * stride + k] += values[from * stride + k];
                    ++count[to];
                }
        size_t filled = 0;
        for (size_t v = 0; v < known.size(); ++v) {
            if (known[v] || count[v] == 0) continue;
            for (size_t k = 0; k < stride; ++k) values[v * stride + k] = sum[v * stride + k] / float(count[v]);
            known[v] = 1;
            ++filled;
        }
        if (filled == 0) break;  // the rest has no path to the outside
        unknown -= filled;
    }
}

// The mesh's triangles and where the rays of its vertices start and stop.
struct VertexTracer {
    raytrace::EmbreeBvh bvh;
    float offset = 0.0f;  // off the surface along the normal
    float tMax = 0.0f;    // beyond every occluder

    static VertexTracer build(const MeshData& mesh) {
        std::vector<glm::vec3> corners;
        corners.reserve(mesh.indices.size());
        for (uint32_t index : mesh.indices) corners.push_back(mesh.vertices[index].position);
        const float diagonal = glm::length(mesh.bounds().size());
        const float offset = kRayOffsetPerDiagonal * diagonal;
        return {raytrace::EmbreeBvh::build(corners), offset, 2.0f * diagonal + offset};
    }
};

}  // namespace

void fillBuriedFromNeighbours(const MeshData& mesh, const std::vector<uint8_t>& buried, std::vector<ShScalar9>& values) {
    if (values.size() != mesh.vertices.size()) return;
    fillFromNeighbours(mesh, buried, std::tuple_size<ShScalar9>::value, values.empty() ? nullptr : values[0].data());
}

Result<std::vector<uint8_t>> findBuriedVertices(const MeshData& mesh, int raysPerVertex) {
    const int strataPerSide = int(std::lround(std::sqrt(double(std::max(raysPerVertex, 0)))));
    if (Status valid = checkInputs(mesh, raysPerVertex, strataPerSide); !valid) return valid.error();
    const VertexTracer tracer = VertexTracer::build(mesh);
    std::vector<uint8_t> buried(mesh.vertices.size(), 0u);
    raytrace::parallelFor(mesh.vertices.size(), 0, [&](size_t vertexIndex) {
        glm::vec3 normal;
        if (!unitNormal(mesh.vertices[vertexIndex], normal)) return;
        const glm::vec3 origin = mesh.vertices[vertexIndex].position + tracer.offset * normal;
        int insideHits = 0;
        forEachTransferRay(vertexIndex, normal, strataPerSide, [&](int, const glm::vec3& direction) {
            raytrace::BvhHit hit;
            if (tracer.bvh.closestHit(raytrace::Ray{origin, direction}, 0.0f, tracer.tMax, &hit) && hit.backFace) ++insideHits;
        });
        buried[vertexIndex] = 2 * insideHits > raysPerVertex ? 1 : 0;
    });
    return buried;
}

Result<ShTransfer> computeShTransfer(const MeshData& mesh, const ShTransferOptions& options) {
    const int strataPerSide = int(std::lround(std::sqrt(double(std::max(options.raysPerVertex, 0)))));
    if (Status valid = checkInputs(mesh, options.raysPerVertex, strataPerSide); !valid) return valid.error();

    const VertexTracer tracer = VertexTracer::build(mesh);
    const float weightPerRay = kPi / float(options.raysPerVertex);

    ShTransfer out;
    out.raysPerVertex = options.raysPerVertex;
    out.perVertex.assign(mesh.vertices.size(), ShScalar9{});
    const size_t words = visibilityWords(options.raysPerVertex);
    out.visibility.assign(mesh.vertices.size() * words, 0u);
    out.buried.assign(mesh.vertices.size(), 0u);
    const std::string label = options.progressLabel.empty()
                                  ? std::string()
                                  : options.progressLabel + " " + std::to_string(mesh.vertices.size()) + " vertices";
    raytrace::parallelFor(
        mesh.vertices.size(), options.threads,
        [&](size_t vertexIndex) {
            const Vertex& vertex = mesh.vertices[vertexIndex];
            glm::vec3 normal;
            if (!unitNormal(vertex, normal)) return;
            const glm::vec3 origin = vertex.position + tracer.offset * normal;
            uint32_t* escaped = out.visibility.data() + vertexIndex * words;
            ShScalar9 sum{};
            int insideHits = 0;
            forEachTransferRay(vertexIndex, normal, strataPerSide, [&](int i, const glm::vec3& direction) {
                raytrace::BvhHit hit;
                if (tracer.bvh.closestHit(raytrace::Ray{origin, direction}, 0.0f, tracer.tMax, &hit)) {
                    if (hit.backFace) ++insideHits;  // counter-clockwise triangles face out
                    return;
                }
                escaped[i / 32] |= 1u << (i % 32);
                const ShScalar9 basis = shBasis(direction);
                for (size_t k = 0; k < basis.size(); ++k) sum[k] += basis[k];
            });
            for (size_t i = 0; i < sum.size(); ++i) out.perVertex[vertexIndex][i] = sum[i] * weightPerRay;
            out.buried[vertexIndex] = 2 * insideHits > options.raysPerVertex ? 1 : 0;
        },
        label);
    fillBuriedFromNeighbours(mesh, out.buried, out.perVertex);
    return out;
}

std::vector<ShScalar9> visibleShareTransfer(const MeshData& mesh, const ShTransfer& transfer, const Image& lit,
                                            const glm::mat3& mapFromObject, const std::vector<HotDirection>& hot) {
    const size_t words = visibilityWords(transfer.raysPerVertex);
    if (transfer.visibility.size() != mesh.vertices.size() * words || lit.empty()) return transfer.perVertex;
    const int strataPerSide = int(std::lround(std::sqrt(double(transfer.raysPerVertex))));
    // A_l of the clamped cosine (Ramamoorthi & Hanrahan 2001), per coefficient.
    constexpr float kBand1 = 2.0f * kPi / 3.0f;
    constexpr float kBand2 = kPi / 4.0f;
    const float clampedCosine[9] = {kPi, kBand1, kBand1, kBand1, kBand2, kBand2, kBand2, kBand2, kBand2};
    const LuminanceCube luminance(lit);
    // The hot directions in object space (mapFromObject is a rotation).
    std::vector<glm::vec3> hotObject;
    for (const HotDirection& h : hot) hotObject.push_back(glm::transpose(mapFromObject) * h.directionMap);
    const float coneCosine = std::cos(kHotVisibilityConeDeg * kPi / 180.0f);
    // Each cosine-weighted ray stands for pi / n of the irradiance of a unit radiance.
    const double rayWeight = double(kPi) / double(transfer.raysPerVertex);
    std::vector<float> shares(mesh.vertices.size(), 0.0f);
    raytrace::parallelFor(mesh.vertices.size(), 0, [&](size_t vertexIndex) {
        glm::vec3 normal;
        if (!unitNormal(mesh.vertices[vertexIndex], normal)) return;
        const uint32_t* escaped = transfer.visibility.data() + vertexIndex * words;
        double visible = 0.0;
        double all = 0.0;
        thread_local std::vector<glm::vec3> rays;  // the vertex's rays, kept for the hot directions; reused, not reallocated
        rays.clear();
        forEachTransferRay(vertexIndex, normal, strataPerSide, [&](int i, const glm::vec3& direction) {
            const double radiance = luminance.at(mapFromObject * direction);
            all += radiance;
            if (escaped[i / 32] & (1u << (i % 32))) visible += radiance;
            if (!hot.empty()) rays.push_back(direction);
        });
        visible *= rayWeight;
        all *= rayWeight;
        for (size_t h = 0; h < hot.size(); ++h) {
            const float cosine = glm::dot(normal, hotObject[h]);
            if (!(cosine > 0.0f)) continue;
            double escapedWeight = 0.0, weight = 0.0;
            float nearest = -2.0f;
            bool nearestEscaped = false;
            for (size_t i = 0; i < rays.size(); ++i) {
                const float closeness = glm::dot(rays[i], hotObject[h]);
                const bool rayEscaped = (escaped[i / 32] & (1u << (i % 32))) != 0;
                if (closeness > nearest) {
                    nearest = closeness;
                    nearestEscaped = rayEscaped;
                }
                if (closeness <= coneCosine) continue;
                weight += closeness - coneCosine;
                if (rayEscaped) escapedWeight += closeness - coneCosine;
            }
            const double visibility = weight > 0.0 ? escapedWeight / weight : (nearestEscaped ? 1.0 : 0.0);
            const double light = double(hot[h].power) * double(cosine);
            all += light;
            visible += light * visibility;
        }
        shares[vertexIndex] = all > 0.0 ? float(visible / all) : 0.0f;
    });
    fillFromNeighbours(mesh, transfer.buried, 1, shares.data());
    std::vector<ShScalar9> out(mesh.vertices.size(), ShScalar9{});
    for (size_t vertexIndex = 0; vertexIndex < mesh.vertices.size(); ++vertexIndex) {
        glm::vec3 normal;
        if (!unitNormal(mesh.vertices[vertexIndex], normal)) continue;
        const ShScalar9 basis = shBasis(normal);
        for (size_t k = 0; k < basis.size(); ++k) out[vertexIndex][k] = shares[vertexIndex] * clampedCosine[k] * basis[k];
    }
    return out;
}

ShareLight shareLightOf(const Image& lit, int width) {
    const int height = width / 2;
    const Image smoothFull = smoothPartOfLatLong(lit);
    Image hotFull = lit;
    for (size_t i = 0; i < hotFull.texels.size(); ++i)
        hotFull.texels[i] = glm::vec4(glm::vec3(lit.texels[i]) - glm::vec3(smoothFull.texels[i]), lit.texels[i].a);
    ShareLight out;
    out.smooth = resampleLatLongByArea(smoothFull, width, height);
    const Image hotMap = resampleLatLongByArea(hotFull, width, height);
    struct Texel {
        int u, v;
        float power;
    };
    std::vector<Texel> hotTexels;
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u) {
            const float power = relativeLuminance(glm::vec3(hotMap.at(u, v))) * latLongTexelSolidAngle(v, width, height);
            if (power > 0.0f) hotTexels.push_back({u, v, power});
        }
    std::sort(hotTexels.begin(), hotTexels.end(), [](const Texel& a, const Texel& b) { return a.power > b.power; });
    for (size_t i = 0; i < hotTexels.size(); ++i) {
        const Texel& t = hotTexels[i];
        if (i < size_t(kMaxHotDirections)) {
            out.hot.push_back({latLongDirection(t.u, t.v, width, height), t.power});
        } else {
            glm::vec4& into = out.smooth.at(t.u, t.v);  // beyond the brightest: read by the rays, as before
            into = glm::vec4(glm::vec3(into) + glm::vec3(hotMap.at(t.u, t.v)), into.a);
        }
    }
    return out;
}

ShScalar9 rotateTransfer(const ShScalar9& transfer, const glm::mat3& rotation) {
    return applyShRotation(makeShRotation(rotation), transfer);
}

glm::mat3 skinningRotation(const glm::mat4& blendedSkinningMatrix) {
    // Quadratic convergence: from a blend of rotations up to ~150 degrees
    // apart, a few iterations reach float precision; 20 is a safe cap.
    constexpr int kMaxIterations = 20;
    constexpr float kConverged = 1e-7f;
    glm::mat3 x(blendedSkinningMatrix);
    if (!(std::abs(glm::determinant(x)) > 0.0f)) return glm::mat3(1.0f);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const glm::mat3 next = 0.5f * (x + glm::transpose(glm::inverse(x)));
        float change = 0.0f;
        for (int c = 0; c < 3; ++c) change = std::max(change, glm::length(next[c] - x[c]));
        x = next;
        if (change < kConverged) break;
    }
    return x;
}

}  // namespace dermis
