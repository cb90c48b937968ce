#pragma once
// Keyboard shortcuts, after Chappuis 2011's application (appendix A.2): digits
// switch lights, letters switch effects, a/d/w/s move light 0, h/j turn the
// first character. Keys are ignored while an ImGui text field has focus.

#include "scene/Scene.h"
#include "viewer/ViewerState.h"
#include "viewer/ViewerWindow.h"

#include <vector>

namespace dermis::viewer {

struct KeyHelp {
    const char* keys;
    const char* action;
};

const std::vector<KeyHelp>& keyHelp();
const std::vector<KeyHelp>& mouseHelp();

// Acts on the key presses since the last frame. Light and character
// movements are applied to every scene in `scenes` (A and B stay
// comparable); `camera` gives the axes they move about.
void handleKeys(const std::vector<KeyPress>& presses, ViewerState& state, const Camera& camera,
                const std::vector<Scene*>& scenes);

}  // namespace dermis::viewer
