#include "lean/LeanBake.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

namespace dermis {
namespace {

glm::vec2 bumpCentre(const glm::vec3& encodedNormal) {
    glm::vec3 n = encodedNormal * 2.0f - 1.0f;
    const float length = glm::length(n);
    if (!(length > 1e-6f) || !std::isfinite(length)) return glm::vec2(0.0f);  // NaN fails the first test
    n /= length;
    if (n.z < kLeanMinNormalZ) {
        // Keep the direction in the tangent plane, tilt it up to the limit.
        const float planar = glm::length(glm::vec2(n));
        const float scale = planar > 1e-6f ? std::sqrt(1.0f - kLeanMinNormalZ * kLeanMinNormalZ) / planar : 0.0f;
        n = glm::vec3(glm::vec2(n) * scale, kLeanMinNormalZ);
    }
    return glm::vec2(n) / n.z;
}

// Weights of the source texels that dest texel `i` covers when `source`
// texels shrink to `dest`: the overlap of [i, i + 1) * source / dest with each
// source texel, normalised. `first` receives the first source index.
std::vector<float> footprintWeights(int i, int source, int dest, int& first) {
    const double scale = double(source) / double(dest);
    const double begin = i * scale;
    const double end = (i + 1) * scale;
    first = static_cast<int>(std::floor(begin));
    const int last = std::min(source - 1, static_cast<int>(std::ceil(end)) - 1);
    std::vector<float> weights;
    for (int s = first; s <= last; ++s) {
        const double overlap = std::min(end, double(s + 1)) - std::max(begin, double(s));
        weights.push_back(static_cast<float>(overlap / scale));
    }
    return weights;
}

// The footprints of every dest texel when `source` texels shrink to `dest`.
struct Footprints {
    std::vector<int> firsts;
    std::vector<std::vector<float>> weights;
};

Footprints footprints(int source, int dest) {
    Footprints out;
    out.firsts.resize(static_cast<size_t>(dest));
    out.weights.resize(static_cast<size_t>(dest));
    for (int i = 0; i < dest; ++i)
        out.weights[static_cast<size_t>(i)] = footprintWeights(i, source, dest, out.firsts[static_cast<size_t>(i)]);
    return out;
}

// Each row shrunk to columns.firsts.size() texels.
Image shrinkRows(const Image& source, const Footprints& columns) {
    const int width = static_cast<int>(columns.firsts.size());
    Image out;
    out.width = width;
    out.height = source.height;
    out.colourSpace = source.colourSpace;
    out.texels.assign(static_cast<size_t>(width) * static_cast<size_t>(source.height), glm::vec4(0.0f));
    for (int y = 0; y < source.height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::vector<float>& w = columns.weights[static_cast<size_t>(x)];
            const int first = columns.firsts[static_cast<size_t>(x)];
            glm::vec4 sum(0.0f);
            for (size_t k = 0; k < w.size(); ++k) sum += w[k] * source.at(first + static_cast<int>(k), y);
            out.at(x, y) = sum;
        }
    }
    return out;
}

Image shrinkRows(const Image& source, int width) { return shrinkRows(source, footprints(source.width, width)); }

Image transpose(const Image& image) {
    Image out;
    out.width = image.height;
    out.height = image.width;
    out.colourSpace = image.colourSpace;
    out.texels.resize(image.texels.size());
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) out.at(y, x) = image.at(x, y);
    }
    return out;
}

Status writeMipChain(const std::string& path, const std::vector<Image>& levels) {
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    if (!output) return makeError(path, "no OpenEXR writer: " + OIIO::geterror());
    if (!output->supports("mipmap")) return makeError(path, "the writer cannot store mip-maps");
    for (size_t level = 0; level < levels.size(); ++level) {
        const Image& image = levels[level];
        OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
        spec.tile_width = 64;
        spec.tile_height = 64;
        spec.attribute("compression", "zip");
        // OpenEXR writes a mip-mapped (tiled) file only for a "texture".
        spec.attribute("textureformat", "Plain Texture");
        spec.attribute("openexr:roundingmode", 0);
        const auto mode = level == 0 ? OIIO::ImageOutput::Create : OIIO::ImageOutput::AppendMIPLevel;
        if (!output->open(path, spec, mode)) return makeError(path, "could not open for writing: " + output->geterror());
        if (!output->write_image(OIIO::TypeDesc::FLOAT, image.texels.data()))
            return makeError(path, "could not write mip level " + std::to_string(level) + ": " + output->geterror());
    }
    if (!output->close()) return makeError(path, "could not finish the file: " + output->geterror());
    return success();
}

}  // namespace

