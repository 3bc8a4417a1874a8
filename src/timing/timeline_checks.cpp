#include "timing/timeline_checks.hpp"

#include <cmath>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

std::string format_seconds(double seconds) {
    return std::isfinite(seconds) ? format_fixed(seconds, 3) : format_shortest(seconds);
}

std::string describe_syllable(const Timeline& timeline, std::size_t index) {
    const Syllable& syllable = timeline.syllables[index];
    return "syllable " + std::to_string(index) + " (\"" + syllable.pinyin + "\", " +
           format_seconds(syllable.start_s) + "-" + format_seconds(syllable.end_s) + " s)";
}

void check_timeline(const Timeline& timeline) {
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        const Syllable& syllable = timeline.syllables[k];
        if (!std::isfinite(syllable.start_s) || !std::isfinite(syllable.end_s) || syllable.start_s < 0.0) {
            throw InvalidArgument(describe_syllable(timeline, k),
                                  "times must be finite seconds from the start of the audio");
        }
        if (syllable.end_s < syllable.start_s) {
            throw InvalidArgument(describe_syllable(timeline, k), "ends before it starts");
        }
        if (k > 0 && syllable.start_s < timeline.syllables[k - 1].start_s) {
            throw InvalidArgument(
                describe_syllable(timeline, k),
                "starts before " + describe_syllable(timeline, k - 1) + "; syllables must be in time order");
        }
    }
    for (std::size_t k = 0; k < timeline.mismatches.size(); ++k) {
        const TextMismatch& mismatch = timeline.mismatches[k];
        const std::string item = "mismatch " + std::to_string(k) + " (" + format_seconds(mismatch.start_s) + "-" +
                                 format_seconds(mismatch.end_s) + " s)";
        if (!std::isfinite(mismatch.start_s) || !std::isfinite(mismatch.end_s) || mismatch.start_s < 0.0 ||
            mismatch.end_s < mismatch.start_s)
            throw InvalidArgument(item, "times must be finite seconds from the start of the audio, the end not before the start");
        if (mismatch.first_syllable > timeline.syllables.size() ||
            mismatch.syllable_count > timeline.syllables.size() - mismatch.first_syllable)
            throw InvalidArgument(item, "stands for syllables from " + std::to_string(mismatch.first_syllable) + " (" +
                                            std::to_string(mismatch.syllable_count) + " of them), past the " +
                                            std::to_string(timeline.syllables.size()) + " syllables");
        for (const double value : mismatch.loudness)
            if (!(value >= 0.0 && value <= 1.0))
                throw InvalidArgument(item, "loudness values must be in 0..1, found " + format_shortest(value));
    }
}

}  // namespace talkface::detail
