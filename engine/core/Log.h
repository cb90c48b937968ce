#pragma once
// Minimal logging: errors and progress go to stderr so stdout stays for tables
// and machine-readable output. Quiet mode (--quiet) silences info and progress;
// warnings stay unless turned off too (dermis --no-warnings); errors always print.

#include <cstdio>
#include <string>

namespace dermis::log {

void setQuiet(bool quiet);
bool quiet();
void setWarnings(bool on);
void info(const std::string& message);
void warn(const std::string& message);
void error(const std::string& message);

// A one-line progress bar on stderr ("label [#####.....] 42/100"), redrawn in
// place when stderr is a terminal, printed every ~10% otherwise.
class Progress {
public:
    Progress(std::string label, size_t total, size_t done = 0);  // done: steps already taken when the bar appears
    ~Progress();
    void advance(size_t steps = 1);

private:
    void draw(bool force);
    std::string mLabel;
    size_t mTotal;
    size_t mDone = 0;
    int mLastDecile = -1;
    bool mTty;
};

}  // namespace dermis::log
