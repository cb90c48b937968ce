#include "stress/InvariantRays.h"

#include "include/SharedConstants.glsl"
#include "brdf/EnergyTable.h"
#include "reference/PixelSampling.h"
#include "plan/SceneGeometry.h"
#include "render/SceneLoading.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dermis::stress {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Both normals must face the light by this much: the engine's N is the
// interpolated (and, for the head, normal-mapped) normal, which leans away
// from the geometric one by far less than the 60 degrees this allows.
constexpr float kMinNDotL = 0.5f;
// A light whose radiance x N.L is below this is not counted as lighting the
// point: with an albedo of 1/255 and an SSS blur, smaller light may round to
// zero in fp16 targets.
constexpr float kMinIrradiance = 1e-3f;
// A hit whose diffuse share towards the eye is below this is not predicted
// lit: the share multiplies the radiance, and 1e-3 of fp16-clamped light
// is still far above zero, so this only drops hits the model makes black.
constexpr float kMinDiffuseLeft = 1e-3f;
// A spot must hold the point this far inside its inner cone (degrees).
constexpr float kSpotMarginDeg = 1.0f;
// Shadow rays start this far off the surface, relative to the point's distance from the origin.
constexpr float kShadowOffset = 1e-4f;

// How far apart two view depths may be and still tie in a 24-bit depth
// buffer at depth z: one step of d = f (z - n) / (z (f - n)) is
// z^2 (f - n) / (f n 2^24); 8 steps for the interpolation's rounding, and
// 1e-5 z for the vertex transform's.
float depthToleranceM(float z, float nearM, float farM) {
    const float step = z * z * (farM - nearM) / (farM * nearM * 16777216.0f);
    return 8.0f * step + 1e-5f * z;
}

// The triangle's corners on screen in pixels from the image centre (y up);
// false when a corner is behind the camera (it is clipped, not snapped).
bool projectCorners(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::mat4& clipFromWorld,
                    int width, int height, glm::vec2 p[3]) {
    const glm::vec3 corners[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const glm::vec4 clip = clipFromWorld * glm::vec4(corners[i], 1.0f);
        if (!(clip.w > 0.0f)) return false;
        p[i] = glm::vec2(clip.x / clip.w * 0.5f * float(width), clip.y / clip.w * 0.5f * float(height));
    }
    return true;
}

// Whether the projected triangle's smallest altitude (pixels) is below `minPx`.
bool thinnerOnScreenThan(const glm::vec2 p[3], float minPx) {
    const float doubleArea = std::abs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
    const float longest = std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    return !(doubleArea >= minPx * longest);  // altitude = 2 area / longest edge
}

// Whether `sample` (same coordinates) lies within `minPx` of one of the
// projected triangle's edge lines: the rasteriser's snapping of the corners
// may move the edge across it (stress seed 5689: a character 1/5 pixel wide
// whose edge passed 0.002 pixel inside a pixel centre, which the rasteriser
// left uncovered).
bool nearerToAnEdgeThan(const glm::vec2 p[3], const glm::vec2& sample, float minPx) {
    for (int i = 0; i < 3; ++i) {
        const glm::vec2 edge = p[(i + 1) % 3] - p[i];
        const float length = glm::length(edge);
        if (!(length > 0.0f)) return true;
        const glm::vec2 offset = sample - p[i];
        if (std::abs(edge.x * offset.y - edge.y * offset.x) < minPx * length) return true;
    }
    return false;
}

}  // namespace

Result<SceneRays> SceneRays::create(const Scene& scene) {
    auto models = loadSceneModels(scene);
    if (!models.ok()) return models.error();
    SceneRays rays;
    rays.mScene = &scene;
    for (size_t c = 0; c < scene.characters.size(); ++c) {
        const Character& character = scene.characters[c];
        const MeshData& mesh = (*models)[c].mesh;
        const glm::mat4 worldFromObject = character.transform.worldFromObject(character.metresPerUnit);
        const glm::mat3 normalFromObject = glm::inverseTranspose(glm::mat3(worldFromObject));
        CharacterMesh m;
        m.predictLights = character.material.normalMap.empty();
        m.rhoS = character.material.rhoS;
        m.roughness = character.material.roughness;
        for (uint32_t index : mesh.indices) {
            if (index >= mesh.vertices.size()) return makeError("character '" + character.name + "'", "mesh index out of range");
            const Vertex& v = mesh.vertices[index];
            m.cornersM.push_back(glm::vec3(worldFromObject * glm::vec4(v.position, 1.0f)));
            m.cornerNormals.push_back(normalFromObject * v.normal);
            const float length = glm::length(v.normal);
            if (!(length > 1e-6f)) m.predictLights = false;
        }
        m.bvh = raytrace::Bvh::build(m.cornersM);
        rays.mCharacters.push_back(std::move(m));
    }
    return rays;
}

