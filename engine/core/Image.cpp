#include "core/Image.h"

#include "core/OutputFiles.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>

namespace dermis {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxErrorLength = 300;
constexpr int kDecodeBandRows = 64;

static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "texels are written to OpenImageIO as packed floats");

// OpenImageIO messages can span several lines; an Error is one line.
std::string condense(const std::string& message, const char* fallback) {
    std::string line;
    bool pendingSpace = false;
    for (char c : message) {
        if (c == '\n' || c == '\r') {
            if (!line.empty() && line.back() != ';') line += ';';
            pendingSpace = !line.empty();
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            pendingSpace = !line.empty();
        } else {
            if (pendingSpace) line += ' ';
            pendingSpace = false;
            line += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
        }
    }
    while (!line.empty() && line.back() == ';') line.pop_back();
    if (line.empty()) return fallback;
    if (line.size() > kMaxErrorLength) line = line.substr(0, kMaxErrorLength) + "...";
    return line;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}


// Embedded images often have no file name; their first bytes say what they are.
std::string extensionFromMagic(const unsigned char* bytes, size_t size) {
    auto startsWith = [&](const char* magic, size_t length, size_t offset = 0) {
        return size >= offset + length && std::memcmp(bytes + offset, magic, length) == 0;
    };
    if (startsWith("\x89PNG", 4)) return ".png";
    if (startsWith("\xFF\xD8\xFF", 3)) return ".jpg";
    if (startsWith("RIFF", 4) && startsWith("WEBP", 4, 8)) return ".webp";
    if (startsWith("GIF8", 4)) return ".gif";
    if (startsWith("BM", 2)) return ".bmp";
    if (startsWith("\x76\x2F\x31\x01", 4)) return ".exr";
    if (startsWith("II*\0", 4) || startsWith("MM\0*", 4)) return ".tif";
    if (startsWith("#?", 2)) return ".hdr";
    return {};
}

OIIO::ImageSpec readConfig() {
    OIIO::ImageSpec config;
    // Keep colour channels as stored: PNG readers otherwise premultiply alpha.
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

Result<Image> decode(OIIO::ImageInput& input, const std::string& where, ColourSpace colourSpace, int* sanitisedTexels) {
    const OIIO::ImageSpec spec = input.spec();
    if (spec.deep) return makeError(where, "deep images are not supported");
    if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxImageDimension || spec.height > kMaxImageDimension)
        return makeError(where, "image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                    " is outside 1.." + std::to_string(kMaxImageDimension));
    if (spec.depth > 1) return makeError(where, "volume images are not supported");
    if (spec.nchannels <= 0) return makeError(where, "image has no channels");

    const size_t texelCount = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height);
    if (texelCount > kMaxImageTexels)
        return makeError(where, "image " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " has " +
                                    std::to_string(texelCount) + " texels, above the budget of " +
                                    std::to_string(kMaxImageTexels) + " (8192x8192, 1 GiB as float RGBA); scale it "
                                    "down first, e.g. oiiotool IN --resize 50% -o OUT");

    const int channels = std::min(spec.nchannels, 4);
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.colourSpace = colourSpace;
    image.storedType = spec.format.c_str();
    for (const OIIO::ParamValue& attribute : spec.extra_attribs) {
        if (attribute.name().string().rfind(kImageAttributePrefix, 0) == 0 && attribute.type() == OIIO::TypeString)
            image.attributes.emplace_back(attribute.name().string(), attribute.get_string());
    }
    image.texels.resize(texelCount);
    // Read straight into the RGBA texels (a texel stride of 16 bytes), in bands
    // of rows, and widen in place: OpenImageIO converts through a temporary as
    // large as the request, so a whole-image read would hold a second
    // full-size float copy. Integer formats are rescaled to [0,1]; no colour
    // conversion happens here.
    const OIIO::stride_t texelStride = sizeof(glm::vec4);
    for (int row = 0; row < spec.height; row += kDecodeBandRows) {
        const int end = std::min(spec.height, row + kDecodeBandRows);
        glm::vec4* band = &image.texels[static_cast<size_t>(row) * static_cast<size_t>(spec.width)];
        if (!input.read_scanlines(0, 0, spec.y + row, spec.y + end, spec.z, 0, channels, OIIO::TypeFloat, band,
                                  texelStride))
            return makeError(where, condense(input.geterror(), "could not read the image data"));
    }
    if (input.has_error()) return makeError(where, condense(input.geterror(), "could not read the image data"));

    const bool greyAlpha = channels == 2 && (spec.alpha_channel == 1 || spec.nchannels == 2);
    int sanitised = 0;
    for (glm::vec4& texel : image.texels) {
        const glm::vec4 s = texel;
        if (channels == 1) texel = glm::vec4(s[0], s[0], s[0], 1.0f);
        else if (greyAlpha) texel = glm::vec4(s[0], s[0], s[0], s[1]);
        else if (channels == 2) texel = glm::vec4(s[0], s[1], 0.0f, 1.0f);
        else if (channels == 3) texel = glm::vec4(s[0], s[1], s[2], 1.0f);
        bool replaced = false;
        for (int c = 0; c < 4; ++c) {
            if (!std::isfinite(texel[c])) {
                texel[c] = 0.0f;
                replaced = true;
            }
        }
        sanitised += replaced ? 1 : 0;
    }
    if (sanitisedTexels) *sanitisedTexels = sanitised;
    return image;
}


}  // namespace

