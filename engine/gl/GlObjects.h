#pragma once
// Move-only owners of GL object names. A zero name means "none".

#include "gl/Gl.h"

#include <utility>

namespace dermis::gl {

template <void (*Delete)(GLuint)>
class Object {
public:
    Object() = default;
    explicit Object(GLuint name) : mName(name) {}
    ~Object() { reset(); }
    Object(Object&& other) noexcept : mName(std::exchange(other.mName, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            mName = std::exchange(other.mName, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint get() const { return mName; }
    bool isValid() const { return mName != 0; }
    void reset() {
        if (mName) Delete(mName);
        mName = 0;
    }

private:
    GLuint mName = 0;
};

namespace detail {
inline void deleteTexture(GLuint n) { glDeleteTextures(1, &n); }
inline void deleteBuffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void deleteFramebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void deleteVertexArray(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void deleteProgram(GLuint n) { glDeleteProgram(n); }
inline void deleteQuery(GLuint n) { glDeleteQueries(1, &n); }
}  // namespace detail

using Texture = Object<detail::deleteTexture>;
using Buffer = Object<detail::deleteBuffer>;
using Framebuffer = Object<detail::deleteFramebuffer>;
using VertexArray = Object<detail::deleteVertexArray>;
using Program = Object<detail::deleteProgram>;
using Query = Object<detail::deleteQuery>;

inline Texture createTexture(GLenum target) {
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    return Texture(name);
}
inline Buffer createBuffer() {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    return Buffer(name);
}
inline Framebuffer createFramebuffer() {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return Framebuffer(name);
}
inline VertexArray createVertexArray() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArray(name);
}

}  // namespace dermis::gl
