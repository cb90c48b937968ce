#include "core/CacheDirectory.h"

#include <cstdlib>

namespace dermis {

std::filesystem::path cacheDirectory() {
    if (const char* dir = std::getenv("DERMIS_CACHE_DIR"); dir && *dir) return std::filesystem::path(dir);
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "dermis";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "dermis";
    return {};
}

}  // namespace dermis
