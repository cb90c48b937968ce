#include "core/ImageMetrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace dermis {
namespace {

bool inMask(const std::vector<uint8_t>& mask, size_t i) { return mask.empty() || mask[i] != 0; }

double texelDifference(const glm::vec4& a, const glm::vec4& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double d = std::abs(double(a[c]) - double(b[c]));
        if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
        worst = std::max(worst, d);
    }
    return worst;
}

// A perceptually ordered ramp (dark to bright), linearly interpolated.
glm::vec3 falseColour(double t) {
    static const std::array<glm::vec3, 5> kRamp = {glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0.15f, 0.1f, 0.55f),
                                                   glm::vec3(0.6f, 0.15f, 0.55f), glm::vec3(0.95f, 0.45f, 0.15f),
                                                   glm::vec3(1.0f, 0.95f, 0.4f)};
    const double x = std::clamp(std::isfinite(t) ? t : 1.0, 0.0, 1.0) * double(kRamp.size() - 1);
    const auto i = std::min(static_cast<size_t>(x), kRamp.size() - 2);
    return glm::mix(kRamp[i], kRamp[i + 1], float(x - double(i)));
}

// 3 x 5 pixel glyphs, one row per string, '#' lit.
struct Glyph {
    char c;
    const char* rows[5];
};
const Glyph kGlyphs[] = {
    {'0', {"###", "#.#", "#.#", "#.#", "###"}}, {'1', {".#.", "##.", ".#.", ".#.", "###"}},
    {'2', {"###", "..#", "###", "#..", "###"}}, {'3', {"###", "..#", "###", "..#", "###"}},
    {'4', {"#.#", "#.#", "###", "..#", "..#"}}, {'5', {"###", "#..", "###", "..#", "###"}},
    {'6', {"###", "#..", "###", "#.#", "###"}}, {'7', {"###", "..#", "..#", "..#", "..#"}},
    {'8', {"###", "#.#", "###", "#.#", "###"}}, {'9', {"###", "#.#", "###", "..#", "###"}},
    {'.', {"...", "...", "...", "...", ".#."}}, {'-', {"...", "...", "###", "...", "..."}},
    {'+', {"...", ".#.", "###", ".#.", "..."}}, {'e', {"...", "###", "#.#", "##.", "###"}},
};

void drawText(Image& image, int x, int y, const std::string& text, int scale) {
    for (char c : text) {
        for (const Glyph& glyph : kGlyphs) {
            if (glyph.c != c) continue;
            for (int row = 0; row < 5; ++row) {
                for (int column = 0; column < 3; ++column) {
                    if (glyph.rows[row][column] != '#') continue;
                    for (int dy = 0; dy < scale; ++dy) {
                        for (int dx = 0; dx < scale; ++dx) {
                            const int px = x + column * scale + dx;
                            const int py = y + row * scale + dy;
                            if (px >= 0 && py >= 0 && px < image.width && py < image.height)
                                image.at(px, py) = glm::vec4(1.0f);
                        }
                    }
                }
            }
        }
        x += 4 * scale;
    }
}

std::string label(double value) {
    char text[32];
    if (value == 0.0) return "0";
    if (value >= 1e-3 && value < 1e4) {
        std::snprintf(text, sizeof text, "%.4g", value);
    } else {
        std::snprintf(text, sizeof text, "%.0e", value);
    }
    return text;
}

}  // namespace

double roundUpToNiceNumber(double x) {
    if (!(x > 0.0) || !std::isfinite(x)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        if (step * decade >= x * (1.0 - 1e-12)) return step * decade;
    }
    return 10.0 * decade;
}

double differencePercentile(const Image& reference, const Image& test, const std::vector<uint8_t>& mask,
                            double fraction) {
    if (reference.texels.size() != test.texels.size() || (!mask.empty() && mask.size() != reference.texels.size()))
        return 0.0;
    std::vector<double> differences;
    for (size_t i = 0; i < reference.texels.size(); ++i) {
        if (inMask(mask, i)) differences.push_back(texelDifference(reference.texels[i], test.texels[i]));
    }
    if (differences.empty()) return 0.0;
    const auto k = static_cast<size_t>(std::clamp(fraction, 0.0, 1.0) * double(differences.size() - 1));
    std::nth_element(differences.begin(), differences.begin() + static_cast<std::ptrdiff_t>(k), differences.end());
    return differences[k];
}

