#pragma once
// The settings whose values are a closed set (a `choice` in
// scene/SettingsFields.h), by JSON pointer ("/settings/tone_map"), each with
// the names it may take. Collected from the field lists themselves, so that a
// new choice is a list in the panels from the start, never a text field.
// No ImGui here (unit-tested).

#include <map>
#include <string>
#include <vector>

namespace dermis::viewer {

const std::map<std::string, std::vector<std::string>>& settingsChoices();

}  // namespace dermis::viewer
