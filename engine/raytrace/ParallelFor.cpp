#include "raytrace/ParallelFor.h"

#include "core/Log.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

namespace dermis::raytrace {

int resolveThreadCount(int requested) {
    if (requested > 0) return requested;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void parallelFor(size_t count, int threads, const std::function<void(size_t)>& work, const std::string& progressLabel) {
    std::unique_ptr<log::Progress> progress;
    if (count == 0) return;
    if (!progressLabel.empty()) progress = std::make_unique<log::Progress>(progressLabel, count);
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t i = next++; i < count; i = next++) {
            work(i);
            if (progress) progress->advance();
        }
    };
    const size_t extra = std::min<size_t>(size_t(resolveThreadCount(threads)), std::max<size_t>(count, 1)) - 1;
    std::vector<std::thread> pool;
    pool.reserve(extra);
    for (size_t t = 0; t < extra; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
}

}  // namespace dermis::raytrace
