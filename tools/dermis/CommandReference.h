#pragma once
// `dermis reference`: the CPU reference of the diffuse AOV (engine/reference).

#include <string>
#include <vector>

namespace dermis::cli {

int runReference(const std::vector<std::string>& args);

}  // namespace dermis::cli
