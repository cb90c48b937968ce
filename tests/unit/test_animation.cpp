// glTF keyframe sampling, node hierarchies, skins and morph targets
// (engine/anim), against closed forms: each interpolation must reproduce the
// function its keyframes were taken from where that function is of the
// interpolation's own kind (a line, a constant angular velocity, a cubic).
#include "anim/Animation.h"
#include "anim/Skeleton.h"
#include "anim/Skinning.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;

namespace {

// Rounding of a few float operations on values of order 1.
constexpr float kTolerance = 1e-5f;

AnimationChannel channel(AnimatedProperty property, Interpolation interpolation, std::vector<float> times,
                         std::vector<float> values, int components) {
    AnimationChannel c;
    c.node = 0;
    c.property = property;
    c.interpolation = interpolation;
    c.timesS = std::move(times);
    c.values = std::move(values);
    c.components = components;
    return c;
}

float sample1(const AnimationChannel& c, float t) {
    float v[4];
    sampleChannel(c, t, v);
    return v[0];
}

glm::quat sampleQuat(const AnimationChannel& c, float t) {
    float v[4];
    sampleChannel(c, t, v);
    return glm::quat(v[3], v[0], v[1], v[2]);
}

glm::quat aboutZ(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1)); }

// How far apart two rotations are: |a - b| for the nearer of b and -b (the
// same rotation), about a quarter of the angle between them in radians for
// small angles. Not the angle by acos(dot): near a dot of 1 that has a
// rounding floor of 0.04 degrees in float.
float rotationDistance(const glm::quat& a, const glm::quat& b) {
    const glm::vec4 p(a.x, a.y, a.z, a.w), q(b.x, b.y, b.z, b.w);
    return std::min(glm::length(p - q), glm::length(p + q));
}

}  // namespace

TEST(Animation, StepHoldsThePreviousKeyframe) {
    const AnimationChannel c = channel(AnimatedProperty::Weights, Interpolation::Step, {0.5f, 1.0f, 2.0f}, {3, 5, 7}, 1);
    EXPECT_EQ(sample1(c, 0.0f), 3.0f);  // before the first: the first
    EXPECT_EQ(sample1(c, 0.5f), 3.0f);
    EXPECT_EQ(sample1(c, 0.99f), 3.0f);
    EXPECT_EQ(sample1(c, 1.0f), 5.0f);  // at a keyframe: its own value
    EXPECT_EQ(sample1(c, 1.7f), 5.0f);
    EXPECT_EQ(sample1(c, 2.0f), 7.0f);
    EXPECT_EQ(sample1(c, 9.0f), 7.0f);  // after the last: the last
}

TEST(Animation, LinearIsExactOnEachLineAndKinksAtKeyframes) {
    // x(t) = 2t + 1 on [0, 1], then x(t) = 3 - (t - 1) on [1, 3].
    const AnimationChannel c =
        channel(AnimatedProperty::Translation, Interpolation::Linear, {0.0f, 1.0f, 3.0f}, {1, 0, 0, 3, 1, 0, 1, 2, 0}, 3);
    for (float t : {0.0f, 0.25f, 0.5f, 1.0f}) EXPECT_NEAR(sample1(c, t), 2.0f * t + 1.0f, kTolerance) << t;
    for (float t : {1.5f, 2.2f, 3.0f}) EXPECT_NEAR(sample1(c, t), 3.0f - (t - 1.0f), kTolerance) << t;
    float v[3];
    sampleChannel(c, 2.0f, v);  // y: 1 -> 2 over [1, 3]
    EXPECT_NEAR(v[1], 1.5f, kTolerance);
}

TEST(Animation, LinearRotationTurnsAtConstantSpeedOnTheShorterArc) {
    // 0 to 120 degrees about z over one second: slerp turns 120 s degrees.
    const glm::quat a = aboutZ(0.0f), b = aboutZ(120.0f);
    const AnimationChannel c = channel(AnimatedProperty::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                                       {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w}, 4);
    for (float s : {0.0f, 0.1f, 0.5f, 0.9f, 1.0f}) {
        const glm::quat q = sampleQuat(c, s);
        EXPECT_NEAR(glm::length(q), 1.0f, kTolerance);
        EXPECT_LT(rotationDistance(q, aboutZ(120.0f * s)), kTolerance) << s;
    }
    // The second key written as -b (the same rotation): still the 120-degree
    // arc, not the 240-degree one the other way.
    const AnimationChannel flipped = channel(AnimatedProperty::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                                             {a.x, a.y, a.z, a.w, -b.x, -b.y, -b.z, -b.w}, 4);
    EXPECT_LT(rotationDistance(sampleQuat(flipped, 0.5f), aboutZ(60.0f)), kTolerance);
    // Nearly equal keys take the nlerp branch and stay unit length.
    EXPECT_NEAR(glm::length(slerpShorter(aboutZ(10.0f), aboutZ(10.001f), 0.5f)), 1.0f, kTolerance);
}

