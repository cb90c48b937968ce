#include "reference/CharacterSurface.h"

#include "reference/TextureSampling.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>

namespace dermis::reference {
namespace {

// normalize() with a fallback for a zero vector (shaders/include/Common.glsl safeNormalize).
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float lengthSquared = glm::dot(v, v);
    return lengthSquared > 1e-8f ? v / std::sqrt(lengthSquared) : fallback;
}

}  // namespace

Result<CharacterSurface> CharacterSurface::create(const Character& character, Model model) {
    const MeshData& mesh = model.mesh;
    if (mesh.indices.size() % 3 != 0) return makeError("character '" + character.name + "'", "index count is not a multiple of 3");
    for (uint32_t index : mesh.indices) {
        if (index >= mesh.vertices.size()) {
            return makeError("character '" + character.name + "'", "mesh index out of range");
        }
    }
    CharacterSurface surface;
    surface.mName = character.name;
    const glm::mat4 worldFromObject = character.transform.worldFromObject(character.metresPerUnit);
    const glm::mat3 normalWorldFromObject = glm::inverseTranspose(glm::mat3(worldFromObject));
    const glm::mat3 linear(worldFromObject);
    const bool flipV = character.material.flipV;
    surface.mPositionsM.reserve(mesh.vertices.size());
    for (const Vertex& v : mesh.vertices) {
        surface.mPositionsM.push_back(glm::vec3(worldFromObject * glm::vec4(v.position, 1.0f)));
        surface.mNormals.push_back(normalWorldFromObject * v.normal);
        surface.mTangents.push_back(glm::vec4(linear * glm::vec3(v.tangent), v.tangent.w));
        surface.mUvs.push_back(flipV ? glm::vec2(v.uv.x, 1.0f - v.uv.y) : v.uv);
    }
    surface.mIndices = mesh.indices;
    surface.mAlbedoMap = decodeToLinear(model.albedoMap);
    surface.mNormalMap = std::move(model.normalMap);
    surface.mAlbedoTint = character.material.albedo;
    surface.mRoughness = character.material.roughness;
    surface.mRhoS = character.material.rhoS;
    return surface;
}

glm::vec3 CharacterSurface::positionAt(size_t triangle, float b1, float b2) const {
    const glm::vec3 p0 = corner(triangle, 0);
    return p0 + b1 * (corner(triangle, 1) - p0) + b2 * (corner(triangle, 2) - p0);
}

SurfacePoint CharacterSurface::pointAt(size_t triangle, float b1, float b2, bool backFacing) const {
    const uint32_t i0 = mIndices[3 * triangle];
    const uint32_t i1 = mIndices[3 * triangle + 1];
    const uint32_t i2 = mIndices[3 * triangle + 2];
    const float b0 = 1.0f - b1 - b2;
    SurfacePoint point;
    point.positionM = positionAt(triangle, b1, b2);  // the same rounding as every other position query
    // Not safeNormalize: a 1 mm triangle's cross product is 1e-6 m^2, far below its unit-vector threshold.
    const glm::vec3 faceNormal = glm::cross(mPositionsM[i1] - mPositionsM[i0], mPositionsM[i2] - mPositionsM[i0]);
    const float faceLength = glm::length(faceNormal);
    point.geometricNormal = faceLength > 0.0f && std::isfinite(faceLength) ? faceNormal / faceLength : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec2 uv = b0 * mUvs[i0] + b1 * mUvs[i1] + b2 * mUvs[i2];

    glm::vec3 n = safeNormalize(b0 * mNormals[i0] + b1 * mNormals[i1] + b2 * mNormals[i2], point.geometricNormal);
    if (backFacing) n = -n;
    if (!mNormalMap.empty()) {
        const glm::vec4 tangent = b0 * mTangents[i0] + b1 * mTangents[i1] + b2 * mTangents[i2];
        glm::vec3 t = glm::vec3(tangent) - n * glm::dot(n, glm::vec3(tangent));
        const glm::vec3 fallbackTangent = std::fabs(n.x) < 0.9f ? glm::normalize(glm::cross(n, glm::vec3(1, 0, 0)))
                                                                : glm::normalize(glm::cross(n, glm::vec3(0, 1, 0)));
        t = safeNormalize(t, fallbackTangent);
        const glm::vec3 b = glm::cross(n, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
        const glm::vec3 tangentNormal = glm::vec3(sampleBilinear(mNormalMap, uv, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f))) * 2.0f - 1.0f;
        n = safeNormalize(glm::mat3(t, b, n) * tangentNormal, n);
    }
    point.shadingNormal = n;
    const glm::vec3 map = glm::vec3(sampleBilinear(mAlbedoMap, uv, glm::vec4(1.0f)));
    point.albedo = glm::clamp(mAlbedoTint * map, 0.0f, 1.0f);
    point.roughness = mRoughness;
    point.rhoS = mRhoS;
    return point;
}

double CharacterSurface::areaM2() const {
    double area = 0.0;
    for (size_t t = 0; t < triangleCount(); ++t) {
        area += 0.5 * double(glm::length(glm::cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0))));
    }
    return area;
}

}  // namespace dermis::reference
