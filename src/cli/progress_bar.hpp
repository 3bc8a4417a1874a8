// The progress bar of the commands that take long (align, animate, demo): one line on stderr,
// redrawn in place, only when stderr is a terminal and --quiet is not given (STYLE.md section 8).
#ifndef TALKFACE_CLI_PROGRESS_BAR_HPP
#define TALKFACE_CLI_PROGRESS_BAR_HPP

#include <functional>
#include <memory>
#include <string>

namespace talkface_cli {

class ProgressBar {
public:
    ProgressBar() = default;
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;
    // Clears the line, so that what follows starts on a clean one.
    ~ProgressBar();

    // Draws `fraction` (0..1) of the whole job and the stage's name; always returns true (go on).
    bool update(double fraction, const std::string& stage);

private:
    int last_percent_ = -1;
    std::string last_stage_;
};

// A bar if stderr is a terminal and not `quiet`, else none.
std::unique_ptr<ProgressBar> make_progress_bar(bool quiet);

// A callback that reports a stage's own fraction 0..1 as the part [start, end] of the whole job to
// `bar` (Rhubarb's ProgressMerger, by hand); an empty callback when there is no bar.
std::function<bool(double, const std::string&)> progress_part(ProgressBar* bar, double start, double end);

}  // namespace talkface_cli

#endif
