#pragma once
// Small ImGui helpers shared by the panels. Every helper returns true when
// the user changed the value, and keeps the value inside the range the scene
// file format allows (content/scenes/README.md), so the renderer never sees
// a value the loader would have refused.

#include "core/EnumTable.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis::viewer::widgets {

// `tooltips`, when given, holds one line per option (empty: none), shown while
// the option is hovered.
bool comboString(const char* label, std::string& value, const std::vector<std::string>& options,
                 const std::vector<std::string>& tooltips = {});
// One value of a closed set, shown by its name from `table`, each entry with
// its description as a tooltip.
template <typename E, size_t N>
bool comboEnum(const char* label, const EnumTable<E, N>& table, E& value) {
    std::string name(table.name(value));
    std::vector<std::string> descriptions;
    for (const EnumEntry<E>& entry : table) descriptions.emplace_back(entry.description);
    if (!comboString(label, name, table.names(), descriptions)) return false;
    value = table.parse(name).value_or(value);
    return true;
}
// An odd integer in [lo, hi] (SSS taps).
bool sliderOdd(const char* label, int& value, int lo, int hi);
// A float shown in millimetres, stored in metres.
bool sliderMetresAsMm(const char* label, float& metres, float loMm, float hiMm);
// A linear RGB colour, each channel >= 0; `hdr` allows values above 1.
bool colourLinear(const char* label, glm::vec3& colour, bool hdr);
// A unit direction, edited as azimuth (about +Y) and elevation angles;
// `label` only scopes the widgets' ids.
bool direction(const char* label, glm::vec3& direction);
// "(?)" with a tooltip.
void help(const char* text);
// `text` in a tooltip while the last item is hovered.
void hoverTooltip(const char* text);

}  // namespace dermis::viewer::widgets
