#pragma once
// The debug pass of docs/stress.md: after every pass, read back each colour
// texture it wrote and count what is wrong in it. Float targets: non-finite
// texels (NaN, Inf) and, for fp16 ones, texels at the fp16 clamp (65504).
// The packed SSS chain (RGBA32UI, eight halves: shaders/include/SssChain.glsl
// sssPack) is decoded half by half as fp16. The depth key (R32UI:
// UniformBlocks.glsl DERMIS_KEY_*) is checked for a valid slot. Unorm targets
// (RGBA8, R8) are read as floats and checked to lie in [0, 1]. Depth and
// stencil buffers are not read. Slow (a read-back per target): for stress
// tests and debugging, never for timing.

#include "gl/GlGraphBackend.h"

#include <map>
#include <string>
#include <vector>

namespace dermis::gl {

struct TargetStats {
    std::string format;
    uint64_t texels = 0;      // texels read (summed over frames)
    uint64_t nonFinite = 0;   // texels with a NaN or Inf component
    uint64_t outOfRange = 0;  // unorm components outside [0, 1]; depth keys with an impossible slot
    uint64_t atHalfMax = 0;   // fp16 targets: texels with a component at +-65504 (the sanitisers' clamp)
    double largest = 0.0;     // largest finite |value| (a depth key: its view depth in metres)
    bool lit = false;         // a lit colour target (irradiance, specular, SSS, composite): see isLitTarget
    double largestLit = 0.0;  // lit targets: largest finite rgb component
    uint64_t bad() const { return nonFinite + outOfRange; }
};

// Whether a texture of this name holds lit colour in rgb, as opposed to data
// (albedo, normals, depth, AO, shadow depth, LEAN moments, texture-space
// geometry) or an AOV output.
bool isLitTarget(std::string_view texture);

class NonFiniteCounter {
public:
    // An inspector for GlGraphBackend::setInspector (and Renderer::setPassInspector).
    PassInspector inspector();

    // Keyed "pass/texture".
    const std::map<std::string, TargetStats>& targets() const { return mTargets; }
    uint64_t totalNonFinite() const;
    uint64_t totalBad() const;
    // The largest finite rgb value of the lit targets (not the shadow maps'
    // clear value, not a depth AOV's far plane).
    double largestLit() const;
    uint64_t totalAtHalfMax() const;
    void reset() { mTargets.clear(); }

private:
    void inspect(std::string_view pass, std::string_view texture, GLuint name, const graph::TextureDesc& desc);
    std::map<std::string, TargetStats> mTargets;
};

// The first of `passes` (a frame's passes in execution order) whose
// sanitisers replaced a NaN or Inf or whose targets hold a bad texel; empty
// when none did. A NaN flows downstream, so later passes may see it too: the
// first one is where it arose.
std::string firstFaultyPass(const std::vector<std::string>& passes, const std::vector<PassSanitised>& sanitised,
                            const NonFiniteCounter& targets);

}  // namespace dermis::gl
