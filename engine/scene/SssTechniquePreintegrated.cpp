// Pre-integrated skin shading (Penner & Borshukov 2011): the lighting pass
// looks each light's N.L and the surface's curvature up in a table of the
// profile's falloff (sss/PreintegratedTable.h, shaders/include/PreintegratedSkin.glsl);
// no pass blurs anything.
#include "scene/SssTechniques.h"

namespace dermis {

SssTechniqueInfo preintegratedTechnique() {
    SssTechniqueInfo info;
    info.technique = SssTechnique::Preintegrated;
    info.scattersInLighting = true;
    SssChoice choice;
    choice.technique = info.technique;
    info.candidates = {choice};
    return info;
}

}  // namespace dermis
