#include "env/PrefilteredEnvironment.h"

#include "core/ImageResample.h"
#include "core/ImageSampling.h"
#include "env/SphericalHarmonics.h"
#include "raytrace/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace dermis {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Texels whose lobe weight is below exp(-kLobeCutoffExponent) of the peak are
// skipped. Near the peak the lobe is a Gaussian in the angle to r, so the
// skipped part of its weight is exp(-9) = 1.2e-4 of the whole; from m = 1/3 on
// the cut-off lies beyond the horizon and the whole hemisphere is summed.
constexpr double kLobeCutoffExponent = 9.0;

// D(h) (n.l) for n = v = r, as a function of c = r.l, without D's constant
// factor 1 / (pi m^2) (it cancels in the normalised sum). Beckmann's
// distribution as Walter et al. 2007 eq. 25 writes it:
// D(h) = exp(-tan^2 a / m^2) / (pi m^2 cos^4 a), a the angle between n and h.
// With h = normalize(l + r): cos^2 a = (1 + c) / 2, tan^2 a = (1 - c) / (1 + c).
double lobeWeight(double c, double inverseRoughnessSquared) {
    if (c <= 0.0) return 0.0;
    const double onePlusC = 1.0 + c;
    return std::exp(-(1.0 - c) / onePlusC * inverseRoughnessSquared) * 4.0 * c / (onePlusC * onePlusC);
}

// For each output cell of [0, 1) cut into outputCount cells, the input cells
// (of inputCount) it overlaps and the overlap's share of the output cell,
// measured by `measure(a, b)` for the interval [a, b].
using Overlaps = std::vector<std::vector<std::pair<int, double>>>;
Overlaps cellOverlaps(int outputCount, int inputCount, const std::function<double(double, double)>& measure) {
    Overlaps overlaps(static_cast<size_t>(outputCount));
    for (int o = 0; o < outputCount; ++o) {
        const double begin = double(o) / outputCount, end = double(o + 1) / outputCount;
        const double outputMeasure = measure(begin, end);
        const int firstInput = int(std::floor(begin * inputCount));
        const int lastInput = std::min(inputCount - 1, int(std::ceil(end * inputCount)) - 1);
        for (int i = firstInput; i <= lastInput; ++i) {
            const double share = measure(std::max(begin, double(i) / inputCount), std::min(end, double(i + 1) / inputCount));
            if (share > 0.0) overlaps[size_t(o)].emplace_back(i, share / outputMeasure);
        }
    }
    return overlaps;
}

// A box-filtered copy of the base that the lobes of one level are summed
// over: each row three times in a row, so that a window of up to `width`
// columns starting anywhere in [-width, width) reads without wrapping.
struct SourceLevel {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> tripledRows;  // row v, column j at v * 3 width + width + j
};

SourceLevel makeSourceLevel(const Image& image) {
    SourceLevel source;
    source.width = image.width;
    source.height = image.height;
    source.tripledRows.reserve(3 * image.texels.size());
    for (int v = 0; v < image.height; ++v)
        for (int copy = 0; copy < 3; ++copy)
            for (int u = 0; u < image.width; ++u) source.tripledRows.emplace_back(image.at(u, v));
    return source;
}

// One output row of a prefiltered level: Prefiltered(r, m) at each texel centre
// r. The source has `scale` (an integer; 1 as built) columns per output column,
// so source column scale u + i lies at the same longitude offset from output
// column u for every u: the weights of a row are computed once, per (source
// row, i), and the sum over a texel's window is multiply-adds only.
void prefilterRow(const SourceLevel& source, float m, Image& output, int row) {
    const int width = source.width, height = source.height;
    const int scale = width / output.width;
    const double inverseRoughnessSquared = 1.0 / (double(m) * m);
    const double cutoff = kLobeCutoffExponent * double(m) * m;
    // lobeWeight's exponent (1 - c) / ((1 + c) m^2) reaches the cut-off at c = minCos.
    const double minCos = std::max(0.0, (1.0 - cutoff) / (1.0 + cutoff));
    const double maxAngle = std::acos(minCos);
    const double theta = kPi * (row + 0.5) / output.height;
    const int firstRow = std::max(0, int(std::ceil(height * (theta - maxAngle) / kPi - 0.5)));
    const int lastRow = std::min(height - 1, int(std::floor(height * (theta + maxAngle) / kPi - 0.5)));

    struct RowWindow {
        int sourceRow = 0;
        int firstOffset = 0;         // i of the first weight
        std::vector<float> weights;  // solid angle x lobe, per i
    };
    std::vector<RowWindow> windows;
    double weightSum = 0.0;
    const auto longitudeOffset = [&](int i) { return 2.0 * kPi * (i + 0.5 - 0.5 * scale) / width; };
    for (int v = firstRow; v <= lastRow; ++v) {
        // The offsets of row v within maxAngle of r: cos(angle) = cos t cos t' + sin t sin t' cos(dphi).
        const double thetaSource = kPi * (v + 0.5) / height;
        const double rowProduct = std::sin(theta) * std::sin(thetaSource);
        const double cosProduct = std::cos(theta) * std::cos(thetaSource);
        const double needed = minCos - cosProduct;
        if (needed >= rowProduct) continue;
        RowWindow window{v, -width / 2, {}};
        int offsetCount = width;
        if (needed > -rowProduct) {
            const double halfWidth = std::acos(needed / rowProduct) * width / (2.0 * kPi);
            window.firstOffset = int(std::ceil(-halfWidth + 0.5 * scale - 0.5));
            offsetCount = std::min(width, int(std::floor(halfWidth + 0.5 * scale - 0.5)) - window.firstOffset + 1);
        }
        const double solidAngle = latLongTexelSolidAngle(v, width, height);
        for (int i = window.firstOffset; i < window.firstOffset + offsetCount; ++i) {
            const double c = cosProduct + rowProduct * std::cos(longitudeOffset(i));
            const double weight = solidAngle * lobeWeight(c, inverseRoughnessSquared);
            window.weights.push_back(float(weight));
            weightSum += double(float(weight));
        }
        windows.push_back(std::move(window));
    }
    for (int column = 0; column < output.width; ++column) {
        glm::vec3 weightedRadiance(0.0f);
        for (const RowWindow& window : windows) {
            const glm::vec3* first = &source.tripledRows[size_t(window.sourceRow) * 3 * size_t(width) + size_t(width) +
                                                         size_t(scale * column + window.firstOffset)];
            for (size_t i = 0; i < window.weights.size(); ++i) weightedRadiance += window.weights[i] * first[i];
        }
        output.at(column, row) = glm::vec4(glm::vec3(glm::dvec3(weightedRadiance) / weightSum), 1.0f);
    }
}

}  // namespace

