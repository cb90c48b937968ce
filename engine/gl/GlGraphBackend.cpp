#include "gl/GlGraphBackend.h"

#include <string>

namespace dermis::gl {

graph::BackendTexture GlGraphBackend::acquireTexture(const graph::TextureDesc& desc, std::string_view debugName) {
    const GLuint texture = mPool.acquire(desc);
    glObjectLabel(GL_TEXTURE, texture, static_cast<GLsizei>(debugName.size()), debugName.data());
    return texture;
}

void GlGraphBackend::releaseTexture(graph::BackendTexture texture, const graph::TextureDesc& desc) {
    mPool.release(texture, desc);
}

void GlGraphBackend::beginPass(std::string_view passName) {
    const std::string name(passName);
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name.c_str());
    mProfiler.beginPass(name);
    if (mFrameEnded) mFramePasses.clear();
    mFrameEnded = false;
    mFramePasses.push_back(name);
    mSanitise.beginPass(passName);
}

void GlGraphBackend::endPass() {
    mSanitise.endPass();
    mProfiler.endPass();
    glPopDebugGroup();
}

void GlGraphBackend::passWrote(std::string_view passName, std::string_view textureName, graph::BackendTexture texture,
                               const graph::TextureDesc& desc) {
    if (mInspector) mInspector(passName, textureName, texture, desc);
}

void GlGraphBackend::endFrame() {
    mFrameEnded = true;
    for (GLuint texture : mPool.endFrame()) mFramebuffers.forget(texture);
}

}  // namespace dermis::gl
