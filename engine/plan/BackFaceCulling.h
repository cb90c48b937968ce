#pragma once
// When the G-buffer may draw only a character's front faces
// (passes/GBufferPass.cpp; settings.cull_back_faces).

#include "plan/FramePlan.h"

namespace dermis {

// True when no back face of the character can show this frame: its mesh is
// closed and wound outward (mesh/MeshTopology.h), it is static (a pose can
// fold a surface through itself), its transform keeps the winding
// (det > 0), and its world bounds lie wholly beyond the near plane, so that
// the eye is outside every part and the near plane cuts none of them open.
bool mayCullBackFaces(bool closedOutward, const CharacterPlacement& placement, const ViewParams& view);

}  // namespace dermis
