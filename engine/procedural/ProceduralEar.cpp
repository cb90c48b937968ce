#include "procedural/ProceduralEar.h"

#include "procedural/ProceduralGrid.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

using glm::vec2;
using glm::vec3;

// The right ear's plate: its centre, how far it leans back from vertical, and
// the angle its plane makes with the side of the head.
const vec3 kCentreM{0.087f, 0.002f, -0.016f};
constexpr float kLeanBack = 0.25f;     // tan of the lean
constexpr float kFlareRad = 0.524f;    // 30 degrees out from the head's side
constexpr float kHalfHeightM = 0.031f;
constexpr float kBackHalfWidthM = 0.018f;   // centre to the free rim
constexpr float kFrontHalfWidthM = 0.026f;  // centre to the buried root
constexpr float kTopWidening = 0.12f;       // the top is wider than the lobe
constexpr float kThicknessM = 0.0026f;
constexpr float kRootThickeningM = 0.008f;
constexpr float kRimRoll = 0.8f;            // extra thickness of the rolled rim, relative
constexpr float kConchaDepthM = 0.005f;
constexpr float kAntihelixM = 0.0015f;
constexpr float kRimCurlM = 0.002f;
constexpr float kCupM = 0.003f;
constexpr float kRootBendM = 0.012f;  // the front curves in to meet the head

constexpr int kFaceRows = 16;      // centre to rim, per face
constexpr int kFaceColumns = 64;   // around

struct Frame {
    vec3 centre, out, up, normal;  // out: toward the free rim; normal: the outer face's side
};

Frame frameFor(float side) {
    Frame f;
    f.up = glm::normalize(vec3(0.0f, 1.0f, -kLeanBack));
    const vec3 out(std::sin(kFlareRad), 0.0f, -std::cos(kFlareRad));
    f.out = glm::normalize(out - f.up * glm::dot(f.up, out));
    f.normal = glm::cross(f.out, f.up);
    f.centre = kCentreM;
    const vec3 mirror(side, 1.0f, 1.0f);
    f.centre *= mirror;
    f.out *= mirror;
    f.up *= mirror;
    f.normal *= mirror;
    return f;
}

float smoothStep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float halfWidthM(float cosAround) { return glm::mix(kFrontHalfWidthM, kBackHalfWidthM, smoothStep(-0.35f, 0.35f, cosAround)); }

// The ear in its plane's coordinates: (a along out, b along up, w along the
// normal). `polar` runs from the outer face's centre (0) through the rim
// (pi/2) to the inner face's centre (pi); `around` turns from out toward up.
// sinPolar and cosPolar are passed in so that the centres can be exact.
vec3 earLocal(float sinPolar, float cosPolar, float around) {
    const float c = std::cos(around);
    const float s = std::sin(around);
    const float halfWidth = halfWidthM(c);
    const float a = sinPolar * halfWidth * c * (1.0f + kTopWidening * s);
    const float b = sinPolar * kHalfHeightM * s;

    const float root = smoothStep(-0.3f * kFrontHalfWidthM, -0.9f * kFrontHalfWidthM, a);
    const float rim = kRimRoll * std::exp(-(sinPolar - 0.86f) * (sinPolar - 0.86f) / (0.08f * 0.08f));
    const float thickness = kThicknessM * (1.0f + rim * (1.0f - root)) + kRootThickeningM * root;

    const float conchaA = (a + 0.006f) / 0.009f;
    const float conchaB = (b + 0.004f) / 0.013f;
    float bend = -kConchaDepthM * std::exp(-(conchaA * conchaA + conchaB * conchaB));
    // The free rim curls toward the outer side, and the plate cups forward.
    const float freeRim = std::max(smoothStep(-0.3f, 0.5f, c), smoothStep(0.3f, 0.9f, s));
    bend += kRimCurlM * freeRim * smoothStep(0.75f, 1.0f, sinPolar);
    const float ridge = (sinPolar - 0.62f) / 0.1f;
    bend += kAntihelixM * freeRim * std::exp(-ridge * ridge);
    const float backward = std::max(a, 0.0f) / kBackHalfWidthM;
    bend += kCupM * backward * backward;
    const float forward = std::max(-a, 0.0f) / kFrontHalfWidthM;
    bend -= kRootBendM * forward * forward;

    return vec3(a, b, bend + 0.5f * thickness * cosPolar);
}