glm::vec4 leanFirstMoments(const glm::vec3& encodedNormal) {
    const glm::vec2 b = bumpCentre(encodedNormal);
    return glm::vec4(b.x, b.y, b.x * b.x, b.y * b.y);
}

float leanCrossMoment(const glm::vec3& encodedNormal) {
    const glm::vec2 b = bumpCentre(encodedNormal);
    return b.x * b.y;
}

int leanMipLevelCount(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
    return levels;
}

Image leanDownsample(const Image& level) {
    const int width = std::max(1, level.width / 2);
    const int height = std::max(1, level.height / 2);
    // Rows, then columns through a transpose: each pass a 1-D area average.
    return transpose(shrinkRows(transpose(shrinkRows(level, width)), height));
}

Status bakeLeanLevels(const Image& normalMap, float baseRoughness, const LeanLevelSink& onLevel) {
    if (normalMap.empty() || normalMap.width <= 0 || normalMap.height <= 0 ||
        normalMap.texels.size() != static_cast<size_t>(normalMap.width) * static_cast<size_t>(normalMap.height)) {
        return makeError("LEAN bake", "the normal map is empty");
    }
    if (!(baseRoughness >= 0.0f && baseRoughness <= 1.0f)) {
        return makeError("LEAN bake", "base roughness must be a Beckmann m in [0, 1]");
    }
    const float baseVariance = 0.5f * baseRoughness * baseRoughness;
    // Level 0's rows [first, first + count) as two images.
    auto momentRows = [&](int first, int count, Image& lean1, Image& lean2) {
        lean1.width = lean2.width = normalMap.width;
        lean1.height = lean2.height = count;
        lean1.colourSpace = lean2.colourSpace = ColourSpace::Linear;
        const size_t begin = static_cast<size_t>(first) * static_cast<size_t>(normalMap.width);
        const size_t size = static_cast<size_t>(count) * static_cast<size_t>(normalMap.width);
        lean1.texels.resize(size);
        lean2.texels.resize(size);
        for (size_t i = 0; i < size; ++i) {
            const glm::vec2 b = bumpCentre(glm::vec3(normalMap.texels[begin + i]));
            lean1.texels[i] = glm::vec4(b.x, b.y, b.x * b.x, b.y * b.y);
            lean2.texels[i] = glm::vec4(b.x * b.y, baseVariance, 0.0f, 1.0f);
        }
    };

    // Level 1 as leanDownsample makes it (rows shrunk, then columns, the same
    // weights added in the same order), accumulated from each band of level 0
    // as it is made: a destination row sums its source rows in their order.
    const int levels = leanMipLevelCount(normalMap.width, normalMap.height);
    const int width = std::max(1, normalMap.width / 2);
    const int height = std::max(1, normalMap.height / 2);
    const Footprints columns = footprints(normalMap.width, width);
    const Footprints rows = footprints(normalMap.height, height);
    Image lean1;
    Image lean2;
    lean1.width = lean2.width = width;
    lean1.height = lean2.height = height;
    lean1.colourSpace = lean2.colourSpace = ColourSpace::Linear;
    if (levels > 1) {
        lean1.texels.assign(static_cast<size_t>(width) * static_cast<size_t>(height), glm::vec4(0.0f));
        lean2.texels.assign(lean1.texels.size(), glm::vec4(0.0f));
    }
    int firstDestRow = 0;  // the first destination row whose footprint has not ended
    Image band1;
    Image band2;
    for (int first = 0; first < normalMap.height; first += kLeanBandRows) {
        momentRows(first, std::min(kLeanBandRows, normalMap.height - first), band1, band2);
        onLevel(0, first, band1, band2);
        if (levels == 1) continue;
        const Image shrunk1 = shrinkRows(band1, columns);
        const Image shrunk2 = shrinkRows(band2, columns);
        for (int r = 0; r < band1.height; ++r) {
            const int source = first + r;
            while (firstDestRow < height &&
                   rows.firsts[size_t(firstDestRow)] + int(rows.weights[size_t(firstDestRow)].size()) <= source)
                ++firstDestRow;
            for (int y = firstDestRow; y < height && rows.firsts[size_t(y)] <= source; ++y) {
                const float weight = rows.weights[size_t(y)][size_t(source - rows.firsts[size_t(y)])];
                for (int x = 0; x < width; ++x) {
                    lean1.at(x, y) += weight * shrunk1.at(x, r);
                    lean2.at(x, y) += weight * shrunk2.at(x, r);
                }
            }
        }
    }
    for (int level = 1; level < levels; ++level) {
        onLevel(level, 0, lean1, lean2);
        if (level + 1 < levels) {
            lean1 = leanDownsample(lean1);
            lean2 = leanDownsample(lean2);
        }
    }
    return success();
}

