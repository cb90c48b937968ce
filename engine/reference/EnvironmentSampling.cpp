#include "reference/EnvironmentSampling.h"

#include "env/SphericalHarmonics.h"

#include <glm/gtc/constants.hpp>

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
    constexpr double kBelowOne = 1.0 - 0x1p-53;  // the largest double below 1
    return {bin, std::clamp(within, 0.0, kBelowOne)};
}

}  // namespace

EnvironmentDistribution::EnvironmentDistribution(Image map) {
    const int width = map.width;
    const int height = map.height;
    if (map.empty() || width <= 0 || height <= 0) return;
    mWidth = width;
    mHeight = height;
    std::vector<float> texelLuminance(size_t(width) * size_t(height));
    mRowCdf.assign(size_t(height) + 1, 0.0);
    mColumnCdfs.assign(size_t(height) * (size_t(width) + 1), 0.0);
    for (int v = 0; v < height; ++v) {
        double* columnCdf = &mColumnCdfs[size_t(v) * (size_t(width) + 1)];
        for (int u = 0; u < width; ++u) {
            const float l = std::max(luminance(map.at(u, v)), 0.0f);
            texelLuminance[size_t(v) * size_t(width) + size_t(u)] = l;
            columnCdf[u + 1] = columnCdf[u] + double(l);
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
    mRowEdgeCos.resize(size_t(height) + 1);
    for (int v = 0; v <= height; ++v) mRowEdgeCos[size_t(v)] = std::cos(kPi * v / height);
    mTexels.resize(texelLuminance.size());
    for (int v = 0; v < height; ++v) {
        for (int u = 0; u < width; ++u) {
            const size_t i = size_t(v) * size_t(width) + size_t(u);
            const float pdf = canSample() ? float(double(texelLuminance[i]) / mTotalWeight) : 0.0f;
            mTexels[i] = glm::vec4(glm::vec3(map.at(u, v)), pdf);
        }
    }
}

EnvironmentSample EnvironmentDistribution::sample(const glm::vec2& u) const {
    const auto [row, withinRow] = pickBin(mRowCdf.data(), mHeight, double(u.x), mRowGuide.data());
    const auto [column, withinColumn] = pickBin(&mColumnCdfs[size_t(row) * (size_t(mWidth) + 1)], mWidth, double(u.y),
                                                &mColumnGuides[size_t(row) * (kGuideSize + 1)]);
    // Uniform in (phi, cos theta) over the texel's patch: uniform in solid angle.
    const double cosTop = mRowEdgeCos[size_t(row)];
    const double cosTheta = cosTop + withinRow * (mRowEdgeCos[size_t(row) + 1] - cosTop);
    const float sinTheta = float(std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta)));
    const float phi = float(2.0 * kPi * (column + withinColumn) / mWidth);
    const glm::vec4& record = texel({column, row});
    EnvironmentSample sample;
    sample.direction = glm::vec3(sinTheta * std::sin(phi), float(cosTheta), sinTheta * std::cos(phi));
    sample.pdfPerSr = record.a;
    sample.radiance = glm::vec3(record);
    return sample;
}

glm::ivec2 EnvironmentDistribution::texelOf(const glm::vec3& direction) const {
    // Single precision: a direction within a float's rounding of a texel edge may land in
    // the neighbour, as it may after the float direction sample() returns.
    constexpr float kTwoPi = 2.0f * glm::pi<float>();
    float phi = std::atan2(direction.x, direction.z);
    if (phi < 0.0f) phi += kTwoPi;
    const float theta = std::acos(std::clamp(direction.y, -1.0f, 1.0f));
    const int u = std::clamp(int(phi * (float(mWidth) / kTwoPi)), 0, mWidth - 1);
    const int v = std::clamp(int(theta * (float(mHeight) / glm::pi<float>())), 0, mHeight - 1);
    return {u, v};
}

float EnvironmentDistribution::pdfPerSr(const glm::vec3& direction) const {
    if (empty()) return 0.0f;
    return texel(texelOf(direction)).a;
}

EnvironmentSample EnvironmentDistribution::lookUp(const glm::vec3& direction) const {
    EnvironmentSample sample;
    sample.direction = direction;
    if (empty()) return sample;
    const glm::vec4& record = texel(texelOf(direction));
    sample.pdfPerSr = record.a;
    sample.radiance = glm::vec3(record);
    return sample;
}

glm::vec3 EnvironmentDistribution::radiance(const glm::vec3& direction) const {
    if (empty()) return glm::vec3(0.0f);
    return glm::vec3(texel(texelOf(direction)));
}

}  // namespace dermis::reference
