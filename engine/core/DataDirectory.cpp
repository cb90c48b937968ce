#include "core/DataDirectory.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace dermis {
namespace {

const char* folderName(DataKind kind) {
    switch (kind) {
    case DataKind::Shaders: return "shaders";
    case DataKind::Content: return "content";
    case DataKind::Tools: return "tools";
    }
    return "";
}

std::string sourceTreeFolder(DataKind kind) {
    switch (kind) {
    case DataKind::Shaders: return DERMIS_SOURCE_SHADER_DIR;
    case DataKind::Content: return DERMIS_SOURCE_CONTENT_DIR;
    case DataKind::Tools: return DERMIS_SOURCE_TOOLS_DIR;
    }
    return "";
}

std::string runningProgramFolder() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::string() : program.parent_path().string();
}

}  // namespace

std::vector<std::string> dataDirectoryCandidates(DataKind kind) {
    std::vector<std::string> candidates;
    if (const char* dir = std::getenv("DERMIS_SHADER_DIR"); dir && kind == DataKind::Shaders) candidates.push_back(dir);
    if (const char* dir = std::getenv("DERMIS_DATA_DIR")) candidates.push_back(std::string(dir) + "/" + folderName(kind));
    if (const std::string program = runningProgramFolder(); !program.empty()) {
        candidates.push_back(
            std::filesystem::path(program + "/../share/dermis/" + folderName(kind)).lexically_normal().string());
    }
    candidates.push_back(sourceTreeFolder(kind));
    candidates.push_back(std::string(DERMIS_INSTALL_DATA_DIR) + "/" + folderName(kind));
    candidates.push_back(std::string(DERMIS_PACKAGE_DATA_DIR) + "/" + folderName(kind));
    return candidates;
}

std::string dataDirectory(DataKind kind) {
    for (const std::string& candidate : dataDirectoryCandidates(kind)) {
        std::error_code error;
        if (std::filesystem::is_directory(candidate, error)) return candidate;
    }
    return sourceTreeFolder(kind);
}

}  // namespace dermis
