#pragma once
// Embree against the in-house BVH on the CPU reference's rays (RayBenchmarks.cpp).

#include "raytrace/TriangleScene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis::bench {

// The rays of the comparison, over a shipped scene's characters:
//   occlusion  400,000 any-hit rays from points spread over the surface, cosine-
//              distributed about the face normal, unbounded (the environment's
//              visibility rays and the SH transfer's)
//   camera     the scene camera's closest-hit rays at 320x180
struct RayWorkload {
    std::vector<glm::vec3> cornersM;  // three per triangle
    std::vector<raytrace::Ray> occlusion;
    std::vector<raytrace::Ray> camera;
    float nearM = 0.0f, farM = 0.0f;
};
// False when the scene or a character cannot be loaded (the scan's content absent).
bool loadRayWorkload(const std::string& sceneName, RayWorkload* out);

// Prints the ray tracers' table (after the run).
void printRaySummary();

}  // namespace dermis::bench
