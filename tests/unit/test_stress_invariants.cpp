// The wrong-image detectors (tools/stress/Invariants.h) on synthetic frames
// that hold or break each invariant; expected numbers are worked out here by
// hand from the frames, not by the checks.
#include "stress/Invariants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace dermis;
using namespace dermis::stress;

namespace {

Image filled(int w, int h, glm::vec4 value) {
    Image image;
    image.width = w;
    image.height = h;
    image.texels.assign(size_t(w) * size_t(h), value);
    return image;
}

// An 8x6 frame: character 0 (id 1) on columns 0-3, character 1 (id 2) on
// columns 4-5, background on 6-7.
Image twoCharacters() {
    Image object = filled(8, 6, glm::vec4(0.0f));
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x) object.at(x, y) = glm::vec4(x < 4 ? 1.0f : 2.0f, 0, 0, 1);
    return object;
}

Image depthOf(const Image& object) {
    Image depth = object;
    for (glm::vec4& t : depth.texels) t = t.r > 0.0f ? glm::vec4(0.4f, 0.4f, 0.4f, 1.0f) : glm::vec4(10, 10, 10, 0);
    return depth;
}

RaySample ray(int x, int y, int character, float depthM = 0.4f) {
    RaySample r;
    r.x = x;
    r.y = y;
    r.character = character;
    r.depthM = depthM;
    r.characterDepthM = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};
    if (character >= 0) r.characterDepthM[size_t(character)] = depthM;
    r.depthToleranceM = 1e-4f;
    return r;
}

// One ray per pixel that agrees with twoCharacters().
std::vector<RaySample> agreeingRays() {
    std::vector<RaySample> rays;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) rays.push_back(ray(x, y, x < 4 ? 0 : (x < 6 ? 1 : -1)));
    return rays;
}

}  // namespace

TEST(StressInvariants, ObjectMatchingDepthHolds) {
    const Image object = twoCharacters();
    InvariantTally t;
    checkObjectCoversDepth(object, depthOf(object), 2, t);
    EXPECT_EQ(t.checked, 48u);
    EXPECT_EQ(t.violated, 0u);
}

TEST(StressInvariants, DroppedIdsBreakCoverage) {
    const Image object = twoCharacters();
    Image dropped = object;
    for (int y = 0; y < 6; ++y) dropped.at(5, y) = glm::vec4(0.0f);  // one column of character 1 lost: 6 pixels
    InvariantTally a;
    checkObjectCoversDepth(dropped, depthOf(object), 2, a);
    EXPECT_EQ(a.violated, 6u);
    Image outOfRange = object;
    outOfRange.at(0, 0).r = 3.0f;  // no third character
    InvariantTally b;
    checkObjectCoversDepth(outOfRange, depthOf(object), 2, b);
    EXPECT_EQ(b.violated, 1u);
}

TEST(StressInvariants, RaysAgreeingWithTheObjectImageHold) {
    InvariantTally t;
    checkRaysMatchObject(twoCharacters(), agreeingRays(), 2, t);
    EXPECT_EQ(t.checked, 48u + 2u);  // every ray, and both characters (each seen by >= 3 rays)
    EXPECT_EQ(t.violated, 0u);
}

TEST(StressInvariants, AnEdgeOffByOnePixelIsNotAMismatch) {
    // The rays put character 1's edge one column left of the engine's (x = 3):
    // the 3x3 neighbourhood of (3, y) holds id 2 at x = 4.
    std::vector<RaySample> rays = agreeingRays();
    for (RaySample& r : rays)
        if (r.x == 3) r.character = 1;
    InvariantTally t;
    checkRaysMatchObject(twoCharacters(), rays, 2, t);
    EXPECT_EQ(t.violated, 0u);
}

TEST(StressInvariants, ACharacterTwoPixelsAwayIsAMismatch) {
    // Rays see character 1 at column 2; the engine's nearest id 2 is at column 4.
    std::vector<RaySample> rays = agreeingRays();
    for (RaySample& r : rays)
        if (r.x == 2) r = ray(2, r.y, 1, 0.3f);  // 0.1 m in front of character 0: no depth tie
    InvariantTally t;
    checkRaysMatchObject(twoCharacters(), rays, 2, t);
    EXPECT_EQ(t.violated, 6u);  // the six rows of column 2
}

