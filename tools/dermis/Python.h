#pragma once
// The Python interpreter that draws the plots (tools/plot_*.py, matplotlib),
// and where those scripts are (core/DataDirectory.h: the source tree's
// tools/, or an installed tree's share/dermis/tools).

#include <string>

namespace dermis::cli {

std::string pythonInterpreter();
std::string toolScript(const std::string& fileName);

}  // namespace dermis::cli