Result<ImageDifference> compareImages(const Image& reference, const Image& test, const std::vector<uint8_t>& mask) {
    if (reference.width != test.width || reference.height != test.height || reference.texels.size() != test.texels.size())
        return makeError("image comparison", std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                                                 " against " + std::to_string(test.width) + "x" +
                                                 std::to_string(test.height) + ": sizes differ");
    if (!mask.empty() && mask.size() != reference.texels.size())
        return makeError("image comparison", "the mask has " + std::to_string(mask.size()) + " entries for " +
                                                 std::to_string(reference.texels.size()) + " pixels");
    ImageDifference out;
    double squares = 0.0;
    double referenceSquares = 0.0;
    for (size_t i = 0; i < reference.texels.size(); ++i) {
        if (!inMask(mask, i)) continue;
        ++out.pixels;
        out.maxAbsDifference = std::max(out.maxAbsDifference, texelDifference(reference.texels[i], test.texels[i]));
        for (int c = 0; c < 3; ++c) {
            const double r = reference.texels[i][c];
            const double d = double(test.texels[i][c]) - r;
            squares += std::isfinite(d) ? d * d : std::numeric_limits<double>::infinity();
            if (std::isfinite(r)) {
                referenceSquares += r * r;
                out.peak = std::max(out.peak, r);
            }
        }
    }
    if (out.pixels == 0) return makeError("image comparison", "no pixel selected");
    const double samples = 3.0 * double(out.pixels);
    const double mse = squares / samples;
    out.rmse = std::sqrt(mse);
    const double referenceRms = std::sqrt(referenceSquares / samples);
    out.relativeRmse = referenceRms > 0.0 ? out.rmse / referenceRms : (out.rmse > 0.0 ? INFINITY : 0.0);
    if (!std::isfinite(mse)) {
        out.psnrDb = 0.0;
    } else if (mse <= 0.0) {
        out.psnrDb = kMaxPsnrDb;
    } else {
        out.psnrDb = std::clamp(10.0 * std::log10(out.peak * out.peak / mse), -kMaxPsnrDb, kMaxPsnrDb);
    }
    return out;
}

std::vector<uint8_t> objectMask(const Image& objectAov, long id) {
    std::vector<uint8_t> mask(objectAov.texels.size(), 0);
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = std::lround(objectAov.texels[i].r) == id ? 1 : 0;
    return mask;
}

Image differenceHeatmap(const Image& reference, const Image& test, const std::vector<uint8_t>& mask, double scaleMax) {
    const int barWidth = 16;
    const int labelWidth = 56;
    const int margin = 8;
    Image out;
    out.width = reference.width + margin + barWidth + labelWidth;
    out.height = std::max(reference.height, 60);
    out.colourSpace = ColourSpace::Srgb;
    out.texels.assign(static_cast<size_t>(out.width) * static_cast<size_t>(out.height), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const bool comparable = reference.width == test.width && reference.height == test.height &&
                            reference.texels.size() == test.texels.size() &&
                            (mask.empty() || mask.size() == reference.texels.size());
    if (scaleMax <= 0.0 || !std::isfinite(scaleMax)) {
        double largest = 0.0;
        if (comparable) {
            for (size_t i = 0; i < reference.texels.size(); ++i) {
                const double d = texelDifference(reference.texels[i], test.texels[i]);
                if (inMask(mask, i) && std::isfinite(d)) largest = std::max(largest, d);
            }
        }
        scaleMax = roundUpToNiceNumber(largest);
    }
    for (int y = 0; y < reference.height && comparable; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const size_t i = static_cast<size_t>(y) * static_cast<size_t>(reference.width) + static_cast<size_t>(x);
            const glm::vec3 colour = inMask(mask, i)
                                         ? falseColour(texelDifference(reference.texels[i], test.texels[i]) / scaleMax)
                                         : glm::vec3(0.12f);
            out.at(x, y) = glm::vec4(colour, 1.0f);
        }
    }
    // The scale bar: the ramp from 0 (bottom) to scaleMax (top), three labels.
    const int barX = reference.width + margin;
    const int top = 4;
    const int bottom = out.height - 5;
    for (int y = top; y <= bottom; ++y) {
        const glm::vec3 colour = falseColour(double(bottom - y) / double(bottom - top));
        for (int x = barX; x < barX + barWidth; ++x) out.at(x, y) = glm::vec4(colour, 1.0f);
    }
    const int scale = 2;
    const int textX = barX + barWidth + 4;
    drawText(out, textX, top, label(scaleMax), scale);
    drawText(out, textX, (top + bottom) / 2 - 5, label(scaleMax / 2.0), scale);
    drawText(out, textX, bottom - 10, "0", scale);
    return out;
}

}  // namespace dermis
