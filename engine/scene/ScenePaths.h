#pragma once
// Paths inside a scene file (glTF meshes, texture maps) are relative to the
// scene file's directory. The loader stores them resolved; the writer turns
// them back into paths relative to the scene file, so that a scene written
// next to where it was read loads back to the same resolved paths.

#include <string>

namespace dermis {

// Absolute paths and empty strings are returned as they are; others are
// joined to the scene file's directory and lexically normalised.
std::string resolveScenePath(const std::string& sceneFile, const std::string& path);

// The inverse of resolveScenePath: a string s with
// resolveScenePath(sceneFile, s) == resolved, relative where possible.
std::string relativeScenePath(const std::string& sceneFile, const std::string& resolved);

}  // namespace dermis
