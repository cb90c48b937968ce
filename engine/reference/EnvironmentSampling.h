#pragma once
// Importance sampling of a lat-long environment map (env/SphericalHarmonics.h
// gives the layout), after Pharr, Jakob & Humphreys 2016 §13.6.7 and §14.2.4:
// a piecewise-constant 2-D distribution over the texels, proportional to
// luminance x texel solid angle, drawn as a marginal over rows and a
// conditional over the columns of the chosen row. Inside the chosen texel the
// direction is uniform in (phi, cos theta), which is uniform in solid angle,
// so the density is constant over a texel:
//   pdf(omega) = luminance(texel) / sum over texels of luminance x solid angle   (per steradian).
// The map is taken as piecewise constant too (each texel's radiance over its
// whole patch of the sphere), the function whose integral the SH projection
// (projectLatLong) sums. Black texels have density 0: a caller must cover them
// with another technique (multiple importance sampling) if they matter.
// Directions are in map space; the caller rotates them.

#include "core/ContentHash.h"
#include "core/Image.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::reference {

struct EnvironmentSample {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit, map space
    float pdfPerSr = 0.0f;
    glm::vec3 radiance{0.0f};  // the map's texel there
};

class EnvironmentDistribution {
public:
    EnvironmentDistribution() = default;
    // `map`: linear RGB radiance, lat-long, width = 2 height (checkEnvironmentMap's maps).
    explicit EnvironmentDistribution(Image map);

    bool empty() const { return mWidth == 0; }
    // False when every texel is black: sample() cannot be used then.
    bool canSample() const { return mTotalWeight > 0.0; }

    // A direction for the uniform numbers `u` in [0, 1)^2; the first picks the row,
    // the second the column, and what remains of each places it inside the texel.
    EnvironmentSample sample(const glm::vec2& u) const;
    // The density sample() draws `direction` (unit, map space) with, per steradian.
    float pdfPerSr(const glm::vec3& direction) const;
    // The map's radiance towards `direction` (unit, map space), piecewise constant.
    glm::vec3 radiance(const glm::vec3& direction) const;
    // Both at once (one texel look-up): what sample() would have given for `direction`.
    EnvironmentSample lookUp(const glm::vec3& direction) const;
    // The map (and so its distribution), into `hash`.
    void hashContent(ContentHash& hash) const {
        hash.number(uint64_t(mWidth)).number(uint64_t(mHeight)).values(mTexels);
    }

private:
    glm::ivec2 texelOf(const glm::vec3& direction) const;
    const glm::vec4& texel(const glm::ivec2& at) const { return mTexels[size_t(at.y) * size_t(mWidth) + size_t(at.x)]; }

    int mWidth = 0;
    int mHeight = 0;
    // Per texel, row-major: the radiance (rgb) and pdfPerSr (a) together, so that a
    // look-up (the cosine technique's, at random texels) misses the cache once.
    std::vector<glm::vec4> mTexels;
    std::vector<double> mRowEdgeCos;      // height + 1 entries: cos theta at each row's top edge
    std::vector<double> mRowCdf;          // height + 1 entries, 0 .. 1
    std::vector<double> mColumnCdfs;      // per row, width + 1 entries each, 0 .. 1
    // Guide tables (Chen & Asau 1974, the indexed search): entry g of a CDF's table is the
    // first index whose value exceeds g / kGuideSize, so a search starts next to its answer.
    std::vector<uint32_t> mRowGuide;      // kGuideSize + 1 entries
    std::vector<uint32_t> mColumnGuides;  // per row, kGuideSize + 1 entries each
    double mTotalWeight = 0.0;            // sum of luminance x texel solid angle
};

}  // namespace dermis::reference
