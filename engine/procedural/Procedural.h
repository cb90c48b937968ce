#pragma once
// The embedded default content: meshes and maps built from code, so the demo
// needs no files and no downloads. Sizes are in metres (metresPerUnit = 1).
//
//   "head"   a head-like character about 0.2 m wide with thin ears, +Y up, face
//            toward +Z, UV-mapped without overlaps (for texture-space SSS),
//            with a skin albedo map and a pore-scale normal map.
//   "nodding_head"  the head with a two-joint rig and a looping 4 s clip,
//            "idle", that turns and nods it (procedural/ProceduralRig.h).
//   "plane"  a 1 m x 1 m square in the XZ plane, normal +Y, UV [0,1]^2.
//   "sphere" a UV sphere of radius 0.1 m, u along longitude, v along latitude.
//   "wedge"  a thin wedge whose thickness grows linearly from 1 mm to 20 mm
//            along +X over 0.2 m, 0.1 m deep (for the transmittance tests).

#include "core/Result.h"
#include "mesh/Model.h"

#include <string>
#include <vector>

namespace dermis {

std::vector<std::string> proceduralModelNames();

// Errors for an unknown name (the message lists the known ones).
Result<Model> makeProceduralModel(const std::string& name);

}  // namespace dermis
