#include "gl/ShaderProgram.h"

#include "core/DataDirectory.h"
#include "core/Log.h"

#include <fstream>
#include <set>
#include <sstream>

namespace dermis::gl {
namespace {

constexpr int kMaxIncludeDepth = 16;

Result<std::string> readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError(path, "cannot open shader file");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

struct IncludeContext {
    const std::vector<GeneratedInclude>& generated;
    std::set<std::string> included;
};

Result<std::string> readInclude(const IncludeContext& context, const std::string& name) {
    for (const GeneratedInclude& generated : context.generated) {
        if (generated.name == name) return generated.text;
    }
    return readFile(shaderDirectory() + "/include/" + name);
}

Status expandIncludes(const std::string& file, const Result<std::string>& text, IncludeContext& context, int depth,
                      std::string& out) {
    if (depth > kMaxIncludeDepth) return makeError(file, "#include nested too deeply");
    if (!text.ok()) return text.error();
    std::istringstream lines(*text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(lines, line)) {
        ++lineNumber;
        const size_t hash = line.find_first_not_of(" \t");
        if (hash != std::string::npos && line.compare(hash, 8, "#include") == 0) {
            const size_t open = line.find('"');
            const size_t close = line.rfind('"');
            if (open == std::string::npos || close <= open) {
                return makeError(file + ":" + std::to_string(lineNumber), "malformed #include");
            }
            const std::string name = line.substr(open + 1, close - open - 1);
            if (context.included.insert(name).second) {
                const Status status = expandIncludes(name, readInclude(context, name), context, depth + 1, out);
                if (!status.ok()) return status;
            }
            continue;
        }
        out += line;
        out += '\n';
    }
    return success();
}

Result<GLuint> compileStage(GLenum stage, const std::string& file, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    labelObject(GL_SHADER, shader, file);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        while (!log.empty() && (log.back() == '\n' || log.back() == '\0')) log.pop_back();
        return makeError(file, "compile error: " + log);
    }
    return shader;
}

}  // namespace

std::string shaderDirectory() { return dataDirectory(DataKind::Shaders); }

Result<std::string> loadShaderSource(const std::string& file, const std::vector<ShaderDefine>& defines,
                                     const std::vector<GeneratedInclude>& generatedIncludes) {
    std::string out = "#version 450 core\n";
    for (const ShaderDefine& define : defines) out += "#define " + define.name + " " + define.value + "\n";
    // Restart line numbering so compile errors point at the file's own lines
    // (approximately: included files shift them).
    out += "#line 1\n";
    IncludeContext context{generatedIncludes, {}};
    const Status status = expandIncludes(file, readFile(shaderDirectory() + "/" + file), context, 0, out);
    if (!status.ok()) return status.error();
    return out;
}

Result<Program> buildProgram(const ProgramSource& source) {
    std::vector<GLuint> stages;
    auto cleanup = [&] {
        for (GLuint s : stages) glDeleteShader(s);
    };
    const std::pair<GLenum, const std::string*> files[] = {{GL_VERTEX_SHADER, &source.vertexFile},
                                                           {GL_FRAGMENT_SHADER, &source.fragmentFile},
                                                           {GL_COMPUTE_SHADER, &source.computeFile}};
    for (const auto& [stage, file] : files) {
        if (file->empty()) continue;
        auto text = loadShaderSource(*file, source.defines, source.generatedIncludes);
        if (!text.ok()) {
            cleanup();
            return text.error();
        }
        auto shader = compileStage(stage, *file, *text);
        if (!shader.ok()) {
            cleanup();
            return shader.error();
        }
        stages.push_back(*shader);
    }
    Program program(glCreateProgram());
    std::string label;
    for (const std::string* file : {&source.vertexFile, &source.fragmentFile, &source.computeFile})
        if (!file->empty()) label += (label.empty() ? "" : " + ") + *file;
    for (const ShaderDefine& define : source.defines) label += " " + define.name + "=" + define.value;
    labelObject(GL_PROGRAM, program.get(), label);
    for (GLuint s : stages) glAttachShader(program.get(), s);
    glLinkProgram(program.get());
    cleanup();
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
        glGetProgramInfoLog(program.get(), length, nullptr, log.data());
        return makeError(source.computeFile.empty() ? source.vertexFile + " + " + source.fragmentFile : source.computeFile,
                         "link error: " + log);
    }
    return program;
}

GLuint LazyProgram::get() const {
    if (!mHasSource) return 0;
    if (!mTried) {
        mTried = true;
        auto program = buildProgram(mSource);
        if (program.ok()) {
            mProgram = std::move(*program);
        } else {
            log::error(program.error().message() + " (falling back to the variant built at start)");
        }
    }
    return mProgram.get();
}

}  // namespace dermis::gl