std::string lowerExtension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

Status writeImageFile(const std::string& path, const std::string& extension, const Image& image) {
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    if (!output) return makeError(path, condense(OIIO::geterror(), "no image writer for this format"));

    const bool png = extension == ".png";
    OIIO::ImageSpec spec(image.width, image.height, 4, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    std::vector<uint8_t> bytes;
    const void* data = image.texels.data();
    if (png) {
        // The writer would otherwise divide colour by alpha.
        spec.attribute("oiio:UnassociatedAlpha", 1);
        bytes.resize(image.texels.size() * 4);
        for (size_t i = 0; i < image.texels.size(); ++i) {
            for (int c = 0; c < 4; ++c) {
                float value = image.texels[i][c];
                value = std::isfinite(value) ? std::clamp(value, 0.0f, 1.0f) : 0.0f;
                bytes[i * 4 + static_cast<size_t>(c)] = static_cast<uint8_t>(std::lround(value * 255.0f));
            }
        }
        data = bytes.data();
    } else {
        spec.attribute("compression", "zip");
        for (const auto& [name, value] : image.attributes) spec.attribute(name, value);
    }

    if (!output->open(path, spec)) return makeError(path, condense(output->geterror(), "could not open for writing"));
    bool written = output->write_image(spec.format, data);
    bool closed = output->close();
    if (!written || !closed || output->has_error())
        return makeError(path, condense(output->geterror(), "could not write the image"));
    return success();
}

Status writeLayeredExr(const std::string& path, const std::vector<ImageLayer>& layers) {
    if (layers.empty()) return makeError(path, "no layers to write");
    const int width = layers.front().image.width;
    const int height = layers.front().image.height;
    for (const ImageLayer& layer : layers) {
        if (layer.image.width != width || layer.image.height != height ||
            layer.image.texels.size() != size_t(width) * size_t(height)) {
            return makeError(path, "layer '" + layer.name + "' is not " + std::to_string(width) + "x" + std::to_string(height));
        }
    }
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    if (!output) return makeError(path, condense(OIIO::geterror(), "no image writer for this format"));
    const int channels = 4 * static_cast<int>(layers.size());
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames.clear();
    for (const ImageLayer& layer : layers)
        for (const char* channel : {"R", "G", "B", "A"})
            spec.channelnames.push_back(layer.name.empty() ? channel : layer.name + "." + channel);
    spec.alpha_channel = layers.front().name.empty() ? 3 : -1;
    spec.attribute("compression", "zip");
    std::vector<float> interleaved(size_t(width) * size_t(height) * size_t(channels));
    for (size_t texel = 0; texel < size_t(width) * size_t(height); ++texel)
        for (size_t layer = 0; layer < layers.size(); ++layer)
            for (int c = 0; c < 4; ++c) interleaved[texel * size_t(channels) + layer * 4 + size_t(c)] = layers[layer].image.texels[texel][c];
    if (!output->open(path, spec)) return makeError(path, condense(output->geterror(), "could not open for writing"));
    const bool written = output->write_image(OIIO::TypeDesc::FLOAT, interleaved.data());
    const bool closed = output->close();
    if (!written || !closed || output->has_error())
        return makeError(path, condense(output->geterror(), "could not write the image"));
    return success();
}

Result<Image> loadImage(const std::string& path, ColourSpace colourSpace, int* sanitisedTexels) {
    std::error_code error;
    if (!fs::exists(path, error)) return makeError(path, "file not found");
    // Devices and pipes could make a format probe read forever.
    if (!fs::is_regular_file(path, error)) return makeError(path, "not a regular file");

    const OIIO::ImageSpec config = readConfig();
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path, &config);
    if (!input) return makeError(path, condense(OIIO::geterror(), "not an image OpenImageIO can read"));
    return decode(*input, path, colourSpace, sanitisedTexels);
}

Result<Image> loadImageFromMemory(const void* data, size_t size, const std::string& name, ColourSpace colourSpace,
                                  int* sanitisedTexels) {
    if (!data || size == 0) return makeError(name, "image data is empty");
    std::string extension = extensionFromMagic(static_cast<const unsigned char*>(data), size);
    if (extension.empty()) extension = lowerExtension(name);
    if (extension.empty()) return makeError(name, "unrecognised image format");

    OIIO::Filesystem::IOMemReader proxy(data, size);
    // OpenImageIO 2.4 ignores open()'s proxy argument when a config is given;
    // the config must carry the proxy itself.
    OIIO::ImageSpec config = readConfig();
    void* proxyPointer = &proxy;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxyPointer);
    const std::string placeholder = "memory" + extension;
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(placeholder, &config, &proxy);
    Result<Image> image = input ? decode(*input, name, colourSpace, sanitisedTexels)
                                : makeError(name, condense(OIIO::geterror(), "not an image OpenImageIO can read"));
    if (!image) return makeError(name, replaceAll(image.error().what, placeholder, name));
    return image;
}

Status saveImage(const std::string& path, const Image& image) {
    OutputFiles out;
    if (Status staged = out.stageImage(path, image); !staged) return staged;
    return out.commit();
}

}  // namespace dermis
