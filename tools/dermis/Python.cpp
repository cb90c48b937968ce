#include "Python.h"

#include "core/DataDirectory.h"

#include <filesystem>

namespace dermis::cli {

std::string pythonInterpreter() {
    // Debian's interpreter has Debian's matplotlib; a python3 earlier on PATH
    // (pyenv, a virtualenv) may not.
    return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

std::string toolScript(const std::string& fileName) { return dataDirectory(DataKind::Tools) + "/" + fileName; }

}  // namespace dermis::cli