TEST(StressInvariants, ADepthTieExcusesTheOtherCharacter) {
    std::vector<RaySample> rays = agreeingRays();
    for (RaySample& r : rays) {
        if (r.x != 1) continue;
        r.character = 1;  // the ray's nearest is character 1 ...
        r.characterDepthM = {0.40005f, 0.4f};  // ... 5e-5 m in front of character 0, inside the 1e-4 m tolerance
    }
    InvariantTally tie;
    checkRaysMatchObject(twoCharacters(), rays, 2, tie);
    EXPECT_EQ(tie.violated, 0u);
    for (RaySample& r : rays)
        if (r.x == 1) r.characterDepthM = {0.4002f, 0.4f};  // 2e-4 m: no tie
    InvariantTally apart;
    checkRaysMatchObject(twoCharacters(), rays, 2, apart);
    EXPECT_EQ(apart.violated, 6u);
}

TEST(StressInvariants, ALostCharacterIsAViolation) {
    Image object = twoCharacters();
    for (glm::vec4& t : object.texels)
        if (t.r == 2.0f) t.r = 0.0f;  // character 1 gone from the frame
    InvariantTally t;
    checkRaysMatchObject(object, agreeingRays(), 2, t);
    // No pixel has id 2: the 12 rays of columns 4-5 mismatch, and the character is lost.
    EXPECT_EQ(t.violated, 12u + 1u);
}

TEST(StressInvariants, RaysNearAClipPlaneAreNotUsed) {
    std::vector<RaySample> rays = agreeingRays();
    for (RaySample& r : rays) {
        r.character = 1;
        r.ambiguous = true;
    }
    InvariantTally t;
    checkRaysMatchObject(twoCharacters(), rays, 2, t);
    EXPECT_EQ(t.checked, 0u);
}

namespace {

struct EnergyFrame {
    Image object = twoCharacters();
    Image irradiance = filled(8, 6, glm::vec4(0.0f));
    Image transmittance = filled(8, 6, glm::vec4(0.0f));
    Image albedo = filled(8, 6, glm::vec4(0.25f, 0.5f, 1.0f, 1.0f));
    Image diffuse = filled(8, 6, glm::vec4(0.0f));
    std::vector<int> groupOf{0, 1};

    // Character 0's blur input peaks at 4 (irradiance 3 + transmittance 1) at
    // (1, 1); with mix 0.5, albedo^(1-mix) = (0.5, 0.7071, 1). The diffuse is
    // everywhere the peak times that: the most a convex blur can give.
    EnergyFrame() {
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 4; ++x) irradiance.at(x, y) = glm::vec4(1.0f);
        irradiance.at(1, 1) = glm::vec4(3.0f);
        transmittance.at(1, 1) = glm::vec4(1.0f);
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 4; ++x) diffuse.at(x, y) = glm::vec4(4.0f * 0.5f, 4.0f * std::sqrt(0.5f), 4.0f, 1);
    }
    InvariantTally check() const {
        EnergyInputs in;
        in.diffuse = &diffuse;
        in.albedo = &albedo;
        in.object = &object;
        in.mix = 0.5f;
        in.groupOf = groupOf;
        in.groupBlurMax = largestBlurInput(irradiance, transmittance, object, groupOf, 2);
        InvariantTally t;
        checkEnergy(in, t);
        return t;
    }
};

}  // namespace

TEST(StressInvariants, LargestBlurInputIsPerGroup) {
    EnergyFrame f;
    const auto largest = largestBlurInput(f.irradiance, f.transmittance, f.object, f.groupOf, 2);
    EXPECT_EQ(largest[0], glm::vec3(4.0f));
    EXPECT_EQ(largest[1], glm::vec3(0.0f));
}

TEST(StressInvariants, DiffuseAtTheBoundHolds) {
    const InvariantTally t = EnergyFrame().check();
    EXPECT_EQ(t.checked, 36u);  // the covered pixels
    EXPECT_EQ(t.violated, 0u);
}

TEST(StressInvariants, DiffuseOverTheBoundIsAViolation) {
    EnergyFrame f;
    // 0.5% over the bound in the blue channel at one pixel: above the 0.2% tolerance.
    f.diffuse.at(2, 3).b = 4.0f * 1.005f;
    EXPECT_EQ(f.check().violated, 1u);
    // Scaled by 1.5 everywhere (the planted violation): every pixel of character 0.
    EnergyFrame g;
    for (glm::vec4& t : g.diffuse.texels) t *= 1.5f;
    EXPECT_EQ(g.check().violated, 24u);
    // A NaN is not within any bound.
    EnergyFrame h;
    h.diffuse.at(0, 0).g = std::nanf("");
    EXPECT_EQ(h.check().violated, 1u);
}

TEST(StressInvariants, ALightFromAnotherGroupIsNoExcuse) {
    // Character 1 is unlit (blur max 0) but shows diffuse 0.01: light leaked from character 0's blur.
    EnergyFrame f;
    f.diffuse.at(5, 0) = glm::vec4(0.01f);
    EXPECT_EQ(f.check().violated, 1u);
    // In one group (same profile) the same value is within character 0's bound.
    f.groupOf = {0, 0};
    EXPECT_EQ(f.check().violated, 0u);
}

