#pragma once
// Where the reference looks through a pixel: the scene camera's rays
// (glm::lookAt + glm::perspective, OpenGL conventions) through points of the
// image plane, the pixel's sub-samples, and the footprint of one whole pixel on
// the surface a ray hits (for the maps' level of detail).
//
// Sub-samples: n x n strata of the pixel (n^2 = samples per pixel), one point
// in each, jittered by a hash of (pixel, stratum), so the image depends on
// nothing else (not on threads). One sample per pixel is the pixel centre, as
// the engine rasterises.

#include "raytrace/Bvh.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis::reference {
using raytrace::Bvh;
using raytrace::BvhHit;
using raytrace::Ray;
}  // namespace dermis::reference

namespace dermis::reference {

// The largest supported samples per pixel (a 16 x 16 grid).
constexpr int kMaxSamplesPerPixel = 256;

// n with n^2 == samplesPerPixel, or 0 if it is not a perfect square in [1, kMaxSamplesPerPixel].
int strataPerSide(int samplesPerPixel);

// The sub-sample offsets inside pixel (x, y), in pixels from its top-left corner, in [0, 1)^2.
std::vector<glm::vec2> subSampleOffsets(int x, int y, int samplesPerPixel);

class CameraRays {
public:
    CameraRays(const Camera& camera, int width, int height);
    // The ray through image point (px, py), in pixels from the top-left corner
    // (pixel centres at +0.5); its direction has view-space z = -1, so t is the
    // view depth in metres.
    Ray through(float px, float py) const;
    // How far a ray's direction moves for one pixel to the right, and one down.
    const glm::vec3& directionPerPixelX() const { return mDirectionPerPixelX; }
    const glm::vec3& directionPerPixelY() const { return mDirectionPerPixelY; }

private:
    glm::vec3 mOriginM{0.0f};
    glm::vec3 mTopLeftDirection{0.0f};  // through image point (0, 0)
    glm::vec3 mDirectionPerPixelX{0.0f};
    glm::vec3 mDirectionPerPixelY{0.0f};
};

// Where `ray` offset by `directionStep` meets the plane through pointM with normal
// `normal`; false when it runs parallel to the plane or meets it behind the origin.
bool offsetRayOnPlane(const Ray& ray, const glm::vec3& directionStep, const glm::vec3& pointM,
                      const glm::vec3& normal, glm::vec3* hitM);

}  // namespace dermis::reference
