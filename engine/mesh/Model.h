#pragma once
// A character's geometry and maps as they leave a loader: one merged triangle
// mesh (node transforms already applied; with a rig, posed in its rest pose)
// plus the maps its material uses, and what moves its vertices (anim/Rig.h;
// empty for a static model). An empty Image means the material has no such map.

#include "anim/Rig.h"
#include "core/Image.h"
#include "mesh/Mesh.h"

namespace dermis {

struct Model {
    MeshData mesh;
    Image albedoMap;             // sRGB colour
    Image normalMap;             // tangent space, linear, +Y up (OpenGL style), encoded as n * 0.5 + 0.5
    Image metallicRoughnessMap;  // glTF convention: G = roughness, B = metallic, linear
    Rig rig;
};

}  // namespace dermis