namespace {

struct BlackFrame {
    Image object = twoCharacters();
    Image albedo = filled(8, 6, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    Image diffuse = filled(8, 6, glm::vec4(0.0f));
    Image radiance = filled(8, 6, glm::vec4(0.0f));
    Image final = filled(8, 6, glm::vec4(0.0f));
    std::vector<RaySample> rays = agreeingRays();
    float exposure = 1.0f;

    // Character 0 lit at every ray: diffuse 0.1, radiance 0.2 (visible), final 0.3; character 1 unlit and black.
    BlackFrame() {
        for (RaySample& r : rays) r.lit = r.character == 0;
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 4; ++x) {
                diffuse.at(x, y) = glm::vec4(0.1f, 0.1f, 0.1f, 1.0f);
                radiance.at(x, y) = glm::vec4(0.2f, 0.2f, 0.2f, 1.0f);
                final.at(x, y) = glm::vec4(0.3f, 0.3f, 0.3f, 1.0f);
            }
    }
    InvariantTally check() const {
        InvariantTally t;
        checkNotBlack(object, albedo, diffuse, radiance, final, rays, exposure, 2, t);
        return t;
    }
};

}  // namespace

TEST(StressInvariants, LitAndVisibleHolds) {
    const InvariantTally t = BlackFrame().check();
    EXPECT_EQ(t.checked, 1u + 24u);  // character 0, and its 24 visible pixels
    EXPECT_EQ(t.violated, 0u);
}

TEST(StressInvariants, ALitCharacterWithZeroRadianceIsAViolation) {
    BlackFrame f;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 4; ++x) f.radiance.at(x, y) = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_EQ(f.check().violated, 1u);
    // One pixel with light left is enough (shadow-map acne may darken the rest).
    f.radiance.at(2, 2).g = 1e-4f;
    EXPECT_EQ(f.check().violated, 0u);
    // Albedo 0: black is right.
    BlackFrame g;
    for (glm::vec4& t : g.radiance.texels) t = glm::vec4(0.0f);
    for (glm::vec4& t : g.albedo.texels) t = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_EQ(g.check().violated, 0u);
    EXPECT_EQ(g.check().checked, 0u);
}

TEST(StressInvariants, ALitCharacterWithSpecularButNoDiffuseLightIsAViolation) {
    // The pre-integrated head with SSS off once lost its diffuse light while
    // its specular (LEAN) still showed: radiance > 0, diffuse 0.
    BlackFrame f;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 4; ++x) f.diffuse.at(x, y) = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_EQ(f.check().violated, 1u);
    f.diffuse.at(1, 3).r = 1e-4f;  // one pixel with diffuse light is enough
    EXPECT_EQ(f.check().violated, 0u);
}

TEST(StressInvariants, ABlackToneMappedPixelOverVisibleRadianceIsAViolation) {
    BlackFrame f;
    f.final.at(1, 4) = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_EQ(f.check().violated, 1u);
    // Exposure 0.04 brings 0.2 to 0.008 < 0.01: not clearly visible, not checked.
    f.exposure = 0.04f;
    EXPECT_EQ(f.check().checked, 1u);
    EXPECT_EQ(f.check().violated, 0u);
}

TEST(StressInvariants, ScreenAndTextureSpaceAgreeingHold) {
    // A 12x12 frame of one character; interior: at least 3 px from the border.
    const Image object = filled(12, 12, glm::vec4(1, 0, 0, 1));
    Image ts = filled(12, 12, glm::vec4(0.5f, 0.4f, 0.3f, 1.0f));
    ts.at(6, 6) = glm::vec4(1.0f, 0.4f, 0.3f, 1.0f);  // the largest interior value: 1
    Image ss = ts;
    ss.at(5, 5).r += 0.029f;  // 2.9% of the largest value
    ss.at(0, 0).r += 5.0f;   // at the border: not interior
    InvariantTally t;
    float relative = -1.0f;
    checkScreenMatchesTexture(object, ss, ts, t, &relative);
    EXPECT_EQ(t.checked, 1u);
    EXPECT_EQ(t.violated, 0u);
    EXPECT_NEAR(relative, 0.029f, 1e-6f);
    ss.at(5, 5).r += 0.002f;  // 3.1%: over the 3% bound
    InvariantTally u;
    checkScreenMatchesTexture(object, ss, ts, u, &relative);
    EXPECT_EQ(u.violated, 1u);
    EXPECT_NEAR(relative, 0.031f, 1e-6f);
}
