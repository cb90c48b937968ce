#include "bench/SweepPlan.h"

#include "scene/SceneLoader.h"

#include <map>

namespace dermis::bench {

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
