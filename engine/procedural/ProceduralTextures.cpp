#include "procedural/ProceduralTextures.h"

#include "mesh/UvBake.h"
#include "procedural/ProceduralHeadShape.h"
#include "procedural/ProceduralNoise.h"

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

using glm::vec3;

constexpr uint8_t kSkullPart = 0;
constexpr uint8_t kEarPart = 1;
// Gutter filling reaches 8 texels at 1024, as far as the charts' gutters.
constexpr int kGutterRingsPer1024 = 8;

// Linear-light skin colours; the map stores them sRGB-encoded.
const vec3 kBaseSkin{0.60f, 0.39f, 0.30f};
const vec3 kFlushTint{1.0f, 0.78f, 0.82f};   // multiplies the base where blood shows
const vec3 kLipColour{0.44f, 0.19f, 0.17f};
const vec3 kBrowColour{0.085f, 0.050f, 0.034f};
const vec3 kLashColour{0.05f, 0.03f, 0.024f};
const vec3 kStubbleTint{0.80f, 0.79f, 0.84f};

float smoothStep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// The share of a feature of the given size that texels of the given
// footprint can hold without aliasing: all of it up to a third of the size,
// none from two thirds. Stretched parts of a chart lose the fine detail
// instead of turning it into streaks.
float resolvable(float featureM, float footprintM) { return smoothStep(0.7f, 0.35f, footprintM / featureM); }

// Value noise faded toward its mean where the texels cannot hold it.
float bandLimitedValueNoise(const vec3& p, float frequencyPerM, float footprintM, uint32_t seed) {
    const float keep = resolvable(1.0f / frequencyPerM, footprintM);
    return keep > 0.0f ? 0.5f + keep * (valueNoise(p * frequencyPerM, seed) - 0.5f) : 0.5f;
}

float gaussian(const vec3& p, const vec3& centre, float sigmaM) {
    const vec3 d = p - centre;
    return std::exp(-glm::dot(d, d) / (2.0f * sigmaM * sigmaM));
}

float encodeSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

glm::vec4 encodeSrgb(const vec3& linear) {
    return {encodeSrgb(linear.x), encodeSrgb(linear.y), encodeSrgb(linear.z), 1.0f};
}

std::vector<uint8_t> partOfTriangle(const HeadMesh& head) {
    std::vector<uint8_t> part(head.mesh.triangleCount(), kEarPart);
    std::fill(part.begin(), part.begin() + static_cast<long>(head.skullTriangleCount), kSkullPart);
    return part;
}

float lipsWeight(const vec3& p) {
    const float x = p.x / head::kLipHalfWidthM;
    const float y = (p.y - head::kMouthM.y) / 0.0125f;
    return smoothStep(1.0f, 0.7f, x * x + y * y) * smoothStep(0.080f, 0.088f, p.z);
}

// How much each region shows at a surface point of the head.
struct Regions {
    float flush = 0.0f;
    float lips = 0.0f;
    float brows = 0.0f;
    float lashes = 0.0f;
    float stubble = 0.0f;
};

Regions regionsAt(const vec3& p, bool ear, float footprintM) {
    const vec3 m(std::fabs(p.x), p.y, p.z);  // mirrored onto the right side
    Regions r;
    r.flush = 0.75f * gaussian(m, head::kCheekM, 0.018f) + 0.65f * gaussian(p, head::kNoseTipM, 0.012f) +
              0.3f * gaussian(p, head::kChinM, 0.014f);
    if (ear) r.flush += 0.55f;
    r.lips = lipsWeight(p);

    // Eyebrows: arcs over the eyes, thicker toward the nose, with hair streaks.
    const float along = (m.x - head::kBrowM.x) / 0.021f;
    const float browCentreY = head::kBrowM.y - 0.004f * along * along - 0.002f * along;
    const float browHalfHeight = 0.0042f * (1.0f - 0.45f * along);
    // Streaks along the hairs: fine across them, long along them.
    const float streaks = bandLimitedValueNoise(vec3(m.x * 0.2f, m.y, m.z * 0.2f), 1500.0f, footprintM, 11u);
    r.brows = smoothStep(1.0f, 0.6f, std::fabs(along)) *
              smoothStep(1.0f, 0.45f, std::fabs(p.y - browCentreY) / browHalfHeight) *
              smoothStep(0.06f, 0.08f, p.z) * (0.55f + 0.45f * streaks);

    // The lash line of the closed eye, sagging in the middle.
    const float lidX = (m.x - head::kEyeM.x) / 0.011f;
    const float lidY = p.y - (head::kEyeM.y - 0.0035f + 0.0025f * lidX * lidX);
    r.lashes = std::exp(-lidY * lidY / (0.0006f * 0.0006f)) * smoothStep(1.0f, 0.7f, std::fabs(lidX)) *
               smoothStep(head::kEyeM.z + 0.004f, head::kEyeM.z + 0.008f, p.z);

    // Stubble: upper lip, chin and along the jaw, not on the lips or the neck.
    const float belowNose = smoothStep(-0.032f, -0.044f, p.y);
    const float aboveNeck = smoothStep(-0.125f, -0.105f, p.y);
    // Toward the back it reaches further down the jaw than up the cheeks.
    const float frontmostZ = glm::mix(0.035f, -0.005f, smoothStep(-0.05f, -0.09f, p.y));
    const float jawSide = smoothStep(frontmostZ, frontmostZ + 0.025f, p.z);
    const float speckle = bandLimitedValueNoise(p, 1200.0f, footprintM, 23u);
    r.stubble = ear ? 0.0f : belowNose * aboveNeck * jawSide * (1.0f - r.lips) * (0.5f + 0.5f * speckle);
    return r;
}

