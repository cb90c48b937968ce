#include "scene/SssTechniques.h"

#include <cassert>

namespace dermis {

// The descriptors, each in its own file.
SssTechniqueInfo gaussiansTechnique();      // scene/SssTechniqueGaussians.cpp
SssTechniqueInfo separableTechnique();      // scene/SssTechniqueSeparable.cpp
SssTechniqueInfo diskTechnique();           // scene/SssTechniqueDisk.cpp
SssTechniqueInfo preintegratedTechnique();  // scene/SssTechniquePreintegrated.cpp

std::vector<SssChoice> sampleCountCandidates(SssTechnique technique, int SssChoice::*member, std::initializer_list<int> counts) {
    std::vector<SssChoice> out;
    for (int count : counts) {
        SssChoice choice;
        choice.technique = technique;
        choice.*member = count;
        out.push_back(choice);
    }
    return out;
}

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
