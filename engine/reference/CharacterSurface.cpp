#include "reference/CharacterSurface.h"

#include "reference/TextureSampling.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace dermis::reference {
namespace {

// normalize() with a fallback for a zero vector (shaders/include/Common.glsl safeNormalize).
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float lengthSquared = glm::dot(v, v);
    return lengthSquared > 1e-8f ? v / std::sqrt(lengthSquared) : fallback;
}

}  // namespace

Result<CharacterSurface> CharacterSurface::create(const Character& character, Model model, uint32_t firstTracedTriangle) {
    const MeshData& mesh = model.mesh;
    if (mesh.indices.size() % 3 != 0) return makeError("character '" + character.name + "'", "index count is not a multiple of 3");
    for (uint32_t index : mesh.indices) {
        if (index >= mesh.vertices.size()) {
            return makeError("character '" + character.name + "'", "mesh index out of range");
        }
    }
    CharacterSurface surface;
    surface.mName = character.name;
    surface.mFirstTracedTriangle = firstTracedTriangle;
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
        surface.mRawUvs.push_back(v.uv);
    }
    surface.mIndices = mesh.indices;
    for (const glm::vec4& colour : model.colours) surface.mColours.push_back(glm::vec3(colour));
    for (size_t m = 0; m < model.materials.size(); ++m) {
        ModelMaterial& source = model.materials[m];
        const Material& scene = characterMaterial(character, source.name, m);
        SurfaceMaterial material;
        material.albedoMap = MipPyramid(decodeToLinear(source.albedoMap), source.albedoWrap);
        material.normalMap = MipPyramid(std::move(source.normalMap), source.normalWrap);
        material.scatterMap = MipPyramid(std::move(source.scatterMap), source.scatterWrap);
        material.albedoTint = scene.albedo * glm::vec3(source.baseColourFactor);
        material.roughness = scene.roughness;
        material.rhoS = scene.rhoS;
        const bool decided = !source.profile.empty();  // else a model made without the loader: the scene decides
        const std::string profile = decided ? source.profile : scene.profile;
        material.scatter = profile == kOpaqueProfile ? 0.0f : decided ? source.scatter : scene.scatter;
        material.scattering = {profile, scene.widthScale};
        surface.mMaterials.push_back(std::move(material));
    }
    surface.mTriangleMaterials.assign(surface.triangleCount(), 0);
    for (const Submesh& submesh : model.drawRanges()) {
        for (uint32_t i = submesh.firstIndex / 3; i < (submesh.firstIndex + submesh.indexCount) / 3; ++i)
            if (i < surface.mTriangleMaterials.size()) surface.mTriangleMaterials[i] = static_cast<uint32_t>(submesh.material);
    }
    return surface;
}

glm::vec3 CharacterSurface::positionAt(size_t triangle, float b1, float b2) const {
    const glm::vec3 p0 = corner(triangle, 0);
    return p0 + b1 * (corner(triangle, 1) - p0) + b2 * (corner(triangle, 2) - p0);
}

glm::vec2 CharacterSurface::mapUvAt(size_t triangle, float b1, float b2) const {
    const glm::vec2& uv0 = mUvs[mIndices[3 * triangle]];
    return uv0 + b1 * (mUvs[mIndices[3 * triangle + 1]] - uv0) + b2 * (mUvs[mIndices[3 * triangle + 2]] - uv0);
}

glm::vec2 CharacterSurface::rawUvAt(size_t triangle, float b1, float b2) const {
    const glm::vec2& uv0 = mRawUvs[mIndices[3 * triangle]];
    return uv0 + b1 * (mRawUvs[mIndices[3 * triangle + 1]] - uv0) + b2 * (mRawUvs[mIndices[3 * triangle + 2]] - uv0);
}

glm::vec2 CharacterSurface::mapUvAtPlanePoint(size_t triangle, const glm::vec3& pointM) const {
    // Weights from the Gram matrix of the two edges (exact for points in the plane).
    const glm::vec3 p0 = corner(triangle, 0);
    const glm::dvec3 e1(corner(triangle, 1) - p0), e2(corner(triangle, 2) - p0), d(pointM - p0);
    const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
    const double r1 = glm::dot(d, e1), r2 = glm::dot(d, e2);
    const double determinant = a * c - b * b;
    if (!(determinant > 0.0)) return mapUvAt(triangle, 0.0f, 0.0f);
    const double b1 = (c * r1 - b * r2) / determinant;
    const double b2 = (a * r2 - b * r1) / determinant;
    return mapUvAt(triangle, float(b1), float(b2));
}

