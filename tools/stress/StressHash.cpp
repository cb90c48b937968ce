#include "stress/StressHash.h"

#include "core/Hash.h"

#include <cstring>

namespace dermis::stress {
namespace {

// How to read a texture back whole: its texels as they are stored, 4 bytes per
// channel (float, unsigned int) or one packed 32-bit word (depth-stencil).
struct ReadBack {
    GLenum format;
    GLenum type;
    size_t wordsPerTexel;
};

ReadBack readBackFor(graph::TextureFormat format) {
    using graph::TextureFormat;
    switch (format) {
    case TextureFormat::R32UI:
    case TextureFormat::Rgba32UI: return {GL_RGBA_INTEGER, GL_UNSIGNED_INT, 4};
    case TextureFormat::Depth24Stencil8: return {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 1};
    case TextureFormat::Depth32F: return {GL_DEPTH_COMPONENT, GL_FLOAT, 1};
    default: return {GL_RGBA, GL_FLOAT, 4};
    }
}

}  // namespace

gl::PassInspector CaseHash::inspector(gl::PassInspector next) {
    return [this, next = std::move(next)](std::string_view pass, std::string_view texture, GLuint name,
                                          const graph::TextureDesc& desc) {
        addText(pass);
        addText(texture);
        if (name != 0) {
            const ReadBack how = readBackFor(desc.format);
            mScratch.assign(size_t(desc.width) * desc.height * how.wordsPerTexel, 0u);
            glGetTextureImage(name, 0, how.format, how.type, GLsizei(mScratch.size() * sizeof(uint32_t)),
                              mScratch.data());
            addWords(mScratch.data(), mScratch.size());
        }
        if (next) next(pass, texture, name, desc);
    };
}

void CaseHash::addImage(const Image& image) {
    const uint32_t size[2] = {uint32_t(image.width), uint32_t(image.height)};
    addWords(size, 2);
    mScratch.resize(image.texels.size() * 4);
    std::memcpy(mScratch.data(), image.texels.data(), mScratch.size() * sizeof(uint32_t));
    addWords(mScratch.data(), mScratch.size());
}

void CaseHash::addText(std::string_view text) {
    for (char ch : text) {
        const uint32_t word = uint8_t(ch);
        addWords(&word, 1);
    }
}

void CaseHash::addWords(const uint32_t* words, size_t count) {
    for (size_t i = 0; i < count; ++i) {
        mHash ^= lowbias32(words[i]);
        mHash *= 0x100000001b3ull;  // FNV-1a 64 prime
    }
}

}  // namespace dermis::stress
