#include "core/TextFile.h"

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace dermis {

Status writeTextFileAtomically(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target(path);
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) return makeError(path, "cannot create the file");
        out << text;
        out.flush();
        if (!out) {
            out.close();
            fs::remove(temporary, ec);
            return makeError(path, "the write failed");
        }
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return makeError(path, "could not move the written file into place: " + ec.message());
    }
    return success();
}

}  // namespace dermis
