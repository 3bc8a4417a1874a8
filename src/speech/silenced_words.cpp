#include "speech/silenced_words.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "common/number_format.hpp"
#include "common/order_statistics.hpp"
#include "speech/alignment_checks.hpp"

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

template <class Stretch>
bool meets(const std::vector<Stretch>& stretches, const SilenceRun& run) {
    return std::any_of(stretches.begin(), stretches.end(), [&](const Stretch& stretch) {
        return stretch.start_s < run.end_s && stretch.end_s > run.start_s;
    });
}

// Whether `run` opens where a second recording joined to the file begins, or holds that time: a
// recording that opens in digital silence, its first frames' windows reading the zeros up to
// kStartsWithRunS late.
bool meets_join(std::optional<double> second_starts_s, const SilenceRun& run) {
    return second_starts_s && *second_starts_s >= run.start_s - kStartsWithRunS &&
           *second_starts_s <= run.end_s;
}

double overlap_s(const Syllable& syllable, const SilenceRun& run) {
    return std::max(0.0, std::min(syllable.end_s, run.end_s) - std::max(syllable.start_s, run.start_s));
}

// The syllables [first, end) judged on one side of a run: up to kSyllablesBeside next to it, in the
// sentence of the one nearest it.
struct Side {
    std::size_t first = 0;
    std::size_t end = 0;
};

Side side_before(const std::vector<Syllable>& syllables, std::size_t after) {
    Side side{after, after};
    while (side.first > 0 && after - side.first < kSyllablesBeside &&
           syllables[side.first - 1].sentence == syllables[after - 1].sentence)
        --side.first;
    return side;
}

Side side_after(const std::vector<Syllable>& syllables, std::size_t after) {
    Side side{after, after};
    while (side.end < syllables.size() && side.end - after < kSyllablesBeside &&
           syllables[side.end].sentence == syllables[after].sentence)
        ++side.end;
    return side;
}

struct Judged {
    std::size_t squeezed = 0;
    bool is_on_silence = false;
    std::string text;
    std::string lengths;
};

// `after` is the first syllable after the run: the one before it is read up to the run, as the
// aligner may let it ring on into it.
Judged judge(const std::vector<Syllable>& syllables, Side side, std::size_t after, const SilenceRun& run,
             double squeezed_s) {
    Judged judged;
    for (std::size_t i = side.first; i < side.end; ++i) {
        const Syllable& syllable = syllables[i];
        const double length_s =
            (i + 1 == after ? std::min(syllable.end_s, run.start_s) : syllable.end_s) - syllable.start_s;
        judged.squeezed += length_s < squeezed_s;
        const double syllable_s = syllable.end_s - syllable.start_s;
        judged.is_on_silence |=
            syllable_s > 0.0 && overlap_s(syllable, run) >= kLeastOnSilenceShare * syllable_s;
        judged.text += syllable.text;
        judged.lengths += (judged.lengths.empty() ? "" : ", ") + std::string("\"") + syllable.text + "\" " +
                          format_fixed(1000.0 * std::max(0.0, length_s), 0) + " ms";
    }
    return judged;
}

std::string describe(const SilenceRun& run, std::size_t sentence, const Judged& judged, double typical_s) {
    return "sentence " + std::to_string(sentence + 1) + ": " + format_fixed(run.start_s, 2) + "-" +
           format_fixed(run.end_s, 2) +
           " s is digital silence (exact zeros), and the syllables beside it are squeezed against it (" +
           judged.lengths + "; the recording's syllables take " + format_fixed(1000.0 * typical_s, 0) +
           " ms): is a word of \"" + judged.text +
           "\" silenced there by an editor, its text kept? Its syllables' times are guesses; take the word "
           "out of the transcript, or the silence out of the recording";
}

