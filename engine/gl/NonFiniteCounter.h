#pragma once
// The debug pass of docs/stress.md: after every pass, read
// back each float texture it wrote and count non-finite texels (NaN, Inf) and
// the largest magnitude. Slow (a read-back per target): for stress tests and
// debugging, never for timing.

#include "gl/GlGraphBackend.h"

#include <map>
#include <string>

namespace dermis::gl {

struct TargetStats {
    uint64_t texels = 0;
    uint64_t nonFinite = 0;
    double largest = 0.0;  // largest finite |value|
};

class NonFiniteCounter {
public:
    // An inspector for GlGraphBackend::setInspector (and Renderer::setPassInspector).
    PassInspector inspector();

    // Keyed "pass/texture".
    const std::map<std::string, TargetStats>& targets() const { return mTargets; }
    uint64_t totalNonFinite() const;
    double largest() const;
    void reset() { mTargets.clear(); }

private:
    void inspect(std::string_view pass, std::string_view texture, GLuint name, const graph::TextureDesc& desc);
    std::map<std::string, TargetStats> mTargets;
};

}  // namespace dermis::gl
