#pragma once
// The procedural head's maps, baked in its UV layout from the 3-D point each
// texel maps to, so that features land where the mesh puts them.

#include "core/Image.h"
#include "procedural/ProceduralHead.h"

namespace dermis {

// Skin colour, sRGB-encoded in [0, 1] (ColourSpace::Srgb): a base tone with
// redder cheeks, nose and ears, lips, darker brows and stubble, and mottling.
Image makeHeadAlbedoMap(const HeadMesh& head, int size);

// Pores and fine wrinkles as a tangent-space normal map (ColourSpace::Linear,
// n * 0.5 + 0.5, +Y up the image), in the mesh's own tangent frames.
Image makeHeadNormalMap(const HeadMesh& head, int size);

}  // namespace dermis
