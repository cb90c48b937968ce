#pragma once
// A plain std::thread loop over work items. Items are taken from a shared
// counter, so which thread runs an item varies, but an item's result must
// depend on the item alone: the callers write to item-owned slots only, which
// keeps every result independent of the thread count.

#include <cstddef>
#include <functional>
#include <string>

namespace dermis::raytrace {

// 0 means std::thread::hardware_concurrency() (at least 1).
int resolveThreadCount(int requested);

// Runs work(i) for i in [0, count) on `threads` threads. With a non-empty
// progressLabel, shows a log::Progress bar advanced once per item.
void parallelFor(size_t count, int threads, const std::function<void(size_t)>& work,
                 const std::string& progressLabel = {});

}  // namespace dermis::raytrace