float prefilteredLevelOfRoughness(float m) {
    using std::clamp;
    using std::log2;
    using std::exp2;
    if (std::isnan(m)) return 0.0f;
    return float(DERMIS_PREFILTERED_LEVEL_OF_ROUGHNESS(double(m)));
}

float prefilteredRoughnessOfLevel(float level) {
    using std::exp2;
    return float(DERMIS_PREFILTERED_ROUGHNESS_OF_LEVEL(double(level)));
}

Image resampleLatLongByArea(const Image& map, int width, int height) {
    if (map.empty() || width <= 0 || height <= 0) return Image{};
    Image out = makeImage(width, height, map.colourSpace);
    // Solid angle is separable on a lat-long map: d phi x d cos(theta).
    const Overlaps columns = cellOverlaps(width, map.width, [](double a, double b) { return b - a; });
    const Overlaps rows =
        cellOverlaps(height, map.height, [](double a, double b) { return std::cos(kPi * a) - std::cos(kPi * b); });
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u) {
            glm::dvec4 sum(0.0);
            for (const auto& [sourceRow, rowShare] : rows[size_t(v)])
                for (const auto& [sourceColumn, columnShare] : columns[size_t(u)])
                    sum += rowShare * columnShare * glm::dvec4(map.at(sourceColumn, sourceRow));
            out.at(u, v) = glm::vec4(sum);
        }
    return out;
}

PrefilteredEnvironment PrefilteredEnvironment::build(const Image& map, int threads, const std::string& progressLabel) {
    PrefilteredEnvironment result;
    if (map.empty()) return result;
    // boxed[k]: the base at level k's size, the source of level k.
    std::vector<Image> boxed{resampleLatLongByArea(map, 2 * kPrefilteredBaseHeight, kPrefilteredBaseHeight)};
    for (int k = 1; k < kPrefilteredLevels; ++k)
        boxed.push_back(resampleLatLongByArea(boxed.back(), boxed.back().width / 2, boxed.back().height / 2));
    std::vector<SourceLevel> sources;
    for (const Image& image : boxed) sources.push_back(makeSourceLevel(image));

    result.mLevels.push_back(boxed.front());
    std::vector<std::pair<int, int>> levelRows;  // (level, row) work items
    for (int k = 1; k < kPrefilteredLevels; ++k) {
        result.mLevels.push_back(makeImage(boxed[size_t(k)].width, boxed[size_t(k)].height, map.colourSpace));
        for (int row = 0; row < result.mLevels.back().height; ++row) levelRows.emplace_back(k, row);
    }
    raytrace::parallelFor(
        levelRows.size(), threads,
        [&](size_t item) {
            const auto [k, row] = levelRows[item];
            prefilterRow(sources[size_t(k)], prefilteredRoughnessOfLevel(float(k)), result.mLevels[size_t(k)], row);
        },
        progressLabel);
    return result;
}

glm::vec3 PrefilteredEnvironment::radiance(const glm::vec3& direction, float m) const {
    if (mLevels.empty()) return glm::vec3(0.0f);
    const float level = prefilteredLevelOfRoughness(m);
    const int lower = std::min(int(level), int(mLevels.size()) - 1);
    const int upper = std::min(lower + 1, int(mLevels.size()) - 1);
    const glm::vec2 uv = latLongUv(direction);
    const auto read = [&](int k) {
        return glm::vec3(sampleBilinear(mLevels[size_t(k)], uv, glm::vec4(0.0f), TextureWrap::Repeat, TextureWrap::ClampToEdge));
    };
    return glm::mix(read(lower), read(upper), level - float(lower));
}

}  // namespace dermis