bool SceneRays::occluded(const glm::vec3& fromM, const glm::vec3& toLight, float distanceM) const {
    const raytrace::Ray ray{fromM, toLight};
    for (const CharacterMesh& m : mCharacters) {
        if (m.bvh.anyHit(ray, 0.0f, distanceM)) return true;
    }
    return false;
}

bool SceneRays::ambientLights() const {
    const RenderSettings& settings = mScene->settings;
    const float ambient = std::max(settings.ambient.r, std::max(settings.ambient.g, settings.ambient.b));
    return ambient >= kMinIrradiance && !settings.ssao.enabled;  // AO = 1 everywhere
}

// With energy conservation on, the diffuse leaving towards the eye is scaled
// by 1 - rho_s rho_dt(N.V, m) (Kelemen & Szirmay-Kalos 2001; EnergyConservation.glsl),
// which reaches 0 at grazing angles when rho_s is 1 and the lobe smooth
// (stress seed 325: a quad seen 4 degrees from edge-on, rho_s 1, m 0.05, black
// by the model, not by a fault). Where a normal map or a zero normal may turn
// N anywhere, the most grazing angle is assumed.
float SceneRays::diffuseLeftTowards(const CharacterMesh& m, const glm::vec3& shadingNormal,
                                    const glm::vec3& toEye) const {
    if (!mScene->settings.energyConservation) return 1.0f;
    const float cosine = m.predictLights ? std::clamp(glm::dot(shadingNormal, toEye), 0.0f, 1.0f) : 0.0f;
    return 1.0f - m.rhoS * rhoDt(cosine, m.roughness);
}

bool SceneRays::lightReaches(const glm::vec3& pointM, const glm::vec3& geometricNormal,
                             const glm::vec3& shadingNormal) const {
    const int count = std::min<int>(int(mScene->lights.size()), DERMIS_MAX_LIGHTS);
    int shadowed = 0;
    const glm::vec3 origin = pointM + geometricNormal * (kShadowOffset * std::max(1.0f, glm::length(pointM)));
    for (int i = 0; i < count; ++i) {
        const Light& light = mScene->lights[size_t(i)];
        const bool hasShadowMap = light.castsShadow && shadowed < DERMIS_MAX_SHADOWED_LIGHTS;
        if (hasShadowMap) ++shadowed;
        const glm::vec3 colour = light.colour * light.intensity;
        glm::vec3 L;
        float distanceM = kInfinity;
        float scale = 1.0f;
        if (light.type == LightType::Directional) {
            L = -glm::normalize(light.direction);
        } else {
            const glm::vec3 toLight = light.positionM - pointM;
            distanceM = glm::length(toLight);
            if (!(distanceM > 1e-3f)) continue;
            L = toLight / distanceM;
            scale = 1.0f / (distanceM * distanceM);
            if (light.type == LightType::Spot) {
                float coneDeg = light.spotInnerDeg - kSpotMarginDeg;
                if (!(light.spotOuterDeg > light.spotInnerDeg)) continue;  // smoothstep with equal edges is undefined
                if (hasShadowMap) coneDeg = std::min(coneDeg, 89.0f - kSpotMarginDeg);  // the map's frustum (LightSetup)
                const float cosAngle = glm::dot(-L, glm::normalize(light.direction));
                if (!(cosAngle > std::cos(glm::radians(coneDeg)))) continue;
            }
        }
        const float nDotL = std::min(glm::dot(geometricNormal, L), glm::dot(shadingNormal, L));
        if (!(nDotL > kMinNDotL)) continue;
        if (!(std::max(colour.r, std::max(colour.g, colour.b)) * scale * nDotL >= kMinIrradiance)) continue;
        if (hasShadowMap && occluded(origin, L, distanceM)) continue;
        return true;
    }
    return false;
}

int SceneRays::nearestCharacter(const raytrace::Ray& ray, float nearM, float farM) const {
    int nearest = -1;
    float nearestT = kInfinity;
    for (size_t c = 0; c < mCharacters.size(); ++c) {
        raytrace::BvhHit hit;
        if (mCharacters[c].bvh.closestHit(ray, nearM, farM, &hit) && hit.t < nearestT) {
            nearestT = hit.t;
            nearest = int(c);
        }
    }
    return nearest;
}

