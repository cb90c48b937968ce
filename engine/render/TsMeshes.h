#pragma once
// What the texture-space passes draw each character with: its GpuMesh's
// vertex and index buffers plus a second vertex buffer of UV-layout values
// (scene/UvLayout.h: dP/du, dP/dv and the distance to a chart border), made
// once per character from a read-back of the mesh. Attribute locations:
//   0 position, 1 normal, 2 tangent, 3 uv   (the GpuMesh's, as the G-buffer's)
//   4 dP/du, 5 dP/dv (object units per UV unit), 6 border distance (object units)
// Owned by TextureSpaceCache (passes/TextureSpacePasses.h); a GL context must
// be current.

#include "gl/GlObjects.h"
#include "render/GpuScene.h"

#include <vector>

namespace dermis {

constexpr GLuint kTsLocationDPdu = 4;
constexpr GLuint kTsLocationDPdv = 5;
constexpr GLuint kTsLocationBorder = 6;

struct TsMesh {
    gl::VertexArray vertexArray;
    gl::Buffer layoutBuffer;
    GLuint sourceVertexBuffer = 0;  // the GpuMesh buffer it was made from
    GLsizei indexCount = 0;
    float medianStretch = 0.0f;  // UvLayout's summary, object units per UV unit
    float denseStretch = 0.0f;

    void draw() const;
};

class TsMeshes {
public:
    // The character's TsMesh, made on first use.
    const TsMesh& get(size_t characterIndex, const GpuCharacter& character);

private:
    std::vector<TsMesh> mMeshes;
};

}  // namespace dermis
