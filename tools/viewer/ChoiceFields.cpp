#include "viewer/ChoiceFields.h"

#include "scene/SettingsFields.h"

namespace dermis::viewer {
namespace {

// A visitor of scene/SettingsFields.h that keeps the choices and skips the rest.
struct ChoiceCollector {
    std::string pointer;
    std::map<std::string, std::vector<std::string>>& choices;

    template <typename... Ignored>
    void number(Ignored&&...) {}
    template <typename... Ignored>
    void integer(Ignored&&...) {}
    template <typename... Ignored>
    void rule(Ignored&&...) {}
    template <typename... Ignored>
    void boolean(Ignored&&...) {}
    template <typename... Ignored>
    void vec3(Ignored&&...) {}
    template <typename... Ignored>
    void path(Ignored&&...) {}
    template <typename Key, typename Table, typename E>
    void choice(const Key& key, const Table& table, E&) {
        choices[pointer + "/" + std::string(key)] = table.names();
    }
    template <typename Key, typename Group, typename Visit>
    void group(const Key& key, Group& group, Visit visit) {
        ChoiceCollector inner{pointer + "/" + std::string(key), choices};
        visit(group, inner);
    }
};

}  // namespace

const std::map<std::string, std::vector<std::string>>& settingsChoices() {
    static const std::map<std::string, std::vector<std::string>> kChoices = [] {
        std::map<std::string, std::vector<std::string>> choices;
        RenderSettings settings;
        ChoiceCollector collector{"/settings", choices};
        visitSettingsFields(settings, collector);
        return choices;
    }();
    return kChoices;
}

}  // namespace dermis::viewer
