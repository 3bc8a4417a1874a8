#include "speech/dropout_finder.hpp"

#include <algorithm>
#include <cmath>

#include "audio/audio_source.hpp"

namespace talkface::detail {

void DropoutFinder::push(const float* samples, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        const float level = std::fabs(samples[i]);
        if (level == 0.0f) {
            if (run_length_ == 0) run_first_ = samples_in_;
            ++run_length_;
            // The history still holds the kSideSamples before the run: read them now, once a run.
            if (run_length_ == kShortestDropoutSamples) {
                run_before_cut_ = 0.0f;
                run_before_side_ = 0.0f;
                // This zero is not in the history yet: the run's first went to next_ - (run_length_ - 1).
                for (std::size_t back = 1; back <= kSideSamples && back <= run_first_; ++back) {
                    const float before =
                        history_[(next_ + kHistory - (kShortestDropoutSamples - 1) - back) % kHistory];
                    run_before_side_ = std::max(run_before_side_, before);
                    if (back <= kCutSamples) run_before_cut_ = std::max(run_before_cut_, before);
                }
            }
        } else if (run_length_ > 0) {
            end_run();
        }
        for (auto& candidate : waiting_) {
            if (candidate.after_seen < kCutSamples)
                candidate.after_cut = std::max(candidate.after_cut, level);
            candidate.after_side = std::max(candidate.after_side, level);
            ++candidate.after_seen;
        }
        while (!waiting_.empty() && waiting_.front().after_seen == kSideSamples) {
            judge(waiting_.front());
            waiting_.erase(waiting_.begin());
        }
        history_[next_] = level;
        next_ = next_ + 1 == kHistory ? 0 : next_ + 1;
        ++samples_in_;
    }
}

void DropoutFinder::end_run() {
    if (run_length_ >= kShortestDropoutSamples && run_length_ <= kLongestDropoutSamples &&
        run_before_side_ > 0.0f)
        waiting_.push_back(
            {{run_first_, run_first_ + run_length_}, run_before_cut_, run_before_side_, 0.0f, 0.0f, 0});
    run_length_ = 0;
}

void DropoutFinder::judge(const Candidate& candidate) {
    if (!(candidate.after_side > 0.0f)) return;
    const float before = candidate.before_cut / candidate.before_side;
    const float after = candidate.after_cut / candidate.after_side;
    if (std::min(before, after) >= kCutShare && std::max(before, after) >= kCleanCutShare)
        found_.push_back(candidate.run);
}

std::vector<Dropout> DropoutFinder::finish() {
    for (const auto& candidate : waiting_) judge(candidate);
    waiting_.clear();
    return std::move(found_);
}

std::vector<Dropout> outside_codec_pauses(std::vector<Dropout> dropouts,
                                          const std::vector<CodecPause>& pauses, int rate_hz) {
    const auto meets_pause = [&](const Dropout& dropout) {
        const double first_s = static_cast<double>(dropout.first_sample) / rate_hz;
        const double end_s = static_cast<double>(dropout.end_sample) / rate_hz;
        return std::any_of(pauses.begin(), pauses.end(), [&](const CodecPause& pause) {
            return first_s < pause.end_s && pause.start_s < end_s;
        });
    };
    dropouts.erase(std::remove_if(dropouts.begin(), dropouts.end(), meets_pause), dropouts.end());
    return dropouts;
}

}  // namespace talkface::detail
