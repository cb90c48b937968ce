#include "viewer/ShaderWatcher.h"

#include <system_error>

namespace dermis::viewer {

ShaderWatcher::ShaderWatcher(std::string directory, std::chrono::milliseconds interval)
    : mDirectory(std::move(directory)), mInterval(interval), mLastPoll(std::chrono::steady_clock::now()) {
    mSnapshot = scan();
}

ShaderWatcher::Snapshot ShaderWatcher::scan() const {
    Snapshot snapshot;
    std::error_code error;
    std::filesystem::recursive_directory_iterator it(mDirectory, error);
    for (; !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
        std::error_code fileError;
        if (!it->is_regular_file(fileError)) continue;
        const auto time = it->last_write_time(fileError);
        if (!fileError) snapshot[it->path().string()] = time;
    }
    return snapshot;
}

bool ShaderWatcher::poll() {
    const auto now = std::chrono::steady_clock::now();
    if (now - mLastPoll < mInterval) return false;
    mLastPoll = now;
    Snapshot current = scan();
    if (current == mSnapshot) return false;
    mSnapshot = std::move(current);
    return true;
}

}  // namespace dermis::viewer
