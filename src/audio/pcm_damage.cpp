#include "audio/pcm_damage.hpp"

#include <algorithm>
#include <cmath>

#include "common/number_format.hpp"

namespace talkface::detail {

namespace {

std::size_t frames_of(double seconds, int sample_rate_hz) {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(seconds * sample_rate_hz)));
}

// "0.512 s, 1.377 s and 2.003 s (and 4 more)", or spans "1.616-1.744 s": the first three.
std::string describe_times(const std::vector<DamagedSamples>& found, int sample_rate_hz, bool as_spans) {
    constexpr std::size_t kNamed = 3;
    const auto seconds = [&](std::size_t frame) {
        return format_fixed(static_cast<double>(frame) / sample_rate_hz, 3);
    };
    std::string text;
    const std::size_t named = std::min(found.size(), kNamed);
    for (std::size_t i = 0; i < named; ++i) {
        if (i > 0) text += i + 1 == named && found.size() <= kNamed ? " and " : ", ";
        text += seconds(found[i].first_frame);
        if (as_spans) text += "-" + seconds(found[i].end_frame);
        text += " s";
    }
    if (found.size() > kNamed) text += " (and " + std::to_string(found.size() - kNamed) + " more)";
    return text;
}

}  // namespace

PcmDamageFinder::PcmDamageFinder(int sample_rate_hz)
    : local_(frames_of(kLocalSeconds, sample_rate_hz)),
      shortest_zeros_(frames_of(kShortestZerosSeconds, sample_rate_hz)),
      cut_(frames_of(kCutSeconds, sample_rate_hz)),
      side_(frames_of(kSideSeconds, sample_rate_hz)),
      ramp_(frames_of(kRampSeconds, sample_rate_hz)) {}

void PcmDamageFinder::push(const float* mono, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) peak_ = std::max(peak_, std::fabs(mono[i]));
    buffer_.insert(buffer_.end(), mono, mono + count);
    const std::size_t end_frame = base_frame_ + buffer_.size();
    // A frame is judged once the side after it is in: a click's local spread, a run's cut.
    if (end_frame > side_ + 1) judge_up_to(end_frame - side_ - 1);
    // Keep the side before the next frame to judge, and before a run of zeros not yet long enough.
    const std::size_t kept = side_ + shortest_zeros_ + 1;
    const std::size_t keep_from = std::max(base_frame_, next_frame_ > kept ? next_frame_ - kept : 0);
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(keep_from - base_frame_));
    base_frame_ = keep_from;
}

void PcmDamageFinder::restart_at(std::size_t frame) {
    buffer_.clear();
    base_frame_ = frame;
    next_frame_ = frame;
    zeros_length_ = 0;
}

void PcmDamageFinder::finish() {
    judge_up_to(base_frame_ + buffer_.size());
    zeros_length_ = 0;
    for (const auto& [run, quieter_side] : cut_runs_)
        if (quieter_side >= kSideShareOfPeak * peak_) cut_zeros_.push_back(run);
    cut_runs_.clear();
}

void PcmDamageFinder::judge_up_to(std::size_t end_frame) {
    const std::size_t buffer_end = base_frame_ + buffer_.size();
    for (std::size_t frame = next_frame_; frame < end_frame; ++frame) {
        if (sample(frame) == 0.0f) {
            if (zeros_length_ == 0) zeros_first_ = frame;
            // Taken once the run is long enough to judge: a quiet wave meets exact zero often.
            if (++zeros_length_ == shortest_zeros_) {
                zeros_before_side_ = loudest(zeros_first_ > side_ ? zeros_first_ - side_ : 0, zeros_first_);
                zeros_before_cut_ = loudest(zeros_first_ > cut_ ? zeros_first_ - cut_ : 0, zeros_first_);
                zeros_before_ramps_ =
                    zeros_first_ > base_frame_ + ramp_ && ramps_down_to(zeros_first_, zeros_before_side_);
            }
            continue;
        }
        if (zeros_length_ > 0) {
            judge_zeros(zeros_first_, frame);
            zeros_length_ = 0;
        }
        if (frame > base_frame_ && frame + 1 < buffer_end && is_click(frame)) {
            if (!clicks_.empty() && clicks_.back().end_frame == frame)
                clicks_.back().end_frame = frame + 1;
            else
                clicks_.push_back({frame, frame + 1});
        }
    }
    next_frame_ = std::max(next_frame_, end_frame);
}

