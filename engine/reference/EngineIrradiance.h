#pragma once
// The matched-irradiance mode's sample values: the engine's own texture-space
// irradiance for one character (shaders/ts_irradiance.frag: rgb = E x
// albedo^mix, alpha > 0 where a texel was covered), read at the mesh's raw
// TEXCOORD_0 (before flip_v). The image is linear float, row y at
// v = (y + 0.5) / H (row 0 at v = 0, not flipped), texel x at u = (x + 0.5) / W.
// Reads are bilinear with clamp-to-edge. An empty texel (alpha 0) takes the
// value of the nearest covered texel within kEmptyTexelReachTexels (Euclidean,
// first in row order on ties); a bilinear read averages only the covered or
// filled taps, and a read none of whose taps has a value returns 0 and is
// counted (emptyReads()).

#include "core/Image.h"
#include "core/Result.h"
#include "reference/CharacterSurface.h"
#include "reference/SampleValues.h"

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace dermis::reference {

constexpr int kEmptyTexelReachTexels = 3;

class EngineIrradiance final : public SampleValues {
public:
    // Errors for a size that does not match its texels or a non-finite texel.
    // `surface` must outlive this object.
    static Result<std::unique_ptr<EngineIrradiance>> create(const CharacterSurface& surface, const Image& texture);

    glm::vec3 valueAt(uint32_t triangle, const glm::vec2& b, LightVisibility* visibility) const override;
    // The bilinear read at raw UV (u, v).
    glm::vec3 sampleAt(const glm::vec2& rawUv) const;

    // Texels that had no covered texel within reach (they read as "no value").
    size_t unfilledTexels() const { return mUnfilledTexels; }
    // Reads since creation that found no value in any of their four taps.
    size_t emptyReads() const { return mEmptyReads.load(); }

private:
    EngineIrradiance() = default;

    const CharacterSurface* mSurface = nullptr;
    Image mTexture;                // empty texels filled where a covered one is in reach
    std::vector<uint8_t> mHasValue;  // per texel
    size_t mUnfilledTexels = 0;
    mutable std::atomic<size_t> mEmptyReads{0};
};

}  // namespace dermis::reference
