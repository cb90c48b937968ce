#pragma once
// Images on the CPU side: loading through OpenImageIO (any format it reads),
// saving PNG (8-bit) and EXR (float). Texels are always float RGBA in memory;
// the GPU upload chooses the storage format.

#include "core/Result.h"

#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

namespace dermis {

enum class ColourSpace {
    Linear,  // data: normals, roughness, LEAN moments
    Srgb,    // colour: albedo; decoded to linear on the GPU (sRGB texture format)
};

// The prefix of the attributes an Image carries (Image::attributes).
constexpr const char* kImageAttributePrefix = "dermis:";

struct Image {
    int width = 0;
    int height = 0;
    ColourSpace colourSpace = ColourSpace::Linear;
    std::vector<glm::vec4> texels;  // row-major, row 0 is the image's top row
    // Loaded from a file: its channels' type as OpenImageIO names it ("uint8",
    // "half", "float"); empty otherwise. Tells a linear float image from an
    // 8-bit encoded one.
    std::string storedType;
    // String attributes whose names start with "dermis:" (what made the image),
    // written into an EXR's header and read back from one.
    std::vector<std::pair<std::string, std::string>> attributes;

    bool empty() const { return texels.empty(); }
    glm::vec4& at(int x, int y) { return texels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)]; }
    const glm::vec4& at(int x, int y) const {
        return texels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
    }
};

// Largest width or height any loaded image may have; larger ones are refused
// with an error rather than risking an enormous allocation.
constexpr int kMaxImageDimension = 16384;
// The memory budget of one loaded image: texels are float RGBA (16 bytes), so
// 8192 x 8192 texels are 1 GiB on the CPU. A larger image (a 16384^2 map,
// 4 GiB decoded) is refused before anything is decoded, with a line naming the
// file and this budget; docs/testing.md "Memory" has the measured peaks.
constexpr size_t kMaxImageTexels = size_t{8192} * 8192;

// Loads any format OpenImageIO reads. Grey and RGB images are expanded to RGBA
// (alpha 1). Non-finite texels (NaN, Inf) are replaced by 0 and counted in
// *sanitisedTexels when it is given. Errors name the file and the problem.
Result<Image> loadImage(const std::string& path, ColourSpace colourSpace, int* sanitisedTexels = nullptr);

// The same, for an encoded image held in memory (an image embedded in a glTF
// file). `name` is used in errors and as a hint to the format when the bytes
// do not identify it.
Result<Image> loadImageFromMemory(const void* data, size_t size, const std::string& name, ColourSpace colourSpace,
                                  int* sanitisedTexels = nullptr);

// Writes to a temporary file beside `path` and renames it, so a failed write
// never leaves a partial file (core/OutputFiles.h; a command with several
// outputs stages them all there). `.png` stores 8-bit values as given (the
// caller has already tone-mapped and encoded); `.exr` stores 32-bit floats.
Status saveImage(const std::string& path, const Image& image);
// Writes `path` itself, in the format of `extension` (".png" or ".exr"): for
// OutputFiles, whose temporaries carry the destination's extension.
Status writeImageFile(const std::string& path, const std::string& extension, const Image& image);

// One layer of a multi-layer EXR: its name and its RGBA image (all of one size).
struct ImageLayer {
    std::string name;  // empty: the default layer (channels R, G, B, A), which viewers show first
    Image image;
};
// Writes `path` itself as one OpenEXR part of 32-bit float channels named
// "LAYER.R", "LAYER.G", "LAYER.B", "LAYER.A" per layer (the OpenEXR convention
// for layers that EXR viewers and compositors list), zip-compressed.
Status writeLayeredExr(const std::string& path, const std::vector<ImageLayer>& layers);
// The path's extension, lower case, with its dot ("x.PNG" -> ".png").
std::string lowerExtension(const std::string& path);

}  // namespace dermis