bool PcmDamageFinder::is_click(std::size_t frame) const {
    const auto off_line = [this](std::size_t at) {
        return sample(at) - 0.5f * (sample(at - 1) + sample(at + 1));
    };
    const float off = std::fabs(off_line(frame));
    if (off < kClickLeast) return false;
    const std::size_t buffer_end = base_frame_ + buffer_.size();
    const std::size_t from = std::max(base_frame_ + 1, frame > local_ ? frame - local_ : 0);
    const std::size_t to = std::min(buffer_end - 1, frame + local_ + 1);
    // Outwards from the sample, so that a voice's ringing ends the search at its next-but-one sample.
    const float bound = off / kClickOverLocal;
    for (std::size_t step = 2; frame >= from + step || frame + step < to; ++step) {
        if (frame >= from + step && std::fabs(off_line(frame - step)) >= bound) return false;
        if (frame + step < to && std::fabs(off_line(frame + step)) >= bound) return false;
    }
    return true;
}

float PcmDamageFinder::loudest(std::size_t from_frame, std::size_t to_frame) const {
    float peak = 0.0f;
    for (std::size_t at = std::max(from_frame, base_frame_);
         at < std::min(to_frame, base_frame_ + buffer_.size()); ++at)
        peak = std::max(peak, std::fabs(sample(at)));
    return peak;
}

bool PcmDamageFinder::ramps_down_to(std::size_t first_zero, float side_loudest) const {
    const auto out = [&](std::size_t steps) { return sample(first_zero - 1 - steps); };
    const float next_to_zeros = std::fabs(out(0));
    if (next_to_zeros >= kCutShare * side_loudest) return false;
    // espeak-ng's ramps are straight lines to zero: its two last samples stand 1.97-2 times apart.
    if (std::fabs(out(1)) < kRampSteepness * next_to_zeros) return false;
    // Rising steadily away from the zeros on one side of zero (a wave crossing zero there is no ramp).
    for (std::size_t i = 0; i < ramp_; ++i)
        if (std::fabs(out(i + 1)) < std::fabs(out(i)) || (out(i + 1) < 0.0f) != (out(0) < 0.0f)) return false;
    return true;
}

void PcmDamageFinder::judge_zeros(std::size_t first_frame, std::size_t end_frame) {
    if (end_frame - first_frame < shortest_zeros_) return;
    const float before_side = zeros_before_side_;
    const float before_cut = zeros_before_cut_;
    const float after_side = loudest(end_frame, end_frame + side_);
    const float after_cut = loudest(end_frame, end_frame + cut_);
    if (before_cut < kCutShare * before_side || after_cut < kCutShare * after_side) return;
    if (before_cut < kCleanCutShare * before_side && after_cut < kCleanCutShare * after_side) return;
    if (zeros_before_ramps_) return;
    cut_runs_.push_back({{first_frame, end_frame}, std::min(before_side, after_side)});
}

std::vector<std::string> describe_pcm_damage(const PcmDamageFinder& finder, int sample_rate_hz) {
    std::vector<std::string> notes;
    if (!finder.cut_zeros().empty())
        notes.push_back("its sound is cut off mid-wave to exact digital zeros at " +
                        describe_times(finder.cut_zeros(), sample_rate_hz, true) +
                        ", as an editor's silence put over the sound leaves it, or a block of the "
                        "file's bytes zeroed by a copy or a disk, or a stream's lost packets: no sound "
                        "is left there (silenced on purpose, the file is as it should be), and the "
                        "syllables there were aligned to what is left");
    if (!finder.clicks().empty())
        notes.push_back("single samples jump far off the wave around them at " +
                        describe_times(finder.clicks(), sample_rate_hz, false) +
                        ", clicks no voice or microphone makes, as bytes changed by a copy or a disk "
                        "leave them: the file is damaged there");
    return notes;
}

}  // namespace talkface::detail
