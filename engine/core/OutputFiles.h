#pragma once
// A command's output files, all or nothing (docs/cli.md, "Outputs"). Each file
// is written in full to a hidden temporary beside its destination (stage);
// commit() then moves them all into place, and if any move fails it puts
// back what the destinations held before. Without a commit (an error, an
// exception) the temporaries are removed. So a failed command leaves every
// output path exactly as it was; a process killed before its commit leaves
// the destinations too, and at most its hidden temporaries
// (".NAME.dermis-PID-N.EXT") beside them.
//
//   OutputFiles out;
//   if (Status s = out.stageImage("a.png", image); !s) return s;   // a.png untouched so far
//   if (Status s = out.stageText("t.json", json); !s) return s;    // neither written
//   return out.commit();                                          // both, or neither

#include "core/Image.h"
#include "core/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace dermis {

class OutputFiles {
public:
    OutputFiles() = default;
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;
    ~OutputFiles();

    // `.png` (8-bit, values as given) or `.exr` (32-bit float), by the path's extension.
    Status stageImage(const std::string& path, const Image& image);
    Status stageText(const std::string& path, const std::string& text);
    // An `.exr` of several named layers (core/Image.h, writeLayeredExr).
    Status stageLayeredExr(const std::string& path, const std::vector<ImageLayer>& layers);
    // A file another program wrote (`written`, on the same file system): moved
    // to `path`'s temporary now, into place at the commit.
    Status stageFile(const std::string& path, const std::filesystem::path& written);
    // Creates `path` and its missing parents now (to fail early, before long
    // work); without a commit, those it created are removed again.
    Status prepareDirectory(const std::string& path);
    // Before long work: that a file can be created beside `path` (its folder
    // made as prepareDirectory does); nothing is left there.
    Status checkWritable(const std::string& path);
    // Moves every staged file into place, or none. Errors name the path.
    Status commit();

private:
    // The temporary of `path`: hidden, beside it, with its extension (which
    // is how OpenImageIO picks the writer). Creates missing parent directories.
    Result<std::filesystem::path> temporaryFor(const std::string& path);
    void discard();

    struct Staged {
        std::filesystem::path temporary;
        std::filesystem::path target;
    };
    std::vector<Staged> mStaged;
    std::vector<std::filesystem::path> mCreatedDirectories;  // outermost first
};

}  // namespace dermis
