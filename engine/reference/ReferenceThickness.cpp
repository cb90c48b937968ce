// ReferenceRenderer::renderThicknessMm: how thick the part under each pixel is,
// for splitting error maps into thin and thick regions (docs/reference.md).
#include "reference/ReferenceRenderer.h"

#include "raytrace/ParallelFor.h"

namespace dermis::reference {
using raytrace::parallelFor;
}  // namespace dermis::reference

namespace dermis::reference {
namespace {

constexpr float kMmPerM = 1000.0f;
// The ray into the part ignores hits closer than this: far thinner than any skin
// part, and far above the float rounding of a hit position (~1e-7 m at 1 m).
constexpr float kThicknessStartM = 1e-5f;
// Surfaces of other characters that the ray passes before meeting its own.
constexpr int kMaxForeignHits = 64;

}  // namespace

Image ReferenceRenderer::renderThicknessMm(int width, int height) {
    const CameraRays camera(mScene.camera, width, height);
    Image image;
    image.width = width;
    image.height = height;
    image.colourSpace = ColourSpace::Linear;
    image.texels.assign(size_t(width) * size_t(height), glm::vec4(0.0f));
    parallelFor(size_t(height), mOptions.threads, [&](size_t y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = camera.through(float(x) + 0.5f, float(y) + 0.5f);
            const Hit hit = trace(ray, mScene.camera.nearM, mScene.camera.farM);
            if (hit.character < 0) continue;
            const CharacterSurface& surface = *mSurfaces[size_t(hit.character)];
            glm::vec3 normal = glm::normalize(glm::cross(surface.corner(hit.triangle, 1) - surface.corner(hit.triangle, 0),
                                                         surface.corner(hit.triangle, 2) - surface.corner(hit.triangle, 0)));
            if (glm::dot(normal, ray.direction) > 0.0f) normal = -normal;  // the viewer's side
            const Ray inwards{surface.positionAt(hit.triangle, hit.b1, hit.b2), -normal};
            float thicknessMm = kNoExitThicknessMm;
            float tMin = kThicknessStartM;
            for (int i = 0; i <= kMaxForeignHits; ++i) {
                const Hit exit = trace(inwards, tMin, std::numeric_limits<float>::infinity());
                if (exit.character < 0) break;
                if (exit.character == hit.character) {
                    const glm::vec3 q = surface.positionAt(exit.triangle, exit.b1, exit.b2);
                    thicknessMm = glm::length(q - inwards.origin) * kMmPerM;
                    break;
                }
                const CharacterSurface& other = *mSurfaces[size_t(exit.character)];
                tMin = glm::dot(other.positionAt(exit.triangle, exit.b1, exit.b2) - inwards.origin, inwards.direction) +
                       kThicknessStartM;
            }
            image.at(x, int(y)) = glm::vec4(glm::vec3(thicknessMm), 1.0f);
        }
    });
    return image;
}

}  // namespace dermis::reference
