#include "gl/FramebufferCache.h"

#include <algorithm>

namespace dermis::gl {

GLuint FramebufferCache::bind(const Attachments& attachments) {
    for (const Entry& entry : mEntries) {
        if (entry.attachments == attachments) {
            glBindFramebuffer(GL_FRAMEBUFFER, entry.framebuffer.get());
            return entry.framebuffer.get();
        }
    }
    Entry entry{attachments, createFramebuffer()};
    const GLuint fbo = entry.framebuffer.get();
    GLenum drawBuffers[kMaxColourAttachments];
    GLsizei count = 0;
    for (int i = 0; i < kMaxColourAttachments && attachments.colour[static_cast<size_t>(i)] != 0; ++i) {
        glNamedFramebufferTexture(fbo, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i), attachments.colour[static_cast<size_t>(i)], 0);
        drawBuffers[count++] = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i);
    }
    if (attachments.depth != 0) {
        glNamedFramebufferTexture(fbo, attachments.depthHasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                  attachments.depth, 0);
    }
    if (count > 0) {
        glNamedFramebufferDrawBuffers(fbo, count, drawBuffers);
    } else {
        glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    }
    mEntries.push_back(std::move(entry));
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    return fbo;
}

void FramebufferCache::forget(GLuint texture) {
    mEntries.erase(std::remove_if(mEntries.begin(), mEntries.end(),
                                  [&](const Entry& e) {
                                      return e.attachments.depth == texture ||
                                             std::find(e.attachments.colour.begin(), e.attachments.colour.end(),
                                                       texture) != e.attachments.colour.end();
                                  }),
                   mEntries.end());
}

}  // namespace dermis::gl
