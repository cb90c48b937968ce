#pragma once
// Keyframe animation as glTF 2.0 defines it (§3.11 "Animations" and Appendix
// C "Interpolation"): a clip is a set of channels, each driving one property
// of one node (translation, rotation, scale, or its mesh's morph weights)
// from a sampler of keyframe times and values.
//
//   STEP         the value of the keyframe at or before t
//   LINEAR       lerp; rotations by slerp on the shorter arc (Appendix C)
//   CUBICSPLINE  cubic Hermite: each keyframe stores (in-tangent a_k, value
//                v_k, out-tangent b_k); between k and k+1, with
//                d = t_(k+1) - t_k and s = (t - t_k) / d,
//                p(s) = (2s^3 - 3s^2 + 1) v_k + d (s^3 - 2s^2 + s) b_k
//                     + (-2s^3 + 3s^2) v_(k+1) + d (s^3 - s^2) a_(k+1);
//                rotations are normalised afterwards.
//
// Before the first keyframe a channel holds the first value, after the last
// the last (glTF leaves this to the implementation; this is the usual
// choice). The clip's duration is its latest keyframe time.

#include "core/EnumTable.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace dermis {

enum class Interpolation { Step, Linear, CubicSpline };

inline constexpr EnumTable<Interpolation, 3> kInterpolations{
    "interpolation",
    {{{Interpolation::Step, "STEP", "the previous keyframe's value"},
      {Interpolation::Linear, "LINEAR", "lerp, slerp for rotations"},
      {Interpolation::CubicSpline, "CUBICSPLINE", "cubic Hermite with stored tangents"}}}};

enum class AnimatedProperty { Translation, Rotation, Scale, Weights };

inline constexpr EnumTable<AnimatedProperty, 4> kAnimatedProperties{
    "animated property",
    {{{AnimatedProperty::Translation, "translation", "vec3"},
      {AnimatedProperty::Rotation, "rotation", "unit quaternion (x, y, z, w)"},
      {AnimatedProperty::Scale, "scale", "vec3"},
      {AnimatedProperty::Weights, "weights", "one float per morph target"}}}};

struct AnimationChannel {
    int node = -1;
    AnimatedProperty property = AnimatedProperty::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> timesS;  // strictly increasing
    // Per keyframe `components` floats (3 for translation and scale, 4 for a
    // rotation as x, y, z, w, the morph target count for weights); three such
    // groups (in-tangent, value, out-tangent) per keyframe for CUBICSPLINE.
    std::vector<float> values;
    int components = 3;
};

struct AnimationClip {
    std::string name;
    std::vector<AnimationChannel> channels;
    float durationS() const;
};

// The channel's value at timeS into `out` (channel.components floats).
void sampleChannel(const AnimationChannel& channel, float timeS, float* out);

// Slerp on the shorter arc (glTF 2.0 Appendix C); nlerp where the two are
// within 1e-4 rad of each other, where sin(a) would lose precision.
glm::quat slerpShorter(const glm::quat& a, const glm::quat& b, float s);

// A clip time from a play time: wrapped into [0, duration) when looping,
// clamped to [0, duration] otherwise. A zero-length clip gives 0.
float clipTime(float playTimeS, float durationS, bool loop);

}  // namespace dermis
