#pragma once
// Loads GLSL 450 programs from the shaders/ folder. Sources may
// `#include "file.glsl"` (resolved in shaders/include/, each file once, or
// among the caller's generated includes: text a registry writes, such as the
// lighting pass's dispatch over the SSS techniques), and callers may prepend
// #defines (Jimenez-style configurable headers).
//
// The shader folder is core/DataDirectory.h's: $DERMIS_SHADER_DIR when set,
// an installed tree's share/dermis/shaders, else the source tree's shaders/.

#include "core/Result.h"
#include "gl/GlObjects.h"

#include <string>
#include <vector>

namespace dermis::gl {

struct ShaderDefine {
    std::string name;
    std::string value;
};

// An include whose text the program's caller makes; `#include "name"` finds it
// before the shader folder, and its own #includes are expanded like a file's.
struct GeneratedInclude {
    std::string name;
    std::string text;
};

struct ProgramSource {
    std::string vertexFile;    // relative to the shader folder
    std::string fragmentFile;  // empty for a depth-only program
    std::vector<ShaderDefine> defines;
    std::string computeFile;   // a compute program: set this and leave the two above empty
    std::vector<GeneratedInclude> generatedIncludes;
};

std::string shaderDirectory();

// Reads a file with its #includes expanded; errors name the file that is missing.
Result<std::string> loadShaderSource(const std::string& file, const std::vector<ShaderDefine>& defines,
                                     const std::vector<GeneratedInclude>& generatedIncludes = {});

// Compiles and links; errors carry the file name and the driver's log.
Result<Program> buildProgram(const ProgramSource& source);

// A program compiled on its first get(): for variants most frames never draw
// with, whose compiling would slow every start. get() returns 0 where there is
// no source (default-constructed) or the build failed (logged once, with the
// driver's log): the caller then falls back to a program it built up front.
class LazyProgram {
public:
    LazyProgram() = default;
    explicit LazyProgram(ProgramSource source) : mSource(std::move(source)), mHasSource(true) {}
    GLuint get() const;

private:
    ProgramSource mSource;
    bool mHasSource = false;
    mutable Program mProgram;
    mutable bool mTried = false;
};

}  // namespace dermis::gl
