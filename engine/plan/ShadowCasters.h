#pragma once
// Which characters a shadow map holds, decided on the CPU (no GL): only what
// can shade something on screen. The receivers are the visible characters
// (FramePlan's CharacterPlacement::visible); each is kept, since it shades
// itself and the others, and the transmittance and texture-space passes read
// its own far side's depth from the map. Another character is kept when it
// can shade a receiver:
//   - directional light: its light-space footprint (its box's corners on the
//     plane across the light) overlaps the receiver's, grown by the penumbra a
//     light of its angular size casts over the depth between them plus
//     kFilterMarginTexels, and its nearest point is nearer the light than the
//     receiver's farthest;
//   - spot and point lights: its bounding sphere meets the capsule from the
//     light to the receiver's bounding sphere, widened by the light's radius
//     and kFilterMarginTexels at the receiver.
// The map is fitted to the receivers with a depth range that reaches the kept
// casters (plan/LightSetup.h), and the shadow cache's key holds only the
// kept casters (plan/ShadowCache.h): a character that cannot shade anything
// on screen is not drawn, and its moving does not make the map stale.

#include "gpu/UniformBlocks.h"
#include "mesh/Mesh.h"

#include <string>
#include <vector>

namespace dermis {

// Shadow-map taps reach this far around a receiver's own texel: PCF 4x4 and
// Poisson 2 texels, the smallest PCSS kernel 1 (shaders/include/Shadows.glsl).
constexpr float kFilterMarginTexels = 4.0f;

struct ShadowCasters {
    std::vector<int> kept;                   // characters drawn into the map, in scene order
    std::vector<std::string> culledBecause;  // per character: why it is not drawn ("" when kept)
    Bounds reach;                            // of the kept characters (meaningful when kept is not empty)
};

// `light`: the light's block with its map fitted around the receivers (it
// gives the map's axes and texel size); bounds and visible have one entry per
// character.
ShadowCasters chooseShadowCasters(const gpu::GpuLight& light, const std::vector<Bounds>& bounds,
                                  const std::vector<bool>& visible);

}  // namespace dermis
