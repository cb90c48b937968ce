#pragma once
// Independent CPU rays for the wrong-image detectors (stress/Invariants.h):
// the scene's characters placed by their transforms in per-character BVHs
// (reference/Bvh.h), rays through pixel centres of the scene camera
// (reference/PixelSampling.h, the same view depth as the engine's), on a
// grid of at most kMaxRayColumns x kMaxRayRows pixels, and for each hit a
// prediction of whether it is lit, made without the engine's shaders.

#include "core/Result.h"
#include "raytrace/Bvh.h"
#include "scene/Scene.h"
#include "stress/Invariants.h"

#include <vector>

namespace dermis::stress {

constexpr int kMaxRayColumns = 64;
constexpr int kMaxRayRows = 36;

class SceneRays {
public:
    static Result<SceneRays> create(const Scene& scene);
    std::vector<RaySample> sample(int width, int height) const;

private:
    struct CharacterMesh {
        raytrace::Bvh bvh;
        std::vector<glm::vec3> cornersM;       // three per triangle
        std::vector<glm::vec3> cornerNormals;  // world space, three per triangle, not normalised
        bool predictLights = true;             // false when a normal map or a zero normal may turn N anywhere
        float rhoS = 0.0f;                     // the material's specular intensity and Beckmann m
        float roughness = 0.0f;
    };
    float diffuseLeftTowards(const CharacterMesh& m, const glm::vec3& shadingNormal, const glm::vec3& toEye) const;
    // The character whose nearest hit along the ray lies in [nearM, farM]; -1 for none.
    int nearestCharacter(const raytrace::Ray& ray, float nearM, float farM) const;
    bool ambientLights() const;
    bool lightReaches(const glm::vec3& pointM, const glm::vec3& geometricNormal, const glm::vec3& shadingNormal) const;
    bool occluded(const glm::vec3& fromM, const glm::vec3& toLight, float distanceM) const;

    const Scene* mScene = nullptr;
    std::vector<CharacterMesh> mCharacters;
};

}  // namespace dermis::stress
