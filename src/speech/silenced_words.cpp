#include "speech/silenced_words.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "common/number_format.hpp"
#include "common/order_statistics.hpp"

namespace talkface::detail {

namespace {

// A syllable starting this little after a run's start starts with it: the frames' windows read a
// run of zeros up to half a window short of the samples'.
constexpr double kStartsWithRunS = 0.02;

struct SilenceRun {
    double start_s = 0.0;
    double end_s = 0.0;
};

std::vector<SilenceRun> silence_runs(const FeatureTrack& track, double track_start_s) {
    std::vector<SilenceRun> runs;
    const auto shortest = static_cast<std::size_t>(std::ceil(kShortestSilencedS * kFramesPerSecond));
    std::size_t t = 0;
    while (t < track.frame_count) {
        if (track.at(t, kEnergyDb) > kDigitalSilenceDb) {
            ++t;
            continue;
        }
        const std::size_t first = t;
        while (t < track.frame_count && track.at(t, kEnergyDb) <= kDigitalSilenceDb) ++t;
        if (t - first >= shortest)
            runs.push_back({track_start_s + frame_time_s(first), track_start_s + frame_time_s(t)});
    }
    return runs;
}

double median_length(const std::vector<Syllable>& syllables) {
    std::vector<double> lengths;
    lengths.reserve(syllables.size());
    for (const Syllable& syllable : syllables) lengths.push_back(syllable.end_s - syllable.start_s);
    return upper_median(std::move(lengths));
}

// The index of the first syllable starting at `time_s` or later; syllables.size() where none does.
std::size_t first_starting_after(const std::vector<Syllable>& syllables, double time_s) {
    std::size_t i = 0;
    while (i < syllables.size() && syllables[i].start_s < time_s) ++i;
    return i;
}

double overlap_s(const Syllable& syllable, const SilenceRun& run) {
    return std::max(0.0, std::min(syllable.end_s, run.end_s) - std::max(syllable.start_s, run.start_s));
}

}  // namespace

std::vector<std::string> describe_silenced_words(const FeatureTrack& track, double track_start_s,
                                                 const Timeline& aligned,
                                                 const std::vector<LostAudio>& lost) {
    std::vector<std::string> warnings;
    const std::vector<Syllable>& syllables = aligned.syllables;
    if (syllables.size() < 2 * kSyllablesBeside) return warnings;
    const double typical_s = median_length(syllables);
    if (!(typical_s > 0.0)) return warnings;
    for (const SilenceRun& run : silence_runs(track, track_start_s)) {
        if (std::any_of(lost.begin(), lost.end(), [&](const LostAudio& stretch) {
                return stretch.start_s < run.end_s && stretch.end_s > run.start_s;
            }))
            continue;
        const std::size_t after = first_starting_after(syllables, run.start_s + kStartsWithRunS);
        if (after == 0 || after == syllables.size()) continue;
        const Syllable& before = syllables[after - 1];
        // A pause the text marks, or one between sentences, may be recorded as exact zeros.
        if (before.pause_after || before.sentence != syllables[after].sentence) continue;
        const std::size_t first = after - std::min(after, kSyllablesBeside);
        const std::size_t end = std::min(syllables.size(), after + kSyllablesBeside);
        std::size_t squeezed = 0;
        bool is_on_silence = false;
        std::string beside;
        std::string lengths;
        for (std::size_t i = first; i < end; ++i) {
            const Syllable& syllable = syllables[i];
            if (syllable.sentence != before.sentence) continue;
            // The syllable before the run is read up to the run: the aligner may let it ring on into it.
            const double length_s =
                (i + 1 == after ? std::min(syllable.end_s, run.start_s) : syllable.end_s) - syllable.start_s;
            squeezed += length_s < kSqueezedShare * typical_s;
            const double syllable_s = syllable.end_s - syllable.start_s;
            is_on_silence |=
                syllable_s > 0.0 && overlap_s(syllable, run) >= kLeastOnSilenceShare * syllable_s;
            beside += syllable.text;
            lengths += (lengths.empty() ? "" : ", ") + std::string("\"") + syllable.text + "\" " +
                       format_fixed(1000.0 * std::max(0.0, length_s), 0) + " ms";
        }
        if (squeezed < kLeastSqueezed && !is_on_silence) continue;
        warnings.push_back(
            "sentence " + std::to_string(before.sentence + 1) + ": " + format_fixed(run.start_s, 2) + "-" +
            format_fixed(run.end_s, 2) +
            " s is digital silence (exact zeros), and the syllables beside it are squeezed against it (" +
            lengths + "; the recording's syllables take " + format_fixed(1000.0 * typical_s, 0) +
            " ms): is a word of \"" + beside +
            "\" silenced there by an editor, its text kept? Its syllables' times are guesses; take the "
            "word out of the transcript, or the silence out of the recording");
    }
    return warnings;
}

}  // namespace talkface::detail
