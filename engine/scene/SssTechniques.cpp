#include "scene/SssTechniques.h"

#include <cassert>

namespace dermis {

const std::vector<SssTechniqueInfo>& sssTechniques() {
    static const std::vector<SssTechniqueInfo> kTechniques = [] {
        std::vector<SssTechniqueInfo> techniques = {
            gaussiansTechnique(),
            separableTechnique(),
            diskTechnique(),
            preintegratedTechnique(),
        };
        assert(techniques.size() == kSssTechniques.size());
        for (size_t i = 0; i < techniques.size(); ++i) assert(techniques[i].technique == kSssTechniques.begin()[i].value);
        return techniques;
    }();
    return kTechniques;
}

const SssTechniqueInfo& sssTechniqueInfo(SssTechnique technique) {
    for (const SssTechniqueInfo& info : sssTechniques()) {
        if (info.technique == technique) return info;
    }
    assert(false && "every SssTechnique is registered");
    return sssTechniques().front();
}

}  // namespace dermis