vec3 toWorld(const Frame& f, const vec3& local) { return f.centre + local.x * f.out + local.y * f.up + local.z * f.normal; }

vec3 earPoint(const Frame& f, float polar, float around) {
    return toWorld(f, earLocal(std::sin(polar), std::cos(polar), around));
}

// Outward normal from the parametric derivatives; `turn` is +1 or -1, the way
// `around` turns with the grid's columns (so the winding stays outward).
vec3 earNormal(const Frame& f, float polar, float around, float turn) {
    constexpr float kStep = 1e-3f;
    const auto at = [&](float p, float a) {
        const vec3 dPolar = earPoint(f, p + kStep, a) - earPoint(f, p - kStep, a);
        const vec3 dAround = turn * (earPoint(f, p, a + kStep) - earPoint(f, p, a - kStep));
        return glm::cross(dPolar, dAround);
    };
    if (std::sin(polar) > 1e-3f) return glm::normalize(at(polar, around));
    // At a face's centre the ring has collapsed: average the normals around it.
    const float nearPolar = polar < 1.0f ? 0.05f : glm::pi<float>() - 0.05f;
    vec3 sum(0.0f);
    for (int i = 0; i < 16; ++i) sum += glm::normalize(at(nearPolar, glm::two_pi<float>() * static_cast<float>(i) / 16.0f));
    return glm::normalize(sum);
}

}  // namespace

glm::vec2 earChartSizeM() {
    const float width = (1.0f + kTopWidening) * (kFrontHalfWidthM + kBackHalfWidthM);
    return {width, 2.0f * kHalfHeightM};
}

void appendEar(MeshData& mesh, float side, const glm::vec2& outerChartUv, const glm::vec2& innerChartUv, float uvPerM) {
    const Frame frame = frameFor(side);
    const float aFront = (1.0f + kTopWidening) * kFrontHalfWidthM;
    const float aBack = (1.0f + kTopWidening) * kBackHalfWidthM;
    // The left ear is the mirror image: its `around` turns the other way, so
    // that the triangles still wind outward.
    const float turn = side;

    for (int face = 0; face < 2; ++face) {
        const bool outer = face == 0;
        const vec2 chart = outer ? outerChartUv : innerChartUv;
        // Seen from outside the face, image-right is +out on the right ear's
        // outer face, and flips with the face and with the side.
        const float rightward = outer ? side : -side;
        appendGrid(mesh, kFaceColumns, kFaceRows, [&](int column, int row) {
            const float polar = glm::half_pi<float>() * (static_cast<float>(row) / kFaceRows + (outer ? 0.0f : 1.0f));
            // The last column repeats the first exactly, so the seam closes.
            const float around = turn * glm::two_pi<float>() * static_cast<float>(column % kFaceColumns) / kFaceColumns;
            const bool centre = (outer && row == 0) || (!outer && row == kFaceRows);
            const float sinPolar = centre ? 0.0f : std::sin(polar);
            const float cosPolar = centre ? (outer ? 1.0f : -1.0f) : std::cos(polar);
            const vec3 local = earLocal(sinPolar, cosPolar, around);

            Vertex v;
            v.position = toWorld(frame, local);
            v.normal = earNormal(frame, polar, around, turn);
            const float u = rightward > 0.0f ? local.x + aFront : aBack - local.x;
            v.uv = chart + uvPerM * vec2(u, kHalfHeightM - local.y);
            return v;
        });
    }
}

}  // namespace dermis
