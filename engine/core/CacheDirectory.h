#pragma once
// Where Dermis keeps what it computes once per machine (the SH transfer, the
// CPU reference's images): $DERMIS_CACHE_DIR, else $XDG_CACHE_HOME/dermis,
// else $HOME/.cache/dermis. Empty when none of the variables is set.

#include <filesystem>

namespace dermis {

std::filesystem::path cacheDirectory();

}  // namespace dermis
