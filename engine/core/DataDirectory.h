#pragma once
// Where the program's data lies: its shaders, its content (scenes) and the
// plot scripts of tools/. The same lookup serves the build tree, an installed
// tree (`cmake --install`, the CPack .deb) and a program that links the
// installed engine (find_package(Dermis)); docs/install.md has the rules.
//
// For each kind, the first of these folders that exists:
//   1. $DERMIS_SHADER_DIR (shaders only, as before: the viewer's hot reload
//      and tests point it at a folder of their own);
//   2. $DERMIS_DATA_DIR/<kind>;
//   3. <folder of the running program>/../share/dermis/<kind>: an installed
//      `dermis`, or any program installed to the same prefix, wherever the
//      prefix was moved;
//   4. the source tree's <kind>/ (compiled in): the build tree's programs;
//   5. <the configured install prefix>/share/dermis/<kind> (compiled in);
//   6. /usr/share/dermis/<kind>, where the CPack .deb puts it.
// When none exists, the source tree's path, so that errors name a file.

#include <string>
#include <vector>

namespace dermis {

enum class DataKind { Shaders, Content, Tools };

std::string dataDirectory(DataKind kind);
// Every folder the lookup tries for `kind`, in order, for error messages
// and docs/install.md.
std::vector<std::string> dataDirectoryCandidates(DataKind kind);

}  // namespace dermis