std::vector<RaySample> SceneRays::sample(int width, int height) const {
    const Camera& camera = mScene->camera;
    const reference::CameraRays cameraRays(camera, width, height);
    // As the engine projects (glm::lookAt + glm::perspective, PixelSampling.h).
    const glm::mat4 clipFromWorld =
        glm::perspective(glm::radians(camera.verticalFovDeg), float(width) / float(height), camera.nearM, camera.farM) *
        glm::lookAt(camera.positionM, camera.targetM, camera.up);
    const int stepX = (width + kMaxRayColumns - 1) / kMaxRayColumns;
    const int stepY = (height + kMaxRayRows - 1) / kMaxRayRows;
    // Hits this close to a clip plane may be kept or clipped by the engine.
    const float shell = 1e-3f;
    std::vector<RaySample> samples;
    for (int y = stepY / 2; y < height; y += stepY) {
        for (int x = stepX / 2; x < width; x += stepX) {
            RaySample s;
            s.x = x;
            s.y = y;
            const raytrace::Ray ray = cameraRays.through(float(x) + 0.5f, float(y) + 0.5f);
            s.characterDepthM.assign(mCharacters.size(), kInfinity);
            raytrace::BvhHit nearest;
            nearest.t = kInfinity;
            for (size_t c = 0; c < mCharacters.size(); ++c) {
                raytrace::BvhHit hit;
                if (!mCharacters[c].bvh.closestHit(ray, camera.nearM * (1.0f - shell), camera.farM * (1.0f + shell), &hit))
                    continue;
                s.characterDepthM[c] = hit.t;
                if (hit.t < nearest.t) {
                    nearest = hit;
                    s.character = int(c);
                }
            }
            if (s.character >= 0) {
                s.depthM = nearest.t;
                s.ambiguous = nearest.t < camera.nearM * (1.0f + shell) || nearest.t > camera.farM * (1.0f - shell);
                s.depthToleranceM = depthToleranceM(nearest.t, camera.nearM, camera.farM);
                const CharacterMesh& m = mCharacters[size_t(s.character)];
                const size_t t = nearest.triangle;
                glm::vec2 corners[3];
                const glm::vec2 samplePx(float(x) + 0.5f - 0.5f * float(width), 0.5f * float(height) - float(y) - 0.5f);
                if (projectCorners(m.cornersM[3 * t], m.cornersM[3 * t + 1], m.cornersM[3 * t + 2], clipFromWorld, width,
                                   height, corners) &&
                    (thinnerOnScreenThan(corners, kMinTrianglePx) ||
                     nearerToAnEdgeThan(corners, samplePx, kMinTrianglePx)))
                    s.ambiguous = true;
                const glm::vec3 p0 = m.cornersM[3 * t], p1 = m.cornersM[3 * t + 1], p2 = m.cornersM[3 * t + 2];
                glm::vec3 ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
                glm::vec3 ns = (1.0f - nearest.u - nearest.v) * m.cornerNormals[3 * t] +
                               nearest.u * m.cornerNormals[3 * t + 1] + nearest.v * m.cornerNormals[3 * t + 2];
                ns = glm::length(ns) > 1e-12f ? glm::normalize(ns) : ng;
                // The engine flips the normal on back faces (gl_FrontFacing).
                if (glm::dot(ng, ray.direction) > 0.0f) {
                    ng = -ng;
                    ns = -ns;
                }
                s.lit = ambientLights();
                if (!s.lit && m.predictLights) s.lit = lightReaches(ray.origin + ray.direction * nearest.t, ng, ns);
                if (diffuseLeftTowards(m, ns, -glm::normalize(ray.direction)) < kMinDiffuseLeft) s.lit = false;
            }
            // The same snapping decides between characters, and between a
            // character and the background: rays 1/16 pixel away from the
            // centre along each diagonal (covering every edge within 1/16
            // pixel) that see another character, or none, make the ray
            // ambiguous (seed 2044: a 1x1 frame at a 179-degree field of view,
            // whose one pixel the engine covered with a character the centre
            // ray missed).
            if (!s.ambiguous) {
                for (const glm::vec2 offset : {glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(-1, -1)}) {
                    const glm::vec2 at = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) + kMinTrianglePx * offset;
                    if (nearestCharacter(cameraRays.through(at.x, at.y), camera.nearM, camera.farM) != s.character) {
                        s.ambiguous = true;
                        break;
                    }
                }
            }
            samples.push_back(std::move(s));
        }
    }
    return samples;
}

}  // namespace dermis::stress
