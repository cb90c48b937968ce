#pragma once
// Measures a render's error by cause and region (bench/ErrorCauses.h) for
// `dermis bench` and `dermis compare --errors`: the references come from
// ReferenceImages, the SSS-off render of each configuration from the session
// (rendered once per distinct configuration), and the regions from the
// object-id AOV and the reference's thickness.

#include "measure/ReferenceImages.h"
#include "measure/Session.h"

#include "bench/ErrorCauses.h"
#include "core/Image.h"
#include "core/Result.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace dermis::measure {

class CauseMeter {
public:
    // Computes (or reuses) the references of the session's current scene at
    // the references' size; `fullReference` replaces the full one when given.
    static Result<CauseMeter> create(Session& session, ReferenceImages& references,
                                     std::optional<Image> fullReference = std::nullopt);

    // The error of `diffuse` (the diffuse AOV of the session's current
    // settings, rendered at renderWidth x renderHeight and resampled to the
    // references' size). Renders the same settings with SSS off (once per
    // distinct configuration) and restores the session's settings.
    Result<bench::CauseErrors> measure(Session& session, const Image& diffuse, int renderWidth, int renderHeight);

    const Image& fullReference() const { return mFull; }
    // SSS pixels of the render that the references do not cover fully (the
    // background or another character at the centre, or a partly covered
    // box-filtered pixel): left out of every figure.
    size_t uncoveredPixels() const { return mUncoveredPixels; }
    const std::vector<uint8_t>& regions() const { return mRegions; }
    // 1 on every SSS pixel.
    std::vector<uint8_t> sssMask() const { return bench::regionMask(mRegions, bench::ErrorRegion::All); }

private:
    CauseMeter(ReferenceImages& references) : mReferences(&references) {}
    Result<Image> renderSssOff(Session& session, int renderWidth, int renderHeight);

    ReferenceImages* mReferences;
    Image mFull;
    Image mSssOff;
    std::vector<uint8_t> mRegions;
    size_t mUncoveredPixels = 0;
    std::map<std::string, Image> mSssOffRenders;  // configuration (SSS off) and size -> diffuse
    // Whether the scene the references were made for scatters: a configuration
    // that turns SSS off is scored against that scene's scattering change, so
    // that leaving out SSS shows as scatter error instead of a perfect 0.
    bool mSceneScatters = true;
};

}  // namespace dermis::measure
