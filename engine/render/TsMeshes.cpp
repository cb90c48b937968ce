#include "render/TsMeshes.h"

#include "gpu/UniformBlocks.h"

#include <algorithm>
#include <cstddef>

namespace dermis {
namespace {

struct LayoutVertex {
    glm::vec3 dPdu;
    glm::vec3 dPdv;
    float borderDistance;
    glm::vec4 seamContinuation;
    float buried;
};

TsMesh makeTsMesh(const GpuCharacter& character, const UvLayout& layout) {
    std::vector<LayoutVertex> vertices(layout.dPdu.size());
    for (size_t v = 0; v < vertices.size(); ++v) {
        vertices[v] = {layout.dPdu[v], layout.dPdv[v], layout.borderDistance[v], layout.seamContinuation[v],
                       v < layout.buried.size() ? float(layout.buried[v]) : 0.0f};
    }

    TsMesh out;
    out.sourceVertexBuffer = character.mesh.vertexBuffer.get();
    out.sourceLayout = &layout;
    out.indexCount = character.mesh.indexCount;
    out.layoutBuffer = gl::createBuffer("texture space: " + character.name + " UV layout");
    glNamedBufferStorage(out.layoutBuffer.get(), static_cast<GLsizeiptr>(std::max<size_t>(vertices.size(), 1) * sizeof(LayoutVertex)),
                         vertices.empty() ? nullptr : vertices.data(), 0);

    out.vertexArray = gl::createVertexArray("texture space: " + character.name);
    const GLuint vao = out.vertexArray.get();
    glVertexArrayVertexBuffer(vao, 0, character.mesh.vertexBuffer.get(), 0, sizeof(Vertex));
    glVertexArrayVertexBuffer(vao, 1, out.layoutBuffer.get(), 0, sizeof(LayoutVertex));
    // An animated character's derivatives are the skinning pass's, deformed with the mesh.
    const bool animated = !character.rig.empty();
    if (animated) glVertexArrayVertexBuffer(vao, 2, character.rig.derivatives.get(), 0, DERMIS_SKIN_DERIVATIVE_FLOATS * sizeof(float));
    glVertexArrayVertexBuffer(vao, 3, character.mesh.colourBuffer.get(), 0, sizeof(glm::vec4));
    glVertexArrayElementBuffer(vao, character.mesh.indexBuffer.get());
    struct Attribute {
        GLuint location;
        GLuint binding;
        GLint components;
        size_t offset;
    };
    const Attribute attributes[] = {{0, 0, 3, offsetof(Vertex, position)},
                                    {1, 0, 3, offsetof(Vertex, normal)},
                                    {2, 0, 4, offsetof(Vertex, tangent)},
                                    {3, 0, 2, offsetof(Vertex, uv)},
                                    {kTsLocationDPdu, animated ? 2u : 1u, 3, animated ? 0 : offsetof(LayoutVertex, dPdu)},
                                    {kTsLocationDPdv, animated ? 2u : 1u, 3, animated ? 3 * sizeof(float) : offsetof(LayoutVertex, dPdv)},
                                    {kTsLocationBorder, 1, 1, offsetof(LayoutVertex, borderDistance)},
                                    {kColourLocation, 3, 4, 0},
                                    {kTsLocationSeamContinuation, 1, 4, offsetof(LayoutVertex, seamContinuation)},
                                    {kTsLocationBuried, 1, 1, offsetof(LayoutVertex, buried)}};
    for (const Attribute& a : attributes) {
        glEnableVertexArrayAttrib(vao, a.location);
        glVertexArrayAttribFormat(vao, a.location, a.components, GL_FLOAT, GL_FALSE, static_cast<GLuint>(a.offset));
        glVertexArrayAttribBinding(vao, a.location, a.binding);
    }
    return out;
}

}  // namespace

void TsMesh::draw() const {
    glBindVertexArray(vertexArray.get());
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
}

void TsMeshes::prepare(size_t characterIndex, const GpuCharacter& character, const UvLayout& layout) {
    if (mMeshes.size() <= characterIndex) mMeshes.resize(characterIndex + 1);
    TsMesh& mesh = mMeshes[characterIndex];
    if (!mesh.vertexArray.isValid() || mesh.sourceVertexBuffer != character.mesh.vertexBuffer.get() ||
        mesh.sourceLayout != &layout) {
        mesh = makeTsMesh(character, layout);
    }
}

}  // namespace dermis
