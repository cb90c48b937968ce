#include "bench/ErrorCauses.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dermis::bench {

std::vector<uint8_t> classifyRegions(int width, int height, const std::vector<int>& objectIds,
                                     const std::vector<bool>& isSss, const Image& thicknessMm) {
    const size_t pixels = size_t(width) * size_t(height);
    std::vector<uint8_t> regions(pixels, kNoRegion);
    if (objectIds.size() != pixels) return regions;
    auto idAt = [&](int x, int y) { return objectIds[size_t(y) * size_t(width) + size_t(x)]; };
    auto sss = [&](int id) { return id > 0 && size_t(id) < isSss.size() && isSss[size_t(id)]; };
    const bool haveThickness = thicknessMm.width == width && thicknessMm.height == height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int id = idAt(x, y);
            if (!sss(id)) continue;
            bool nearEdge = false;
            for (int dy = -kSilhouetteBandPx; dy <= kSilhouetteBandPx && !nearEdge; ++dy) {
                for (int dx = -kSilhouetteBandPx; dx <= kSilhouetteBandPx && !nearEdge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    // The frame's border is not an edge of the surface.
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    nearEdge = idAt(nx, ny) != id;
                }
            }
            ErrorRegion region = ErrorRegion::Rest;
            if (nearEdge) {
                region = ErrorRegion::Silhouette;
            } else if (haveThickness) {
                const float mm = thicknessMm.at(x, y).r;
                // A ray that leaves the part without a hit (NaN, inf) is thick.
                if (mm < kThinUnderMm) region = ErrorRegion::ThinUnder4Mm;
                else if (mm < kThickFromMm) region = ErrorRegion::Thin4To8Mm;
            }
            regions[size_t(y) * size_t(width) + size_t(x)] = static_cast<uint8_t>(region);
        }
    }
    return regions;
}

size_t dropUncovered(std::vector<uint8_t>& regions, const std::vector<const Image*>& references) {
    size_t dropped = 0;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (regions[i] == kNoRegion) continue;
        for (const Image* reference : references) {
            if (reference->texels.size() == regions.size() && !(reference->texels[i].a >= 1.0f)) {
                regions[i] = kNoRegion;
                ++dropped;
                break;
            }
        }
    }
    return dropped;
}

std::vector<uint8_t> regionMask(const std::vector<uint8_t>& regions, ErrorRegion region) {
    std::vector<uint8_t> mask(regions.size(), 0);
    for (size_t i = 0; i < regions.size(); ++i) {
        mask[i] = regions[i] != kNoRegion && (region == ErrorRegion::All || regions[i] == uint8_t(region)) ? 1 : 0;
    }
    return mask;
}

double CauseErrors::relativeRmse(ErrorCause cause, ErrorRegion region) const {
    const auto& figure = at(cause, region);
    return figure ? figure->relativeRmse : std::numeric_limits<double>::quiet_NaN();
}

void measureCause(CauseErrors& errors, ErrorCause cause, const Image& reference, const Image& test,
                  const std::vector<uint8_t>& regions) {
    for (const EnumEntry<ErrorRegion>& region : kErrorRegions) {
        auto difference = compareImages(reference, test, regionMask(regions, region.value));
        errors.table[size_t(cause)][size_t(region.value)] =
            difference.ok() ? std::optional<ImageDifference>(*difference) : std::nullopt;
    }
}

Image addImages(const Image& reference, const Image& change) {
    Image sum = reference;
    if (change.width != reference.width || change.height != reference.height) return sum;
    for (size_t i = 0; i < sum.texels.size(); ++i) {
        sum.texels[i] = glm::vec4(glm::vec3(reference.texels[i]) + glm::vec3(change.texels[i]), reference.texels[i].a);
    }
    return sum;
}

}  // namespace dermis::bench
