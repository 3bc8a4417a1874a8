#include "progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

namespace talkface_cli {

ProgressBar::~ProgressBar() {
    if (last_percent_ >= 0) std::fputs("\r\033[K", stderr);
}

bool ProgressBar::update(double fraction, const std::string& stage) {
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_percent_ && stage == last_stage_) return true;
    last_percent_ = percent;
    last_stage_ = stage;
    const int filled = percent * 30 / 100;
    std::fprintf(stderr, "\r%-9s [%-30s] %3d%%", stage.c_str(),
                 std::string(static_cast<std::size_t>(filled), '#').c_str(), percent);
    std::fflush(stderr);
    return true;
}

std::unique_ptr<ProgressBar> make_progress_bar(bool quiet) {
    if (quiet || ::isatty(::fileno(stderr)) == 0) return nullptr;
    return std::make_unique<ProgressBar>();
}

std::function<bool(double, const std::string&)> progress_part(ProgressBar* bar, double start, double end) {
    if (bar == nullptr) return {};
    return [bar, start, end](double fraction, const std::string& stage) {
        return bar->update(start + (end - start) * fraction, stage);
    };
}

}  // namespace talkface_cli
