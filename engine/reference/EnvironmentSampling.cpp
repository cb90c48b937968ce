#include "reference/EnvironmentSampling.h"

#include "env/SphericalHarmonics.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dermis::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Rec. 709 / sRGB primaries' luminance weights.
float luminance(const glm::vec4& rgb) { return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b; }

// Normalises running sums in place to a CDF ending at exactly 1 (a total of 0 leaves zeros).
void normaliseCdf(double* cdf, size_t entries) {
    const double total = cdf[entries - 1];
    if (!(total > 0.0)) return;
    for (size_t i = 1; i + 1 < entries; ++i) cdf[i] /= total;
    cdf[entries - 1] = 1.0;
}

// Entries of a guide table: a power of two, so that g / kGuideSize and u x kGuideSize are exact.
constexpr uint32_t kGuideSize = 1024;

// The guide table of a CDF of `bins` + 1 entries: entry g is the first index i with cdf[i] > g / kGuideSize.
void buildGuide(const double* cdf, int bins, uint32_t* guide) {
    for (uint32_t g = 0; g <= kGuideSize; ++g) {
        guide[g] = uint32_t(std::upper_bound(cdf, cdf + bins + 1, double(g) / kGuideSize) - cdf);
    }
}

// The bin b with cdf[b] <= u < cdf[b + 1] (bins of zero probability are never
// chosen) and where u lies inside it, in [0, 1). The first index with cdf > u lies
// between the guide's entries for g / kGuideSize <= u < (g + 1) / kGuideSize: the
// search is the full one's, over a few entries.
std::pair<int, double> pickBin(const double* cdf, int bins, double u, const uint32_t* guide) {
    const auto g = std::min(uint32_t(std::max(u, 0.0) * kGuideSize), kGuideSize - 1);
    const double* first = cdf + guide[g];
    const double* last = cdf + std::min<uint32_t>(guide[g + 1] + 1, uint32_t(bins) + 1);
    const int bin = std::clamp(int(std::upper_bound(first, last, u) - cdf) - 1, 0, bins - 1);
    const double width = cdf[bin + 1] - cdf[bin];
    const double within = width > 0.0 ? (u - cdf[bin]) / width : 0.5;
    return {bin, std::clamp(within, 0.0, std::nextafter(1.0, 0.0))};
}

}  // namespace

EnvironmentDistribution::EnvironmentDistribution(Image map) : mMap(std::move(map)) {
    const int width = mMap.width;
    const int height = mMap.height;
    if (mMap.empty() || width <= 0 || height <= 0) return;
    mLuminance.resize(size_t(width) * size_t(height));
    mRowCdf.assign(size_t(height) + 1, 0.0);
    mColumnCdfs.assign(size_t(height) * (size_t(width) + 1), 0.0);
    for (int v = 0; v < height; ++v) {
        double* columnCdf = &mColumnCdfs[size_t(v) * (size_t(width) + 1)];
        for (int u = 0; u < width; ++u) {
            const float texelLuminance = std::max(luminance(mMap.at(u, v)), 0.0f);
            mLuminance[size_t(v) * size_t(width) + size_t(u)] = texelLuminance;
            columnCdf[u + 1] = columnCdf[u] + double(texelLuminance);
        }
        // Every texel of a row has the same solid angle: it weights the row, not the columns.
        const double rowWeight = columnCdf[width] * double(latLongTexelSolidAngle(v, width, height));
        mRowCdf[size_t(v) + 1] = mRowCdf[size_t(v)] + rowWeight;
        normaliseCdf(columnCdf, size_t(width) + 1);
    }
    mTotalWeight = mRowCdf.back();
    normaliseCdf(mRowCdf.data(), mRowCdf.size());
    mRowGuide.resize(kGuideSize + 1);
    buildGuide(mRowCdf.data(), height, mRowGuide.data());
    mColumnGuides.resize(size_t(height) * (kGuideSize + 1));
    for (int v = 0; v < height; ++v) {
        buildGuide(&mColumnCdfs[size_t(v) * (size_t(width) + 1)], width, &mColumnGuides[size_t(v) * (kGuideSize + 1)]);
    }
}

EnvironmentSample EnvironmentDistribution::sample(const glm::vec2& u) const {
    const int width = mMap.width;
    const int height = mMap.height;
    const auto [row, withinRow] = pickBin(mRowCdf.data(), height, double(u.x), mRowGuide.data());
    const auto [column, withinColumn] = pickBin(&mColumnCdfs[size_t(row) * (size_t(width) + 1)], width, double(u.y),
                                                &mColumnGuides[size_t(row) * (kGuideSize + 1)]);
    // Uniform in (phi, cos theta) over the texel's patch: uniform in solid angle.
    const double cosTop = std::cos(kPi * row / height);
    const double cosBottom = std::cos(kPi * (row + 1) / height);
    const double cosTheta = cosTop + withinRow * (cosBottom - cosTop);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * (column + withinColumn) / width;
    EnvironmentSample sample;
    sample.direction = glm::vec3(float(sinTheta * std::sin(phi)), float(cosTheta), float(sinTheta * std::cos(phi)));
    sample.pdfPerSr = pdfOfTexel({column, row});
    sample.radiance = glm::vec3(mMap.at(column, row));
    return sample;
}

glm::ivec2 EnvironmentDistribution::texelOf(const glm::vec3& direction) const {
    double phi = std::atan2(double(direction.x), double(direction.z));
    if (phi < 0.0) phi += 2.0 * kPi;
    const double theta = std::acos(std::clamp(double(direction.y), -1.0, 1.0));
    const int u = std::clamp(int(phi / (2.0 * kPi) * mMap.width), 0, mMap.width - 1);
    const int v = std::clamp(int(theta / kPi * mMap.height), 0, mMap.height - 1);
    return {u, v};
}

float EnvironmentDistribution::pdfOfTexel(const glm::ivec2& texel) const {
    if (!canSample()) return 0.0f;
    return float(double(mLuminance[size_t(texel.y) * size_t(mMap.width) + size_t(texel.x)]) / mTotalWeight);
}

float EnvironmentDistribution::pdfPerSr(const glm::vec3& direction) const {
    if (empty()) return 0.0f;
    return pdfOfTexel(texelOf(direction));
}

EnvironmentSample EnvironmentDistribution::lookUp(const glm::vec3& direction) const {
    EnvironmentSample sample;
    sample.direction = direction;
    if (empty()) return sample;
    const glm::ivec2 texel = texelOf(direction);
    sample.pdfPerSr = pdfOfTexel(texel);
    sample.radiance = glm::vec3(mMap.at(texel.x, texel.y));
    return sample;
}

glm::vec3 EnvironmentDistribution::radiance(const glm::vec3& direction) const {
    if (empty()) return glm::vec3(0.0f);
    const glm::ivec2 texel = texelOf(direction);
    return glm::vec3(mMap.at(texel.x, texel.y));
}

}  // namespace dermis::reference
