#pragma once
// The Python interpreter that draws the plots (tools/plot_*.py, matplotlib).

#include <string>

namespace dermis::cli {

std::string pythonInterpreter();

}  // namespace dermis::cli
