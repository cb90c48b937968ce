#include "anim/Animation.h"

#include <algorithm>
#include <cmath>

namespace dermis {

float AnimationClip::durationS() const {
    float duration = 0.0f;
    for (const AnimationChannel& channel : channels)
        if (!channel.timesS.empty()) duration = std::max(duration, channel.timesS.back());
    return duration;
}

glm::quat slerpShorter(const glm::quat& a, const glm::quat& b, float s) {
    float cosine = glm::dot(a, b);
    const glm::quat target = cosine < 0.0f ? -b : b;
    cosine = std::abs(cosine);
    const float angle = std::acos(std::min(cosine, 1.0f));
    if (angle < 1e-4f) return glm::normalize(a * (1.0f - s) + target * s);
    const float sine = std::sin(angle);
    return a * (std::sin(angle * (1.0f - s)) / sine) + target * (std::sin(angle * s) / sine);
}

float clipTime(float playTimeS, float durationS, bool loop) {
    if (!(durationS > 0.0f)) return 0.0f;
    if (!loop) return std::clamp(playTimeS, 0.0f, durationS);
    const float wrapped = std::fmod(playTimeS, durationS);
    return wrapped < 0.0f ? wrapped + durationS : wrapped;
}

namespace {

// Keyframe k's value (the middle of the three groups for CUBICSPLINE).
const float* keyValue(const AnimationChannel& c, size_t k) {
    const size_t stride = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    return c.values.data() + (k * stride + (stride == 3 ? 1 : 0)) * size_t(c.components);
}

void copyKey(const AnimationChannel& c, size_t k, float* out) {
    const float* v = keyValue(c, k);
    std::copy(v, v + c.components, out);
}

void normaliseRotation(const AnimationChannel& c, float* out) {
    if (c.property != AnimatedProperty::Rotation) return;
    const float length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
    if (length > 0.0f)
        for (int i = 0; i < 4; ++i) out[i] /= length;
}

}  // namespace

void sampleChannel(const AnimationChannel& c, float timeS, float* out) {
    const size_t keys = c.timesS.size();
    if (keys == 0) return;
    if (keys == 1 || !(timeS > c.timesS.front())) return copyKey(c, 0, out);
    if (timeS >= c.timesS.back()) return copyKey(c, keys - 1, out);
    // The keyframe at or before timeS: k with t_k <= timeS < t_(k+1).
    const size_t k = size_t(std::upper_bound(c.timesS.begin(), c.timesS.end(), timeS) - c.timesS.begin()) - 1;
    const float d = c.timesS[k + 1] - c.timesS[k];
    const float s = (timeS - c.timesS[k]) / d;
    const int n = c.components;
    switch (c.interpolation) {
    case Interpolation::Step:
        return copyKey(c, k, out);
    case Interpolation::Linear: {
        const float* a = keyValue(c, k);
        const float* b = keyValue(c, k + 1);
        if (c.property == AnimatedProperty::Rotation) {
            const glm::quat q = slerpShorter(glm::quat(a[3], a[0], a[1], a[2]), glm::quat(b[3], b[0], b[1], b[2]), s);
            out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
            return;
        }
        for (int i = 0; i < n; ++i) out[i] = a[i] + (b[i] - a[i]) * s;
        return;
    }
    case Interpolation::CubicSpline: {
        const float* v0 = keyValue(c, k);
        const float* b0 = v0 + n;        // out-tangent of k
        const float* v1 = keyValue(c, k + 1);
        const float* a1 = v1 - n;        // in-tangent of k + 1
        const float s2 = s * s, s3 = s2 * s;
        const float h00 = 2.0f * s3 - 3.0f * s2 + 1.0f;
        const float h10 = d * (s3 - 2.0f * s2 + s);
        const float h01 = -2.0f * s3 + 3.0f * s2;
        const float h11 = d * (s3 - s2);
        for (int i = 0; i < n; ++i) out[i] = h00 * v0[i] + h10 * b0[i] + h01 * v1[i] + h11 * a1[i];
        return normaliseRotation(c, out);
    }
    }
}

}  // namespace dermis
