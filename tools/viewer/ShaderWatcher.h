#pragma once
// Notices edits to the shader folder by polling file modification times (and
// which files exist) a few times a second: portable, and cheap for a few
// dozen files. Editors that save by writing a new file and renaming it are
// seen too, since the new file has a new time.

#include <chrono>
#include <filesystem>
#include <map>
#include <string>

namespace dermis::viewer {

class ShaderWatcher {
public:
    explicit ShaderWatcher(std::string directory, std::chrono::milliseconds interval = std::chrono::milliseconds(400));

    // True once for each change seen since the last poll that returned true.
    bool poll();
    const std::string& directory() const { return mDirectory; }

private:
    using Snapshot = std::map<std::string, std::filesystem::file_time_type>;
    Snapshot scan() const;

    std::string mDirectory;
    std::chrono::milliseconds mInterval;
    std::chrono::steady_clock::time_point mLastPoll;
    Snapshot mSnapshot;
};

}  // namespace dermis::viewer
