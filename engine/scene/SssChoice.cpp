#include "scene/SssChoice.h"

#include "core/Limits.h"
#include "scene/Scene.h"
#include "scene/SssTechniques.h"

namespace dermis {

SssChoice SssChoice::fromSettings(const SssSettings& settings) {
    SssChoice choice;
    choice.technique = settings.technique;
    for (const SssTechniqueInfo& info : sssTechniques()) {
        for (const SssSampleSetting& setting : info.settings) choice.*setting.choice = settings.*setting.setting;
    }
    return choice;
}

SssChoice SssChoice::finest() {
    SssChoice choice = fromSettings(SssSettings{});
    choice.technique = SssTechnique::Gaussians;
    choice.taps = kMaxBlurTaps;
    choice.gaussians = kMaxProfileGaussians;
    return choice;
}

SssChoice SssChoice::canonical() const {
    SssChoice out = fromSettings(SssSettings{});
    out.technique = technique;
    for (const SssSampleSetting& setting : sssTechniqueInfo(technique).settings) out.*setting.choice = this->*setting.choice;
    return out;
}

void SssChoice::applyTo(SssSettings& settings) const {
    settings.technique = technique;
    for (const SssTechniqueInfo& info : sssTechniques()) {
        for (const SssSampleSetting& setting : info.settings) settings.*setting.setting = this->*setting.choice;
    }
}

bool SssChoice::operator==(const SssChoice& other) const {
    if (technique != other.technique) return false;
    for (const SssTechniqueInfo& info : sssTechniques()) {
        for (const SssSampleSetting& setting : info.settings) {
            if (this->*setting.choice != other.*setting.choice) return false;
        }
    }
    return true;
}

nlohmann::ordered_json sssChoiceJson(const SssChoice& choice) {
    nlohmann::ordered_json json{{"technique", std::string(kSssTechniques.name(choice.technique))}};
    for (const SssTechniqueInfo& info : sssTechniques()) {
        for (const SssSampleSetting& setting : info.settings) json[setting.key] = choice.*setting.choice;
    }
    return json;
}

std::string describeSssChoice(const SssChoice& choice) {
    std::string out(kSssTechniques.name(choice.technique));
    for (const SssSampleSetting& setting : sssTechniqueInfo(choice.technique).settings) {
        out += " " + std::string(setting.label) + "=" + std::to_string(choice.*setting.choice);
    }
    return out;
}

}  // namespace dermis
