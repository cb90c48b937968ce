#pragma once
// The process's resident memory, as the kernel counts it (/proc/self/statm),
// after handing malloc's free pages back to the kernel (malloc_trim): freed
// blocks that glibc keeps would otherwise swing the figure by tens of MiB from
// one sample to the next, while memory still allocated stays counted.

#include "core/Result.h"

#include <cstdint>

namespace dermis::cli {

Result<uint64_t> residentBytes();

}  // namespace dermis::cli
