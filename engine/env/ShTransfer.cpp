#include "env/ShTransfer.h"

#include "core/Hash.h"
#include "raytrace/EmbreeBvh.h"
#include "raytrace/ParallelFor.h"
#include "raytrace/Sampling.h"

#include <cmath>

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

}  // namespace

Result<ShTransfer> computeShTransfer(const MeshData& mesh, const ShTransferOptions& options) {
    const int strataPerSide = int(std::lround(std::sqrt(double(std::max(options.raysPerVertex, 0)))));
    if (Status valid = checkInputs(mesh, options.raysPerVertex, strataPerSide); !valid) return valid.error();

    std::vector<glm::vec3> corners;
    corners.reserve(mesh.indices.size());
    for (uint32_t index : mesh.indices) corners.push_back(mesh.vertices[index].position);
    const raytrace::EmbreeBvh bvh = raytrace::EmbreeBvh::build(corners);
    const float diagonal = glm::length(mesh.bounds().size());
    const float offset = kRayOffsetPerDiagonal * diagonal;
    const float tMax = 2.0f * diagonal + offset;  // beyond every occluder
    const float weightPerRay = kPi / float(options.raysPerVertex);

    ShTransfer out;
    out.raysPerVertex = options.raysPerVertex;
    out.perVertex.assign(mesh.vertices.size(), ShScalar9{});
    const std::string label = options.progressLabel.empty()
                                  ? std::string()
                                  : options.progressLabel + " " + std::to_string(mesh.vertices.size()) + " vertices";
    raytrace::parallelFor(
        mesh.vertices.size(), options.threads,
        [&](size_t vertexIndex) {
            const Vertex& vertex = mesh.vertices[vertexIndex];
            const float normalLength = glm::length(vertex.normal);
            if (!(normalLength > 0.0f)) return;  // no direction to integrate about: no light
            const glm::vec3 normal = vertex.normal / normalLength;
            glm::vec3 tangent, bitangent;
            orthonormalBasis(normal, tangent, bitangent);
            const uint32_t seed = lowbias32(uint32_t(vertexIndex) * 0x9e3779b9U + 0x632be5abU);
            const float turn = 2.0f * kPi * raytrace::unitFloatFromHash(lowbias32(seed));
            const glm::vec3 turnedTangent = std::cos(turn) * tangent + std::sin(turn) * bitangent;
            const glm::vec3 turnedBitangent = glm::cross(normal, turnedTangent);
            const glm::vec3 origin = vertex.position + offset * normal;
            ShScalar9 sum{};
            for (const glm::vec2& square : raytrace::jitteredGrid(strataPerSide, seed)) {
                const glm::vec2 disc = raytrace::concentricDisc(square);
                const float cosine = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disc, disc)));  // Malley's method
                const glm::vec3 direction = disc.x * turnedTangent + disc.y * turnedBitangent + cosine * normal;
                if (bvh.anyHit(raytrace::Ray{origin, direction}, 0.0f, tMax)) continue;
                const ShScalar9 basis = shBasis(direction);
                for (size_t i = 0; i < basis.size(); ++i) sum[i] += basis[i];
            }
            for (size_t i = 0; i < sum.size(); ++i) out.perVertex[vertexIndex][i] = sum[i] * weightPerRay;
        },
        label);
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
