#pragma once
// A stress case's fingerprint: a hash over every texel of every texture each
// pass writes (all formats, read back as they are stored) and each frame's
// output image, so that two runs of one seed can be compared texel for
// texel without storing the texels. FNV-1a over 32-bit words, each word
// mixed by lowbias32 (core/Hash.h) first so that nearby values spread.

#include "core/Image.h"
#include "gl/GlGraphBackend.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace dermis::stress {

class CaseHash {
public:
    // An inspector that hashes what `next` is shown, then calls it.
    gl::PassInspector inspector(gl::PassInspector next);
    void addImage(const Image& image);
    void addText(std::string_view text);
    uint64_t value() const { return mHash; }

private:
    void addWords(const uint32_t* words, size_t count);
    uint64_t mHash = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis
    std::vector<uint32_t> mScratch;
};

}  // namespace dermis::stress
