#include "stress/InvariantJson.h"

namespace dermis::stress {

nlohmann::ordered_json countsJson(const InvariantReport& report) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& entry : kInvariants) {
        const InvariantTally& t = report[entry.value];
        out[std::string(entry.name)] = {{"checked", t.checked}, {"violated", t.violated}};
    }
    return out;
}

nlohmann::ordered_json violationsJson(const InvariantReport& report) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& entry : kInvariants) {
        const InvariantTally& t = report[entry.value];
        if (t.violated == 0) continue;
        out[std::string(entry.name)] = {{"checked", t.checked}, {"violated", t.violated}, {"details", t.details}};
    }
    return out;
}

std::string countsLine(const InvariantReport& report) {
    std::string line;
    for (const auto& entry : kInvariants) {
        const InvariantTally& t = report[entry.value];
        if (!line.empty()) line += ", ";
        line += std::string(entry.name) + " " + std::to_string(t.checked) + "/" + std::to_string(t.violated);
    }
    return line + " checked/violated";
}

}  // namespace dermis::stress