vec3 skinColour(const vec3& p, bool ear, float footprintM) {
    const Regions r = regionsAt(p, ear, footprintM);

    // Mottling: broad blotches, smaller patches and fine grain.
    const float broad = fractalNoise(p * 30.0f, 2, 2.0f, 0.5f, 3u).value;
    const float patches = valueNoise(p * 180.0f, 5u) - 0.5f;
    const float grain = bandLimitedValueNoise(p, 900.0f, footprintM, 7u) - 0.5f;
    const float blood = std::clamp(r.flush + 0.25f * broad + 0.2f * patches, 0.0f, 1.0f);

    vec3 c = kBaseSkin * (1.0f + 0.06f * broad + 0.05f * patches + 0.06f * grain);
    c *= glm::mix(vec3(1.0f), kFlushTint, blood);
    // Sparse, soft, round freckles.
    constexpr float kFreckleCellM = 0.006f;
    const float freckle = -resolvable(kFreckleCellM, footprintM) * poreNoise(p / kFreckleCellM, 0.4f, 0.35f, 13u).value;
    c *= glm::mix(vec3(1.0f), vec3(0.90f, 0.86f, 0.84f), std::min(freckle, 1.0f));

    c = glm::mix(c, kLipColour * (1.0f + 0.1f * grain), r.lips);
    c *= glm::mix(vec3(1.0f), kStubbleTint, r.stubble);
    c = glm::mix(c, kBrowColour, std::min(r.brows, 0.85f));
    c = glm::mix(c, kLashColour, 0.8f * r.lashes);
    return c;
}

// Skin relief in metres, with its gradient: pores and fine creases.
NoiseSample skinRelief(const vec3& p, bool ear, float footprintM) {
    const vec3 m(std::fabs(p.x), p.y, p.z);
    const float lips = lipsWeight(p);
    // Pores are largest on the nose and cheeks, finer on the ears, absent on
    // the lips. Only their radius and depth vary: a varying lattice scale
    // would smear them.
    const float nose = gaussian(p, head::kNoseTipM, 0.015f);
    const float cheek = gaussian(m, head::kCheekM, 0.025f);
    const float poreCellM = ear ? 0.0006f : 0.0009f;
    const float poreRadius = std::min(0.36f + 0.12f * (nose + cheek), 0.5f);
    const float poreDepthM = 0.00008f * (1.0f + 0.5f * nose) * (1.0f - lips) *
                             resolvable(2.0f * poreRadius * poreCellM, footprintM);

    NoiseSample relief;
    const NoiseSample pores = poreDepthM > 0.0f ? poreNoise(p / poreCellM, poreRadius, 0.75f, 101u) : NoiseSample{};
    relief.value += poreDepthM * pores.value;
    relief.gradient += (poreDepthM / poreCellM) * pores.gradient;

    // Creases along the zero lines of gradient noise, at two scales; lips
    // crease vertically.
    const vec3 stretch = glm::mix(vec3(1.0f), vec3(3.0f, 0.4f, 1.0f), lips);
    constexpr float kCreaseM[2] = {0.0022f, 0.0011f};
    constexpr float kCreaseDepthM[2] = {0.00005f, 0.00002f};
    for (int layer = 0; layer < 2; ++layer) {
        const vec3 scale = stretch / kCreaseM[layer];
        const NoiseSample crease = gradientNoise(p * scale, 202u + static_cast<uint32_t>(layer));
        const float depthM = kCreaseDepthM[layer] * resolvable(kCreaseM[layer], footprintM) *
                             (crease.value < 0.0f ? -1.0f : 1.0f);
        relief.value += depthM * crease.value;
        relief.gradient += depthM * crease.gradient * scale;
    }
    return relief;
}

}  // namespace

namespace {

// A map over the head's UV layout: texel(surface texel) for every covered
// texel, then the gutters filled (fillGutters) with `gutter`.
template <class TexelValue>
Image makeHeadMap(const HeadMesh& head, int size, ColourSpace colourSpace, const glm::vec4& gutter, bool gutterIsNormal,
                  TexelValue&& texel) {
    const SurfaceMap surface = rasteriseSurface(head.mesh, partOfTriangle(head), size, size);
    Image image;
    image.width = size;
    image.height = size;
    image.colourSpace = colourSpace;
    image.texels.resize(surface.texels.size());
    forEachRow(size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const size_t i = static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x);
            const SurfaceTexel& s = surface.texels[i];
            if (s.covered) image.texels[i] = texel(s);
        }
    });
    fillGutters(image, surface, kGutterRingsPer1024 * size / 1024, gutter, gutterIsNormal);
    return image;
}

}  // namespace

Image makeHeadAlbedoMap(const HeadMesh& head, int size) {
    return makeHeadMap(head, size, ColourSpace::Srgb, encodeSrgb(kBaseSkin), false, [](const SurfaceTexel& s) {
        return encodeSrgb(skinColour(s.position, s.part == kEarPart, s.footprintM));
    });
}

Image makeHeadNormalMap(const HeadMesh& head, int size) {
    return makeHeadMap(head, size, ColourSpace::Linear, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f), true, [](const SurfaceTexel& s) {
        const glm::vec3 gradient = skinRelief(s.position, s.part == kEarPart, s.footprintM).gradient;
        // The surface z = h tilts its normal by -grad h within the tangent plane.
        const vec3 slope = gradient - s.normal * glm::dot(s.normal, gradient);
        const vec3 tilted(-glm::dot(slope, s.tangent), -glm::dot(slope, s.bitangent), 1.0f);
        const vec3 n = glm::normalize(tilted);
        return glm::vec4(n * 0.5f + 0.5f, 1.0f);
    });
}

}  // namespace dermis
