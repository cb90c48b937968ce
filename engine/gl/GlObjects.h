#pragma once
// Move-only owners of GL object names. A zero name means "none".
//
// Every object is made with a label (glObjectLabel, GL 4.3 / KHR_debug), so
// that a frame capture (RenderDoc, docs/profiling.md) and the debug output
// name it: "<owner>: <what>" ("gpu scene: head vertices"). A test reads every
// live object's label back (tests/render/test_object_labels.cpp).

#include "gl/Gl.h"

#include <string_view>
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

// identifier: GL_TEXTURE, GL_BUFFER, GL_FRAMEBUFFER, GL_VERTEX_ARRAY, GL_PROGRAM, GL_SHADER, GL_QUERY.
inline void labelObject(GLenum identifier, GLuint name, std::string_view label) {
    if (name != 0) glObjectLabel(identifier, name, static_cast<GLsizei>(label.size()), label.data());
}

inline Texture createTexture(GLenum target, std::string_view label) {
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    labelObject(GL_TEXTURE, name, label);
    return Texture(name);
}
inline Buffer createBuffer(std::string_view label) {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    labelObject(GL_BUFFER, name, label);
    return Buffer(name);
}
inline Framebuffer createFramebuffer(std::string_view label) {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    labelObject(GL_FRAMEBUFFER, name, label);
    return Framebuffer(name);
}
inline VertexArray createVertexArray(std::string_view label) {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    labelObject(GL_VERTEX_ARRAY, name, label);
    return VertexArray(name);
}
inline GLuint createQuery(GLenum target, std::string_view label) {
    GLuint name = 0;
    glCreateQueries(target, 1, &name);
    labelObject(GL_QUERY, name, label);
    return name;
}

}  // namespace dermis::gl
