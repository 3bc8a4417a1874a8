#include "speech/alignment_progress.hpp"

namespace talkface::detail {

void report_pass(ProgressReporter& progress, int pass, int passes, std::size_t w, std::size_t count) {
    const double alignment_share = kPlannedShare - kReadingShare - kCuttingShare;
    progress.report(
        kReadingShare + kCuttingShare +
            alignment_share * (pass + static_cast<double>(w + 1) / static_cast<double>(count)) / passes,
        "syllables");
}

}  // namespace talkface::detail