glm::vec3 CharacterSurface::smoothSurfacePoint(const glm::vec3& pointM, const glm::vec3& weights,
                                               const glm::uvec3& corners, bool backFacing) const {
    // Hanika 2021, "Hacking the shadow terminator": project the point onto each
    // corner's tangent plane where it lies below it, and interpolate the
    // projections with the barycentric weights. Points above every plane stay.
    glm::vec3 lifted(0.0f);
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 cornerM = mPositionsM[corners[k]];
        glm::vec3 normal = safeNormalize(mNormals[corners[k]], glm::vec3(0.0f));
        if (backFacing) normal = -normal;
        const float height = std::min(0.0f, glm::dot(pointM - cornerM, normal));
        lifted += weights[k] * (pointM - height * normal);
    }
    return lifted;
}

SurfacePoint CharacterSurface::pointAt(size_t triangle, float b1, float b2, bool backFacing,
                                       const MapFootprint* footprint) const {
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
    auto read = [&](const MipPyramid& map, const glm::vec4& fallback) {
        return footprint ? map.sample(uv, *footprint, fallback) : map.sample(uv, fallback);
    };

    glm::vec3 n = safeNormalize(b0 * mNormals[i0] + b1 * mNormals[i1] + b2 * mNormals[i2], point.geometricNormal);
    if (backFacing) n = -n;
    point.smoothNormal = n;
    point.rayLiftM = smoothSurfacePoint(point.positionM, {b0, b1, b2}, {i0, i1, i2}, backFacing) - point.positionM;
    point.tracedTriangle = mFirstTracedTriangle + static_cast<uint32_t>(triangle);
    const SurfaceMaterial& material = mMaterials[mTriangleMaterials[triangle]];
    if (!material.normalMap.empty()) {
        const glm::vec4 tangent = b0 * mTangents[i0] + b1 * mTangents[i1] + b2 * mTangents[i2];
        glm::vec3 t = glm::vec3(tangent) - n * glm::dot(n, glm::vec3(tangent));
        const glm::vec3 fallbackTangent = std::fabs(n.x) < 0.9f ? glm::normalize(glm::cross(n, glm::vec3(1, 0, 0)))
                                                                : glm::normalize(glm::cross(n, glm::vec3(0, 1, 0)));
        t = safeNormalize(t, fallbackTangent);
        const glm::vec3 b = glm::cross(n, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
        const glm::vec3 tangentNormal = glm::vec3(read(material.normalMap, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f))) * 2.0f - 1.0f;
        n = safeNormalize(glm::mat3(t, b, n) * tangentNormal, n);
    }
    point.shadingNormal = n;
    const glm::vec3 map = glm::vec3(read(material.albedoMap, glm::vec4(1.0f)));
    const glm::vec3 colour =
        mColours.empty() ? glm::vec3(1.0f) : b0 * mColours[i0] + b1 * mColours[i1] + b2 * mColours[i2];
    point.albedo = glm::clamp(material.albedoTint * map * colour, 0.0f, 1.0f);
    point.roughness = material.roughness;
    point.rhoS = material.rhoS;
    point.scatter = material.scatter;
    if (!material.scatterMap.empty()) point.scatter *= read(material.scatterMap, glm::vec4(1.0f)).r;
    point.scatter = glm::clamp(point.scatter, 0.0f, 1.0f);
    return point;
}

double CharacterSurface::areaM2() const {
    double area = 0.0;
    for (size_t t = 0; t < triangleCount(); ++t) {
        area += 0.5 * double(glm::length(glm::cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0))));
    }
    return area;
}

void CharacterSurface::hashContent(ContentHash& hash) const {
    hash.text(mName).number(mFirstTracedTriangle).values(mPositionsM).values(mNormals).values(mTangents).values(mUvs).values(mRawUvs);
    hash.values(mColours).values(mIndices).values(mTriangleMaterials);
    auto hashMap = [&](const MipPyramid& map) {
        if (map.empty()) {
            hash.number(0);
            return;
        }
        hash.image(map.level(0));  // the other levels follow from it
        const int wraps[] = {int(map.wraps().s), int(map.wraps().t)};
        hash.bytes(wraps, sizeof wraps);
    };
    for (const SurfaceMaterial& m : mMaterials) {
        hashMap(m.albedoMap);
        hashMap(m.normalMap);
        hashMap(m.scatterMap);
        const float factors[] = {m.albedoTint.r, m.albedoTint.g, m.albedoTint.b, m.roughness, m.rhoS, m.scatter,
                                 m.scattering.widthScale};
        hash.bytes(factors, sizeof factors).text(m.scattering.profile);
    }
}

}  // namespace dermis::reference
