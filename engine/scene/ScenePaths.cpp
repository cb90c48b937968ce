#include "scene/ScenePaths.h"

#include <filesystem>

namespace dermis {

namespace fs = std::filesystem;

std::string resolveScenePath(const std::string& sceneFile, const std::string& path) {
    if (path.empty() || fs::path(path).is_absolute()) {
        return path;
    }
    const fs::path directory = fs::path(sceneFile).parent_path();
    if (directory.empty()) {
        return path;
    }
    return (directory / path).lexically_normal().generic_string();
}

std::string relativeScenePath(const std::string& sceneFile, const std::string& resolved) {
    if (resolved.empty() || fs::path(resolved).is_absolute()) {
        return resolved;
    }
    const fs::path directory = fs::path(sceneFile).parent_path();
    if (directory.empty()) {
        return resolved;
    }
    const std::string relative = fs::path(resolved).lexically_relative(directory.lexically_normal()).generic_string();
    // lexically_relative cannot always invert (e.g. a directory that climbs out
    // with ".."); then the stored path is written unchanged.
    if (!relative.empty() && resolveScenePath(sceneFile, relative) == resolved) {
        return relative;
    }
    return resolved;
}

}  // namespace dermis
