// The viewer offers every closed set of the settings as a list
// (tools/viewer/ChoiceFields.h): each string setting that the loader refuses
// an unknown word for has a list in the panels, and the loader accepts every
// word of that list. The loader is the independent side: its refusals, not
// the field lists the viewer reads. (Before, the lists were written by hand
// and the SSS technique and the tone map were text fields.)
#include "viewer/ChoiceFields.h"

#include "scene/SceneLoader.h"

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace dermis;

namespace {

// "/settings/sss/blur" -> "settings.sss.blur"
std::string overridePath(const std::string& pointer) {
    std::string path = pointer.substr(1);
    for (char& c : path) c = c == '/' ? '.' : c;
    return path;
}

void stringSettings(const nlohmann::json& value, const std::string& pointer, std::vector<std::string>& out) {
    if (value.is_string()) out.push_back(pointer);
    if (!value.is_object()) return;
    for (const auto& [key, child] : value.items()) stringSettings(child, pointer + "/" + key, out);
}

}  // namespace

TEST(ViewerChoices, EveryClosedSetOfTheSettingsIsAListOfTheWordsTheLoaderAccepts) {
    auto scene = loadScene(test::contentScene("default.json"));
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const nlohmann::json document = nlohmann::json::parse(sceneToJson(*scene));
    std::vector<std::string> strings;
    stringSettings(document.at("settings"), "/settings", strings);
    ASSERT_GE(strings.size(), 6u) << "the default scene's document lists every setting";

    const auto& choices = viewer::settingsChoices();
    int closedSets = 0;
    for (const std::string& pointer : strings) {
        const std::string path = overridePath(pointer);
        const bool refused = !parseSceneWithOverrides(sceneToJson(*scene), "default.json", {path + "=not-a-word"}).ok();
        const auto listed = choices.find(pointer);
        if (!refused) {
            EXPECT_EQ(listed, choices.end()) << pointer << " takes any text, yet the viewer lists choices for it";
            continue;
        }
        ++closedSets;
        ASSERT_NE(listed, choices.end()) << pointer << " is a closed set, and the viewer offers a text field for it";
        EXPECT_GE(listed->second.size(), 2u) << pointer;
        for (const std::string& word : listed->second) {
            const auto accepted = parseSceneWithOverrides(sceneToJson(*scene), "default.json", {path + "=" + word});
            EXPECT_TRUE(accepted.ok()) << pointer << " = " << word << ": " << accepted.error().message();
        }
    }
    // mode, tone_map, shadow.filter, sss.variant, sss.blur, sss.technique at least.
    EXPECT_GE(closedSets, 6);
    EXPECT_EQ(static_cast<size_t>(closedSets), choices.size()) << "a listed setting is not in the scene's document";
}
