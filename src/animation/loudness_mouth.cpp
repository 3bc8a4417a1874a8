#include "animation/loudness_mouth.hpp"

#include <algorithm>
#include <cmath>

namespace talkface::detail {

namespace {

// Where the mouth leaves one shape for the next, on the loudness scale: below a tenth it is the
// breath and noise around speech, closed; the wide a only for the loudest third, the peaks of
// stressed vowels, so that ordinary syllables do not drop the jaw.
// (lip_sync.hpp documents these.)
constexpr double kClosedBelow = 0.1;
constexpr double kSlightBelow = 0.35;
constexpr double kHalfBelow = 0.67;

// The mean loudness of the values whose steps' middles lie within a frame's width around
// `time_s` (the one holding it where none does): the frames sample a smoothed envelope.
double loudness_at(const TextMismatch& mismatch, double time_s, double frame_s) {
    const std::vector<double>& values = mismatch.loudness;
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < values.size(); ++k) {
        const double middle_s = mismatch.start_s + (static_cast<double>(k) + 0.5) * kMismatchLoudnessStepS;
        if (std::abs(middle_s - time_s) <= frame_s / 2.0) {
            sum += values[k];
            ++count;
        }
    }
    if (count > 0) return sum / count;
    const double step = std::floor((time_s - mismatch.start_s) / kMismatchLoudnessStepS);
    return values[static_cast<std::size_t>(std::clamp(step, 0.0, static_cast<double>(values.size() - 1)))];
}

}  // namespace

MouthShape loudness_shape(double loudness) {
    if (loudness < kClosedBelow) return MouthShape::m;
    if (loudness < kSlightBelow) return MouthShape::z;
    if (loudness < kHalfBelow) return MouthShape::n;
    return MouthShape::a;
}

std::vector<MouthKeyFrame> loudness_key_frames(const Timeline& timeline, const TextMismatch& mismatch, double fps) {
    std::vector<MouthKeyFrame> keys;
    if (mismatch.loudness.empty()) return keys;
    const auto first_frame = static_cast<long long>(std::ceil(mismatch.start_s * fps - 1e-9));
    const auto last_frame = static_cast<long long>(std::floor(mismatch.end_s * fps + 1e-9));
    for (long long frame = first_frame; frame <= last_frame; ++frame) {
        const double time_s = static_cast<double>(frame) / fps;
        MouthKeyFrame key{time_s, loudness_shape(loudness_at(mismatch, time_s, 1.0 / fps)), std::nullopt};
        for (std::size_t i = mismatch.first_syllable; i < mismatch.first_syllable + mismatch.syllable_count; ++i)
            if (timeline.syllables[i].start_s <= time_s && time_s < timeline.syllables[i].end_s) key.syllable = i;
        // A run of one shape keeps its first and last key frames only.
        if (keys.size() >= 2 && keys[keys.size() - 1].shape == key.shape && keys[keys.size() - 2].shape == key.shape)
            keys.back() = key;
        else
            keys.push_back(key);
    }
    return keys;
}

}  // namespace talkface::detail