// Whether `run` (times of the track) may hold a word of the sentence `named` silenced: it lasts
// kLeastSyllablesSilenced syllables or more, and lies kSyllablesFromPauseMark or more from every
// pause the text marks, the sentence's span shared evenly among its syllables.
bool may_hold_silenced_word(const Timeline& transcript, const NamedSentence& named, const SilenceRun& run) {
    std::vector<double> marks;  // in syllables from the sentence's start
    std::size_t count = 0;
    for (const Syllable& syllable : transcript.syllables) {
        if (syllable.sentence != named.sentence) continue;
        ++count;
        if (syllable.pause_after) marks.push_back(static_cast<double>(count));
    }
    if (count == 0) return false;
    const double per_syllable_s = (named.end_s - named.start_s) / static_cast<double>(count);
    const double first = (run.start_s - named.start_s) / per_syllable_s;
    const double last = (run.end_s - named.start_s) / per_syllable_s;
    return last - first >= kLeastSyllablesSilenced &&
           std::none_of(marks.begin(), marks.end(), [&](double mark) {
               return mark >= first - kSyllablesFromPauseMark && mark <= last + kSyllablesFromPauseMark;
           });
}

}  // namespace

std::optional<std::string> describe_zeros_in_refused_sentence(const FeatureTrack& track, double track_start_s,
                                                              const Timeline& transcript,
                                                              const std::string& refusal,
                                                              const std::vector<LostAudio>& lost,
                                                              const std::vector<CutToZeros>& cuts,
                                                              std::optional<double> second_starts_s) {
    const std::optional<NamedSentence> named = sentence_named_in(refusal);
    if (!named || named->sentence >= transcript.sentences.size()) return std::nullopt;
    for (const SilenceRun& run : silence_runs(track, track_start_s)) {
        if (meets(lost, run) || meets(cuts, run) || meets_join(second_starts_s, run)) continue;
        const SilenceRun on_track{run.start_s - track_start_s, run.end_s - track_start_s};
        if (on_track.start_s < named->start_s + kStartsWithRunS ||
            on_track.end_s > named->end_s - kStartsWithRunS ||
            !may_hold_silenced_word(transcript, *named, on_track))
            continue;
        return "the recording: " + format_fixed(on_track.start_s, 2) + "-" + format_fixed(on_track.end_s, 2) +
               " s, inside sentence " + std::to_string(named->sentence + 1) +
               ", is digital silence (exact zeros) where its text marks no pause, as an editor leaves a word "
               "it "
               "silenced: is a word of the text silenced there, its text kept? Take the word out of the "
               "transcript, or the silence out of the recording";
    }
    return std::nullopt;
}

std::vector<std::string> describe_silenced_words(const FeatureTrack& track, double track_start_s,
                                                 const Timeline& aligned, const std::vector<LostAudio>& lost,
                                                 const std::vector<CutToZeros>& cuts,
                                                 std::optional<double> second_starts_s) {
    std::vector<std::string> warnings;
    const std::vector<Syllable>& syllables = aligned.syllables;
    if (syllables.size() < 2 * kSyllablesBeside) return warnings;
    const double typical_s = median_length(syllables);
    if (!(typical_s > 0.0)) return warnings;
    for (const SilenceRun& run : silence_runs(track, track_start_s)) {
        if (meets(lost, run) || meets(cuts, run) || meets_join(second_starts_s, run)) continue;
        const std::size_t after = first_starting_after(syllables, run.start_s + kStartsWithRunS);
        const Side before_side = after == 0 ? Side{} : side_before(syllables, after);
        const Side after_side = after == syllables.size() ? Side{after, after} : side_after(syllables, after);
        const bool is_inside = after > 0 && after < syllables.size() && !syllables[after - 1].pause_after &&
                               syllables[after - 1].sentence == syllables[after].sentence;
        if (is_inside) {
            const Judged judged =
                judge(syllables, {before_side.first, after_side.end}, after, run, kSqueezedShare * typical_s);
            if (judged.squeezed >= kLeastSqueezed || judged.is_on_silence)
                warnings.push_back(describe(run, syllables[after].sentence, judged, typical_s));
            continue;
        }
        // A pause the text marks, a sentence's edge or the recording's may be recorded as exact zeros,
        // with short syllables beside it: each side is judged alone, all of it squeezed further.
        for (const Side side : {before_side, after_side}) {
            const Judged judged = judge(syllables, side, after, run, kEdgeSqueezedShare * typical_s);
            if ((side.end - side.first == kSyllablesBeside && judged.squeezed == kSyllablesBeside) ||
                judged.is_on_silence) {
                warnings.push_back(describe(run, syllables[side.first].sentence, judged, typical_s));
                break;
            }
        }
    }
    return warnings;
}

}  // namespace talkface::detail
