#include "procedural/ProceduralHeadShape.h"

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

using glm::vec3;

// Approximate distance to an axis-aligned ellipsoid (exact on its surface).
float ellipsoid(const vec3& p, const vec3& radii) {
    const float k0 = glm::length(p / radii);
    const float k1 = glm::length(p / (radii * radii));
    if (k1 <= 0.0f) return -std::min(radii.x, std::min(radii.y, radii.z));
    return k0 * (k0 - 1.0f) / k1;
}

// A segment from a to b thickened by a radius that varies linearly along it.
float taperedCapsule(const vec3& p, const vec3& a, const vec3& b, float radiusA, float radiusB) {
    const vec3 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab)) - (radiusA + (radiusB - radiusA) * t);
}

float sphere(const vec3& p, const vec3& centre, float radius) { return glm::length(p - centre) - radius; }

// Polynomial smooth minimum: a union whose crease is rounded over width k.
float smoothUnion(float a, float b, float k) {
    const float h = std::max(k - std::fabs(a - b), 0.0f) / k;
    return std::min(a, b) - 0.25f * h * h * k;
}

float smoothSubtract(float a, float b, float k) { return -smoothUnion(-a, b, k); }

float smoothStep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float nose(const vec3& p, const vec3& mirrored) {
    float d = taperedCapsule(p, {0.0f, 0.022f, 0.090f}, {0.0f, -0.019f, 0.114f}, 0.0062f, 0.0085f);
    d = smoothUnion(d, sphere(p, {0.0f, -0.0235f, 0.1125f}, 0.0105f), 0.006f);
    // The wings beside the nostrils.
    d = smoothUnion(d, ellipsoid(mirrored - vec3(0.0125f, -0.0285f, 0.1015f), {0.0085f, 0.0075f, 0.009f}), 0.014f);
    return d;
}

float lips(const vec3& p) {
    // Two lips that meet in a crease: the mouth line.
    float d = ellipsoid(p - vec3(0.0f, -0.0515f, 0.0930f), {0.023f, 0.0072f, 0.0100f});
    d = smoothUnion(d, ellipsoid(p - vec3(0.0f, -0.0650f, 0.0905f), {0.020f, 0.0080f, 0.0100f}), 0.0015f);
    return d;
}

float neck(const vec3& p) {
    const float d = taperedCapsule(p, {0.0f, -0.05f, -0.016f}, {0.0f, -0.26f, -0.004f}, 0.053f, 0.056f);
    // Cut flat at the bottom, with a rounded rim.
    return -smoothUnion(-d, p.y - head::kNeckBottomM, 0.012f);
}

}  // namespace

float headSignedDistance(const glm::vec3& p) {
    const vec3 m(std::fabs(p.x), p.y, p.z);

    float d = ellipsoid(p - vec3(0.0f, 0.024f, -0.014f), {0.075f, 0.100f, 0.094f});  // cranium
    // Face and jaw, narrowing toward the chin.
    const float taper = 1.0f + 0.32f * smoothStep(0.0f, -0.12f, p.y);
    const vec3 face = (p - vec3(0.0f, -0.030f, 0.014f)) * vec3(taper, 1.0f, 1.0f);
    d = smoothUnion(d, ellipsoid(face, {0.067f, 0.084f, 0.080f}), 0.03f);
    d = smoothUnion(d, ellipsoid(m - vec3(0.050f, -0.058f, 0.000f), {0.016f, 0.030f, 0.030f}), 0.025f);  // jaw angle
    d = smoothUnion(d, ellipsoid(p - vec3(0.0f, -0.094f, 0.066f), {0.024f, 0.018f, 0.018f}), 0.025f);  // chin
    d = smoothUnion(d, ellipsoid(m - vec3(0.045f, 0.000f, 0.060f), {0.022f, 0.015f, 0.022f}), 0.025f);  // cheekbone
    d = smoothUnion(d, ellipsoid(m - vec3(0.038f, -0.032f, 0.058f), {0.024f, 0.024f, 0.024f}), 0.025f);  // cheek
    d = smoothUnion(d, ellipsoid(p - vec3(0.0f, 0.031f, 0.074f), {0.054f, 0.012f, 0.016f}), 0.025f);   // brow ridge
    d = smoothUnion(d, ellipsoid(p - vec3(0.0f, -0.056f, 0.068f), {0.030f, 0.028f, 0.024f}), 0.02f);  // muzzle
    d = smoothSubtract(d, ellipsoid(m - vec3(0.033f, 0.012f, 0.090f), {0.018f, 0.011f, 0.014f}), 0.015f);  // socket
    d = smoothUnion(d, sphere(m, head::kEyeM, 0.012f), 0.005f);  // closed lids over the eyeball
    d = smoothUnion(d, nose(p, m), 0.011f);
    d = smoothSubtract(d, ellipsoid(m - vec3(0.0068f, -0.0350f, 0.1065f), {0.0035f, 0.0025f, 0.0050f}), 0.002f);  // nostril
    d = smoothUnion(d, lips(p), 0.006f);
    d = smoothUnion(d, neck(p), 0.03f);
    return d;
}

glm::vec3 headSurfaceNormal(const glm::vec3& p) {
    constexpr float kStepM = 1e-4f;
    const vec3 gradient(headSignedDistance(p + vec3(kStepM, 0, 0)) - headSignedDistance(p - vec3(kStepM, 0, 0)),
                        headSignedDistance(p + vec3(0, kStepM, 0)) - headSignedDistance(p - vec3(0, kStepM, 0)),
                        headSignedDistance(p + vec3(0, 0, kStepM)) - headSignedDistance(p - vec3(0, 0, kStepM)));
    const float length = glm::length(gradient);
    return length > 0.0f ? gradient / length : glm::normalize(p);
}

}  // namespace dermis
