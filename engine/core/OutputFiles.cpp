#include "core/OutputFiles.h"

#include <atomic>
#include <fstream>

#include <unistd.h>

namespace dermis {

namespace fs = std::filesystem;

namespace {

std::string uniqueSuffix() {
    static std::atomic<unsigned> counter{0};
    return ".dermis-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

// A name in `path`'s directory that nothing uses: "." + stem + suffix + extension.
fs::path hiddenBeside(const fs::path& path, const std::string& suffix) {
    const std::string name = "." + path.stem().string() + suffix + path.extension().string();
    return path.has_parent_path() ? path.parent_path() / name : fs::path(name);
}

}  // namespace

OutputFiles::~OutputFiles() { discard(); }

void OutputFiles::discard() {
    std::error_code ignored;
    for (const Staged& s : mStaged) fs::remove(s.temporary, ignored);
    mStaged.clear();
    // Innermost first; fs::remove leaves a directory that holds anything else.
    for (auto d = mCreatedDirectories.rbegin(); d != mCreatedDirectories.rend(); ++d) fs::remove(*d, ignored);
    mCreatedDirectories.clear();
}

Status OutputFiles::prepareDirectory(const std::string& path) {
    std::error_code error;
    std::vector<fs::path> missing;
    for (fs::path p = fs::path(path); !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    fs::create_directories(path, error);
    if (error || !fs::is_directory(path)) {
        // Say why: a file in the way (the common mistake) or what the system said.
        std::string why = error ? error.message() : "it is not a directory";
        for (fs::path p = fs::path(path); !p.empty(); p = p.parent_path()) {
            std::error_code ignored;
            if (fs::exists(p, ignored) && !fs::is_directory(p, ignored)) {
                why = p.string() == path ? "a file of that name is in the way" : "'" + p.string() + "' is a file, not a directory";
                break;
            }
            if (p == p.parent_path()) break;
        }
        return makeError(path, "cannot create the directory: " + why);
    }
    mCreatedDirectories.insert(mCreatedDirectories.end(), missing.rbegin(), missing.rend());
    return success();
}

Result<fs::path> OutputFiles::temporaryFor(const std::string& path) {
    const fs::path target(path);
    std::error_code error;
    if (target.has_parent_path()) {
        if (Status made = prepareDirectory(target.parent_path().string()); !made) return made.error();
    }
    if (fs::is_directory(target, error)) return makeError(path, "is a directory");
    return hiddenBeside(target, uniqueSuffix());
}

namespace {
// A writer's error names the hidden temporary; the user asked for `path`.
std::string namingTarget(std::string what, const fs::path& temporary, const std::string& path) {
    const std::string hidden = temporary.string();
    for (size_t at = what.find(hidden); at != std::string::npos; at = what.find(hidden, at + path.size()))
        what.replace(at, hidden.size(), path);
    return what;
}
}  // namespace

Status OutputFiles::checkWritable(const std::string& path) {
    auto temporary = temporaryFor(path);
    if (!temporary) return temporary.error();
    bool created = false;
    {
        std::ofstream probe(*temporary, std::ios::binary | std::ios::trunc);
        created = static_cast<bool>(probe);
    }
    std::error_code ignored;
    fs::remove(*temporary, ignored);
    if (!created) return makeError(path, "cannot create a file there");
    return success();
}

Status OutputFiles::stageImage(const std::string& path, const Image& image) {
    const std::string extension = lowerExtension(path);
    if (extension != ".png" && extension != ".exr")
        return makeError(path, "unsupported image extension '" + extension + "' (use .png or .exr)");
    if (image.width <= 0 || image.height <= 0 ||
        image.texels.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height))
        return makeError(path, "image is empty or its texel count does not match " + std::to_string(image.width) +
                                   "x" + std::to_string(image.height));
    auto temporary = temporaryFor(path);
    if (!temporary) return temporary.error();
    mStaged.push_back({*temporary, fs::path(path)});
    if (Status written = writeImageFile(temporary->string(), extension, image); !written)
        return makeError(path, namingTarget(written.error().what, *temporary, path));
    return success();
}

Status OutputFiles::stageLayeredExr(const std::string& path, const std::vector<ImageLayer>& layers) {
    if (lowerExtension(path) != ".exr") return makeError(path, "layers are written to an .exr file only");
    auto temporary = temporaryFor(path);
    if (!temporary) return temporary.error();
    mStaged.push_back({*temporary, fs::path(path)});
    if (Status written = writeLayeredExr(temporary->string(), layers); !written)
        return makeError(path, namingTarget(written.error().what, *temporary, path));
    return success();
}

Status OutputFiles::stageText(const std::string& path, const std::string& text) {
    auto temporary = temporaryFor(path);
    if (!temporary) return temporary.error();
    mStaged.push_back({*temporary, fs::path(path)});
    std::ofstream out(*temporary, std::ios::binary | std::ios::trunc);
    if (!out) return makeError(path, "cannot create the file");
    out << text;
    out.flush();
    if (!out) return makeError(path, "the write failed");
    return success();
}

Status OutputFiles::stageFile(const std::string& path, const fs::path& written) {
    auto temporary = temporaryFor(path);
    if (!temporary) return temporary.error();
    std::error_code error;
    fs::rename(written, *temporary, error);
    if (error) return makeError(path, "could not take " + written.string() + ": " + error.message());
    mStaged.push_back({*temporary, fs::path(path)});
    return success();
}

Status OutputFiles::commit() {
    // What each destination held: moved aside first, so that a failed move
    // can put every destination back as it was.
    struct Moved {
        fs::path target;
        fs::path backup;  // empty: there was nothing
    };
    std::vector<Moved> moved;
    auto rollBack = [&] {
        std::error_code ignored;
        for (auto m = moved.rbegin(); m != moved.rend(); ++m) {
            fs::remove(m->target, ignored);
            if (!m->backup.empty()) fs::rename(m->backup, m->target, ignored);
        }
        discard();
    };
    // rollBack() discards mStaged, so each failure names its target from a copy.
    for (const Staged& s : mStaged) {
        std::error_code error;
        Moved m{s.target, {}};
        const std::string target = s.target.string();
        if (fs::is_directory(fs::symlink_status(s.target, error))) {
            rollBack();
            return makeError(target, "is a directory");
        }
        if (fs::exists(fs::symlink_status(s.target, error))) {
            m.backup = hiddenBeside(s.target, uniqueSuffix() + "-was");
            fs::rename(s.target, m.backup, error);
            if (error) {
                rollBack();
                return makeError(target, "could not replace the existing file: " + error.message());
            }
        }
        fs::rename(s.temporary, s.target, error);
        if (error) {
            if (!m.backup.empty()) {
                std::error_code ignored;
                fs::rename(m.backup, m.target, ignored);
            }
            rollBack();
            return makeError(target, "could not move the written file into place: " + error.message());
        }
        moved.push_back(m);
    }
    std::error_code ignored;
    for (const Moved& m : moved)
        if (!m.backup.empty()) fs::remove(m.backup, ignored);
    mStaged.clear();
    mCreatedDirectories.clear();  // they hold the outputs now
    return success();
}

}  // namespace dermis
