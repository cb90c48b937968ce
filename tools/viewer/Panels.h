#pragma once
// The settings panels, one function per group, grouped by pass. Each draws
// its widgets into the current ImGui window and edits the scene in place;
// it returns true when it changed something. Ranges follow the scene file
// format (content/scenes/README.md).

#include "render/FrameTimings.h"
#include "plan/SceneGeometry.h"
#include "scene/Scene.h"
#include "viewer/SceneJson.h"
#include "viewer/ViewerState.h"

namespace dermis::viewer {

// Scene groups (ScenePanels.cpp).
bool lightsPanel(Scene& scene);
bool materialsPanel(Scene& scene);
bool charactersPanel(Scene& scene);
bool cameraPanel(Camera& camera);

// Per-pass settings (SettingsPanels.cpp).
// Panels that take `error` set a choice through the loader (JsonFields.h) and
// report its refusal there.
bool shadowPanel(Scene& scene, std::string& error);
// The settings, each character's profile and (read-only, from `reports`, the
// side's last frame) the SSS choice each character renders with.
bool sssPanel(Scene& scene, const std::vector<CharacterReport>& reports, std::string& error);
bool transmittancePanel(TransmittanceSettings& transmittance);
bool ssaoPanel(Scene& scene);  // global and per character
bool framePanel(Scene& scene);  // exposure, ambient, background, energy conservation
// Settings keys without a typed panel (the SSS mode, texture-space settings ...), by their JSON type.
bool otherSettingsPanel(Scene& scene, std::string& error);
bool hasOtherSettings(const Scene& scene);

// The environment light's source, intensity, rotation, background, occlusion,
// specular and SH bands (EnvironmentPanel.cpp). `edit` holds the map file being
// typed and the latest refusal (Variant::takeRefusedEnvironment).
bool environmentPanel(Scene& scene, EnvironmentEdit& edit);

// Play / pause, the frame time and each animated character's clip (AnimationPanel.cpp).
// `geometry` is the rendered scene's (null before its first frame).
bool animationPanel(ViewerState& state, Scene& scene, const SceneGeometry* geometry);
// Moves the frame time on by elapsedS x the playback speed while playing.
void advanceAnimationTime(ViewerState& state, float elapsedS);

// The viewer's own groups (ViewerPanels.cpp).
// `differences` between A and B are shown while comparing.
void viewPanel(ViewerState& state, Scene& a, Scene& b, const std::vector<SceneDifference>& differences,
               float cameraDistanceM);
void effectsPanel(ViewerState& state, const Scene& scene);
void savePanel(ViewerState& state);
void shaderPanel(ViewerState& state, const std::string& shaderDirectory);
void keysPanel();

}  // namespace dermis::viewer
