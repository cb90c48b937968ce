#include "viewer/AovDisplay.h"

namespace dermis::viewer {
namespace {
// The procedural head's stretch map (default.json) is about 400 mm per UV
// unit at the median and 900 at the 95th percentile, along u and v; the UV
// sphere's is 314 (v) and up to 628 (u).
constexpr float kStretchDisplayMaxMm = 1000.0f;
}  // namespace

const std::vector<AovChoice>& aovChoices() {
    static const std::vector<AovChoice> kChoices = [] {
        std::vector<AovChoice> choices;
        for (const EnumEntry<Aov>& entry : kAovs) choices.push_back({entry.value, std::string(entry.name)});
        return choices;
    }();
    return kChoices;
}

AovMapping defaultAovMapping(Aov aov, float cameraDistanceM) {
    switch (aov) {
        case Aov::Final: return {DisplayTransform::AsStored, {0.0f, 1.0f}, ""};
        case Aov::Normal: return {DisplayTransform::Range, {-1.0f, 1.0f}, ""};
        case Aov::Depth: return {DisplayTransform::Range, {0.75f * cameraDistanceM, 1.25f * cameraDistanceM}, "m"};
        case Aov::Ao: return {DisplayTransform::Range, {0.0f, 1.0f}, ""};
        case Aov::Thickness: return {DisplayTransform::Range, {0.0f, 20.0f}, "mm"};
        case Aov::Stretch: return {DisplayTransform::Range, {0.0f, kStretchDisplayMaxMm}, "mm"};
        default: return {DisplayTransform::RangeSrgb, {0.0f, 1.0f}, ""};
    }
}

}  // namespace dermis::viewer