TEST(Animation, CubicSplineReproducesTheCubicItsKeysCameFrom) {
    // f(t) = t^3 - 2t^2 + 0.5t + 1 with f'(t) as both tangents at irregular
    // keyframes: the Hermite segment of a cubic with its exact end slopes is
    // that cubic (glTF 2.0 Appendix C).
    const auto f = [](float t) { return t * t * t - 2.0f * t * t + 0.5f * t + 1.0f; };
    const auto df = [](float t) { return 3.0f * t * t - 4.0f * t + 0.5f; };
    const std::vector<float> times = {0.0f, 0.7f, 2.0f};
    std::vector<float> values;
    for (float t : times) values.insert(values.end(), {df(t), f(t), df(t)});
    const AnimationChannel c = channel(AnimatedProperty::Weights, Interpolation::CubicSpline, times, values, 1);
    for (float t : {0.0f, 0.1f, 0.35f, 0.7f, 1.0f, 1.6f, 2.0f}) EXPECT_NEAR(sample1(c, t), f(t), 1e-5f) << t;
    // Tangents are scaled by the segment length: the same tangents without
    // the scale give a different curve, which this catches.
    AnimationChannel wrong = c;
    for (size_t k = 0; k < times.size(); ++k) wrong.values[3 * k] = wrong.values[3 * k + 2] = 0.0f;
    EXPECT_GT(std::abs(sample1(wrong, 1.6f) - f(1.6f)), 0.05f);
}

TEST(Animation, CubicSplineRotationIsNormalised) {
    const glm::quat a = aboutZ(0.0f), b = aboutZ(90.0f);
    const AnimationChannel c = channel(AnimatedProperty::Rotation, Interpolation::CubicSpline, {0.0f, 1.0f},
                                       {0, 0, 0, 0, a.x, a.y, a.z, a.w, 0, 0, 0, 0,  //
                                        0, 0, 0, 0, b.x, b.y, b.z, b.w, 0, 0, 0, 0},
                                       4);
    const glm::quat q = sampleQuat(c, 0.5f);
    EXPECT_NEAR(glm::length(q), 1.0f, kTolerance);
    // Zero tangents: a symmetric blend, so halfway is 45 degrees.
    EXPECT_LT(rotationDistance(q, aboutZ(45.0f)), kTolerance);
}

TEST(Animation, ClipTimeLoopsOrClamps) {
    EXPECT_FLOAT_EQ(clipTime(2.5f, 1.0f, true), 0.5f);
    EXPECT_FLOAT_EQ(clipTime(-0.25f, 1.0f, true), 0.75f);
    EXPECT_FLOAT_EQ(clipTime(2.5f, 1.0f, false), 1.0f);
    EXPECT_FLOAT_EQ(clipTime(-1.0f, 1.0f, false), 0.0f);
    EXPECT_FLOAT_EQ(clipTime(3.0f, 0.0f, true), 0.0f);
    AnimationClip clip;
    clip.channels = {channel(AnimatedProperty::Weights, Interpolation::Step, {0.0f, 1.5f}, {0, 1}, 1),
                     channel(AnimatedProperty::Weights, Interpolation::Step, {0.0f, 2.5f}, {0, 1}, 1)};
    EXPECT_FLOAT_EQ(clip.durationS(), 2.5f);
}

TEST(Skeleton, ChildWorldIsParentWorldTimesLocalWhateverTheOrder) {
    // Node 0 is the child (listed first), node 1 its parent, turned 90
    // degrees about z: the child's origin one unit along the parent's x lands
    // on world y.
    std::vector<SkeletonNode> nodes(2);
    nodes[0].parent = 1;
    nodes[0].rest.translation = glm::vec3(1, 0, 0);
    nodes[1].rest.rotation = aboutZ(90.0f);
    nodes[1].rest.scale = glm::vec3(2.0f);
    const std::vector<glm::mat4> world = worldFromNodes(nodes, restPose(nodes));
    const glm::vec3 origin = glm::vec3(world[0] * glm::vec4(0, 0, 0, 1));
    EXPECT_NEAR(origin.x, 0.0f, kTolerance);
    EXPECT_NEAR(origin.y, 2.0f, kTolerance);  // scaled by the parent's 2
}

