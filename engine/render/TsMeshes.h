#pragma once
// What the texture-space passes draw each character with: its GpuMesh's
// vertex and index buffers plus a second vertex buffer of UV-layout values
// (mesh/UvLayout.h: dP/du, dP/dv, the distance to a chart border and the
// seam's continuation), made
// once per character from the layout analysed on the CPU mesh
// (plan/SceneGeometry.h). Attribute locations:
//   0 position, 1 normal, 2 tangent, 3 uv   (the GpuMesh's, as the G-buffer's)
//   4 dP/du, 5 dP/dv (object units per UV unit), 6 border distance (object units)
//   7 colour (COLOR_0, the GpuMesh's colour buffer)
//   8-10 the environment's SH transfer where it is attached (DERMIS_LOCATION_TRANSFER)
//   11 seam continuation (UV across the nearest border, 1 where it is a seam, the seam's turn)
//   12 buried (1 inside the body)
// An animated character's dP/du and dP/dv come instead from its GpuRig's
// derivatives, which the skinning pass deforms with the mesh each pose, so
// its stretch map follows the deformation (the border distances stay the
// rest pose's).
// Owned by the frame resources (render/FrameResources.h), which make them in
// the prepare step; a GL context must be current.

#include "gl/GlObjects.h"
#include "render/GpuScene.h"
#include "mesh/UvLayout.h"
#include "include/SharedConstants.glsl"

#include <vector>

namespace dermis {

constexpr GLuint kTsLocationDPdu = 4;
constexpr GLuint kTsLocationDPdv = 5;
constexpr GLuint kTsLocationBorder = 6;
constexpr GLuint kTsLocationSeamContinuation = DERMIS_LOCATION_TS_SEAM;
constexpr GLuint kTsLocationBuried = DERMIS_LOCATION_TS_BURIED;
// GpuEnvironment::attachTransfer binds its three locations on a TsMesh too.
static_assert(kTsLocationSeamContinuation >= DERMIS_LOCATION_TRANSFER + 3 && kTsLocationBuried >= DERMIS_LOCATION_TRANSFER + 3,
              "texture space's attributes must not share the SH transfer's locations");

struct TsMesh {
    gl::VertexArray vertexArray;
    gl::Buffer layoutBuffer;
    GLuint sourceVertexBuffer = 0;  // the GpuMesh buffer it was made from
    const UvLayout* sourceLayout = nullptr;  // and the layout
    GLsizei indexCount = 0;

    void draw() const;
};

class TsMeshes {
public:
    // Makes the character's TsMesh unless it was made from this GpuMesh and layout already.
    void prepare(size_t characterIndex, const GpuCharacter& character, const UvLayout& layout);
    // The character's TsMesh; prepare() made it.
    const TsMesh& get(size_t characterIndex) const { return mMeshes[characterIndex]; }

private:
    std::vector<TsMesh> mMeshes;
};

}  // namespace dermis