Result<LeanMaps> bakeLeanMaps(const Image& normalMap, float baseRoughness) {
    LeanMaps maps;
    const Status baked =
        bakeLeanLevels(normalMap, baseRoughness, [&](int level, int firstRow, const Image& lean1, const Image& lean2) {
            if (firstRow == 0) {
                maps.lean1.push_back(lean1);
                maps.lean2.push_back(lean2);
                return;
            }
            Image& whole1 = maps.lean1[static_cast<size_t>(level)];
            Image& whole2 = maps.lean2[static_cast<size_t>(level)];
            whole1.texels.insert(whole1.texels.end(), lean1.texels.begin(), lean1.texels.end());
            whole2.texels.insert(whole2.texels.end(), lean2.texels.begin(), lean2.texels.end());
            whole1.height += lean1.height;
            whole2.height += lean2.height;
        });
    if (!baked.ok()) return baked.error();
    return maps;
}

Status saveLeanMaps(const std::string& prefix, const LeanMaps& maps) {
    if (maps.lean1.empty() || maps.lean1.size() != maps.lean2.size()) return makeError(prefix, "no LEAN maps to save");
    const std::filesystem::path folder = std::filesystem::path(prefix).parent_path();
    std::error_code error;
    if (!folder.empty()) std::filesystem::create_directories(folder, error);
    if (error) return makeError(prefix, "could not create the directory: " + error.message());
    if (const Status first = writeMipChain(prefix + "_lean1.exr", maps.lean1); !first.ok()) return first;
    return writeMipChain(prefix + "_lean2.exr", maps.lean2);
}

Result<std::vector<Image>> loadMipChain(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path);
    if (!input) return makeError(path, "not an image OpenImageIO can read: " + OIIO::geterror());
    std::vector<Image> levels;
    for (int level = 0; input->seek_subimage(0, level); ++level) {
        const OIIO::ImageSpec& spec = input->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxImageDimension || spec.height > kMaxImageDimension)
            return makeError(path, "mip level " + std::to_string(level) + " has an unsupported size");
        Image image;
        image.width = spec.width;
        image.height = spec.height;
        std::vector<float> raw(static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height) * 4, 0.0f);
        const int channels = std::min(spec.nchannels, 4);
        if (!input->read_image(0, level, 0, channels, OIIO::TypeFloat, raw.data(), 4 * sizeof(float)))
            return makeError(path, "could not read mip level " + std::to_string(level) + ": " + input->geterror());
        image.texels.resize(raw.size() / 4);
        for (size_t i = 0; i < image.texels.size(); ++i) {
            glm::vec4 t(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], channels == 4 ? raw[4 * i + 3] : 1.0f);
            for (int c = 0; c < 4; ++c) t[c] = std::isfinite(t[c]) ? t[c] : 0.0f;
            image.texels[i] = t;
        }
        levels.push_back(std::move(image));
    }
    if (levels.empty()) return makeError(path, "no image data");
    return levels;
}

}  // namespace dermis
