#include "gl/FramebufferCache.h"

#include <algorithm>
#include <string>

namespace dermis::gl {
namespace {

std::string textureLabel(GLuint texture) {
    char label[256] = {};
    GLsizei length = 0;
    glGetObjectLabel(GL_TEXTURE, texture, sizeof label, &length, label);
    return length > 0 ? std::string(label, size_t(length)) : "texture " + std::to_string(texture);
}

// What it draws to first ("framebuffer: gbuffer albedo + gbuffer normal + depth"): pooled
// textures are named again for each pass that uses them, so later passes may draw other things.
std::string framebufferLabel(const Attachments& attachments) {
    std::string label = "framebuffer:";
    const char* separator = " ";
    for (GLuint texture : attachments.colour) {
        if (texture == 0) break;
        label += separator + textureLabel(texture);
        separator = " + ";
    }
    if (attachments.depth != 0) label += separator + textureLabel(attachments.depth);
    return label;
}

}  // namespace

GLuint FramebufferCache::bind(const Attachments& attachments) {
    for (const Entry& entry : mEntries) {
        if (entry.attachments == attachments) {
            glBindFramebuffer(GL_FRAMEBUFFER, entry.framebuffer.get());
            return entry.framebuffer.get();
        }
    }
    Entry entry{attachments, createFramebuffer(framebufferLabel(attachments))};
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
