// The alignment job's progress bar (ProgressCallback): reading and features, cutting and the
// alignment passes as planned, and the work done again, which no plan foresees.
#ifndef TALKFACE_SPEECH_ALIGNMENT_PROGRESS_HPP
#define TALKFACE_SPEECH_ALIGNMENT_PROGRESS_HPP

#include <algorithm>
#include <cstddef>
#include <string>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"
#include "talkface/progress.hpp"

namespace talkface::detail {

// Shares of the job's progress as planned: reading and features, cutting, the alignment passes. The
// bar's last kWorkAgainShare is left to the work done again, which no plan foresees
// (ProgressReporter).
inline constexpr double kReadingShare = 0.45;
inline constexpr double kCuttingShare = 0.05;
inline constexpr double kWorkAgainShare = 0.05;
inline constexpr double kPlannedShare = 1.0 - kWorkAgainShare;
inline constexpr double kProgressStep = 0.002;

// The bar: the job's progress as planned (reading, cutting, the alignment passes, up to
// kPlannedShare), and work done again, which reports from lower once more: the cut aligned again
// (kept to the text's pauses, with nasal releases, its sentence ends confirmed, as one block), the
// alignment made again without its checks (CheckMode::warn), the recording read again (with the
// pitch, at another phase). How much of that comes is known only as it comes, so each such piece
// fills half of the bar still left: the bar moves while the callback is asked, and reaches 1.0
// only when the job is done (session 28: the planned alignment ended at 1.0, and the bar stood
// there through the work done again).
class ProgressReporter {
public:
    explicit ProgressReporter(const ProgressCallback& callback) : callback_(callback) {}

    // `fraction` of the job as planned, in `stage`: asked at most every kProgressStep of a stage.
    void report(double fraction, const char* stage) {
        if (!callback_) return;
        if (fraction < planned_fraction_) {
            // Work done again begins: the bar stands where it is for this report, and the ones
            // after it move it through half of what is left.
            again_from_ = fraction;
            again_base_ = bar_;
            again_scale_ = 0.5 * (1.0 - bar_) / (kPlannedShare - fraction);
            planned_fraction_ = fraction;
            stage_ = stage;
            return;
        }
        if (stage == stage_ && fraction < planned_fraction_ + kProgressStep) return;
        planned_fraction_ = fraction;
        stage_ = stage;
        bar_ = std::min(again_base_ + (fraction - again_from_) * again_scale_, kBarBeforeDone);
        ask(bar_);
    }

    // The job is done: the bar at 1.0, in the alignment's last stage.
    void report_done() {
        if (!callback_) return;
        stage_ = "syllables";
        bar_ = 1.0;
        ask(bar_);
    }

private:
    // The most the bar shows before report_done: reports are double and may round up to 1.0.
    static constexpr double kBarBeforeDone = 1.0 - 1e-9;

    void ask(double bar) {
        if (!callback_(bar, stage_))
            throw Cancelled(std::string("alignment cancelled by the progress callback while ") + stage_ +
                            " at " + format_fixed(100.0 * bar, 1) + "%");
    }

    const ProgressCallback& callback_;
    const char* stage_ = nullptr;
    double planned_fraction_ = -1.0;
    double bar_ = 0.0;
    // Where the work done last began again: the planned fraction it began at, the bar then, and how
    // far the bar moves per planned fraction (1 until work is done again).
    double again_from_ = 0.0;
    double again_base_ = 0.0;
    double again_scale_ = 1.0;
};

// Progress after chain `w` of `count` in pass `pass` of `passes` (alignment_passes).
void report_pass(ProgressReporter& progress, int pass, int passes, std::size_t w, std::size_t count);

}  // namespace talkface::detail

#endif
