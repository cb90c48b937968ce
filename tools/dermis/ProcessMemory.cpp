#include "ProcessMemory.h"

#include <malloc.h>
#include <unistd.h>

#include <fstream>

namespace dermis::cli {

Result<uint64_t> residentBytes() {
    malloc_trim(0);
    // statm: total program size, then resident pages (proc(5)).
    std::ifstream statm("/proc/self/statm");
    uint64_t sizePages = 0;
    uint64_t residentPages = 0;
    if (!(statm >> sizePages >> residentPages)) return makeError("/proc/self/statm", "cannot read the resident pages");
    return residentPages * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace dermis::cli