TEST(Skeleton, ClipDrivesOnlyItsChannels) {
    std::vector<SkeletonNode> nodes(1);
    nodes[0].rest.translation = glm::vec3(5, 6, 7);
    nodes[0].rest.scale = glm::vec3(3.0f);
    AnimationClip clip;
    clip.channels = {channel(AnimatedProperty::Translation, Interpolation::Linear, {0.0f, 1.0f}, {0, 0, 0, 2, 0, 0}, 3)};
    Pose pose = restPose(nodes);
    applyClip(clip, 0.5f, pose);
    EXPECT_EQ(pose[0].translation, glm::vec3(1, 0, 0));
    EXPECT_EQ(pose[0].scale, glm::vec3(3.0f));
    AnimationClip stray = clip;
    stray.channels[0].node = 4;  // no such node: skipped
    applyClip(stray, 0.5f, pose);
    EXPECT_EQ(pose[0].translation, glm::vec3(1, 0, 0));
}

TEST(CpuSkinning, BlendsJointMatricesWithTheirInverseBinds) {
    // Joint 0 at the origin, joint 1 at x = 1 (inverse bind: back by 1),
    // turned 90 degrees about z at its own place. A vertex at x = 2 follows
    // joint 1 alone to (1, 1); half and half lands on the mean of (2, 0) and
    // (1, 1), as linear-blend skinning does.
    std::vector<SkeletonNode> nodes(2);
    nodes[1].rest.translation = glm::vec3(1, 0, 0);
    nodes[1].rest.rotation = aboutZ(90.0f);
    Skin skin;
    skin.joints = {0, 1};
    skin.inverseBindMatrices = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(-1, 0, 0))};
    const std::vector<glm::mat4> joints = jointMatrices(skin, worldFromNodes(nodes, restPose(nodes)));

    SkinnedVertices v;
    v.positions = {glm::vec3(2, 0, 0), glm::vec3(2, 0, 0)};
    v.normals = {glm::vec3(1, 0, 0), glm::vec3(1, 0, 0)};
    v.tangents = {glm::vec4(0, 1, 0, -1), glm::vec4(0, 1, 0, -1)};
    std::vector<SkinInfluence> influences(2);
    influences[0].joints = glm::u16vec4(1, 0, 0, 0);
    influences[0].weights = glm::vec4(1, 0, 0, 0);
    influences[1].joints = glm::u16vec4(0, 1, 0, 0);
    influences[1].weights = glm::vec4(0.5f, 0.5f, 0, 0);
    const SkinnedVertices s = skinVertices(v, influences, joints);
    EXPECT_NEAR(glm::length(s.positions[0] - glm::vec3(1, 1, 0)), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(s.normals[0] - glm::vec3(0, 1, 0)), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(glm::vec3(s.tangents[0]) - glm::vec3(-1, 0, 0)), 0.0f, kTolerance);
    EXPECT_EQ(s.tangents[0].w, -1.0f);
    EXPECT_NEAR(glm::length(s.positions[1] - glm::vec3(1.5f, 0.5f, 0)), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(s.normals[1]), 1.0f, kTolerance);
}

TEST(CpuSkinning, MorphTargetsAddTheirWeightedDisplacements) {
    SkinnedVertices base;
    base.positions = {glm::vec3(0.0f)};
    base.normals = {glm::vec3(0, 0, 1)};
    std::vector<MorphTarget> targets(2);
    targets[0].positions = {glm::vec3(1, 0, 0)};
    targets[0].normals = {glm::vec3(1, 0, 0)};
    targets[1].positions = {glm::vec3(0, 2, 0)};
    const SkinnedVertices m = applyMorphTargets(base, targets, {0.25f, 0.5f, 9.0f});  // a third weight: no target
    EXPECT_NEAR(glm::length(m.positions[0] - glm::vec3(0.25f, 1.0f, 0.0f)), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(m.normals[0] - glm::normalize(glm::vec3(0.25f, 0, 1))), 0.0f, kTolerance);
}
