#include "core/Log.h"

#include <unistd.h>

#include <atomic>
#include <mutex>

namespace dermis::log {
namespace {
std::atomic<bool> gQuiet{false};
std::atomic<bool> gWarnings{true};
std::mutex gMutex;
}  // namespace

void setQuiet(bool q) { gQuiet = q; }
bool quiet() { return gQuiet; }
void setWarnings(bool on) { gWarnings = on; }

void info(const std::string& message) {
    if (gQuiet) return;
    std::lock_guard<std::mutex> lock(gMutex);
    std::fprintf(stderr, "%s\n", message.c_str());
}

void warn(const std::string& message) {
    if (!gWarnings) return;
    std::lock_guard<std::mutex> lock(gMutex);
    std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void error(const std::string& message) {
    // One line, whatever a path in it holds: control characters are written as escapes.
    std::string line;
    for (const char c : message) {
        if (c == '\n') line += "\\n";
        else if (c == '\r') line += "\\r";
        else if (c == '\t') line += "\\t";
        else line += c;
    }
    std::lock_guard<std::mutex> lock(gMutex);
    std::fprintf(stderr, "error: %s\n", line.c_str());
}

Progress::Progress(std::string label, size_t total, size_t done)
    : mLabel(std::move(label)), mTotal(total == 0 ? 1 : total), mDone(done < mTotal ? done : mTotal),
      mTty(isatty(STDERR_FILENO) != 0) {
    draw(true);
}

Progress::~Progress() {
    if (mTty && !gQuiet) std::fprintf(stderr, "\n");
}

void Progress::advance(size_t steps) {
    std::lock_guard<std::mutex> lock(gMutex);
    mDone += steps;
    if (mDone > mTotal) mDone = mTotal;
    draw(false);
}

void Progress::draw(bool force) {
    if (gQuiet) return;
    constexpr int kWidth = 30;
    const int decile = static_cast<int>(10 * mDone / mTotal);
    if (!mTty && !force && decile == mLastDecile) return;
    mLastDecile = decile;
    const int filled = static_cast<int>(kWidth * mDone / mTotal);
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(kWidth - filled), '.');
    std::fprintf(stderr, "%s%s [%s] %zu/%zu%s", mTty ? "\r" : "", mLabel.c_str(), bar.c_str(), mDone, mTotal,
                 mTty ? "" : "\n");
    std::fflush(stderr);
}

}  // namespace dermis::log
