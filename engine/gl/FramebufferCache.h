#pragma once
// Framebuffer objects for a set of attachments, created once and reused.
// Passes ask for "these colour targets and this depth" and get a bound FBO.

#include "gl/GlObjects.h"

#include <array>
#include <vector>

namespace dermis::gl {

constexpr int kMaxColourAttachments = 7;  // the G-buffer with LEAN and the transfer (GBufferPass.h)

struct Attachments {
    std::array<GLuint, kMaxColourAttachments> colour{};  // 0 = unused slot (and every slot after it)
    GLuint depth = 0;
    bool depthHasStencil = false;

    bool operator==(const Attachments& o) const {
        return colour == o.colour && depth == o.depth && depthHasStencil == o.depthHasStencil;
    }
};

class FramebufferCache {
public:
    // Binds (GL_FRAMEBUFFER) and returns the FBO for these attachments, with
    // draw buffers set to the used colour slots.
    GLuint bind(const Attachments& attachments);
    void clear() { mEntries.clear(); }
    // Drops FBOs that refer to a texture about to be deleted.
    void forget(GLuint texture);

private:
    struct Entry {
        Attachments attachments;
        Framebuffer framebuffer;
    };
    std::vector<Entry> mEntries;
};

}  // namespace dermis::gl
