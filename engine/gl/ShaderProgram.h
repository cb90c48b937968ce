#pragma once
// Loads GLSL 450 programs from the shaders/ folder. Sources may
// `#include "file.glsl"` (resolved in shaders/include/, each file once), and
// callers may prepend #defines (Jimenez-style configurable headers).
//
// The shader folder is $DERMIS_SHADER_DIR when set, else the source tree's
// shaders/ (compiled in), so an installed binary and the viewer's hot reload
// read the same files.

#include "core/Result.h"
#include "gl/GlObjects.h"

#include <string>
#include <vector>

namespace dermis::gl {

struct ShaderDefine {
    std::string name;
    std::string value;
};

struct ProgramSource {
    std::string vertexFile;    // relative to the shader folder
    std::string fragmentFile;  // empty for a depth-only program
    std::vector<ShaderDefine> defines;
    std::string computeFile;   // a compute program: set this and leave the two above empty
};

std::string shaderDirectory();

// Reads a file with its #includes expanded; errors name the file that is missing.
Result<std::string> loadShaderSource(const std::string& file, const std::vector<ShaderDefine>& defines);

// Compiles and links; errors carry the file name and the driver's log.
Result<Program> buildProgram(const ProgramSource& source);

}  // namespace dermis::gl
