#include "bench/SweepPlan.h"

#include "scene/SceneLoader.h"
#include "scene/SssTechniques.h"

#include <algorithm>
#include <map>

namespace dermis::bench {
namespace {

// The label without the swept SSS sample settings that the configuration's
// screen-space technique does not read ("technique=disk separable_samples=7
// disk_samples=16" -> "technique=disk disk_samples=16"): they were reset.
std::string canonicalLabel(const std::string& label, const Scene& scene) {
    if (scene.settings.mode != SssMode::ScreenSpace) return label;
    const SssTechnique technique = scene.settings.sss.technique;
    std::vector<std::pair<std::string, SssTechnique>> owners;
    for (const SssTechniqueInfo& info : sssTechniques()) {
        for (const SssSampleSetting& setting : info.settings) owners.push_back({std::string(setting.key) + "=", info.technique});
    }
    std::string out;
    size_t start = 0;
    while (start <= label.size()) {
        const size_t end = std::min(label.find(' ', start), label.size());
        const std::string token = label.substr(start, end - start);
        bool reset = false;
        for (const auto& [prefix, owner] : owners) reset = reset || (token.rfind(prefix, 0) == 0 && owner != technique);
        if (!token.empty() && !reset) out += (out.empty() ? "" : " ") + token;
        start = end + 1;
    }
    return out;
}

}  // namespace

Result<std::vector<PlannedConfig>> planConfigs(const std::string& scenePath, const std::vector<std::string>& base,
                                               const std::vector<SweepConfig>& sweep) {
    std::vector<PlannedConfig> planned;
    std::map<std::string, size_t> seen;  // settings JSON + scale -> index
    auto add = [&](const SweepConfig& config, bool isDefault) -> Status {
        std::vector<std::string> overrides = base;
        overrides.insert(overrides.end(), config.overrides.begin(), config.overrides.end());
        auto scene = loadScene(scenePath, overrides);
        if (!scene.ok()) {
            return makeError(scene.error().where, scene.error().what + " (in the configuration " + config.mode + " " +
                                                      config.label + ")");
        }
        SssChoice::fromSettings(scene->settings.sss).canonical().applyTo(scene->settings.sss);
        const std::string identity = sceneToJson(*scene) + "@" + std::to_string(config.scale);
        if (auto found = seen.find(identity); found != seen.end()) {
            planned[found->second].isDefault = planned[found->second].isDefault || isDefault;
            return success();
        }
        seen[identity] = planned.size();
        planned.push_back({config, std::move(*scene), isDefault});
        planned.back().sweep.label = canonicalLabel(config.label, planned.back().scene);
        if (isDefault) planned.back().sweep.label = "default";
        return success();
    };
    for (const EnumEntry<SssMode>& entry : kSssModes) {
        const std::string mode(entry.name);
        bool swept = false;
        for (const auto& config : sweep) swept = swept || config.mode == mode;
        if (!swept) continue;
        SweepConfig shipped;
        shipped.mode = mode;
        shipped.overrides = {"mode=" + mode};
        if (Status ok = add(shipped, true); !ok.ok()) return ok.error();
        for (const auto& config : sweep) {
            if (config.mode != mode) continue;
            if (Status ok = add(config, false); !ok.ok()) return ok.error();
        }
    }
    return planned;
}


}  // namespace dermis::bench
