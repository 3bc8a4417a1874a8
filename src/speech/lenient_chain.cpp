#include "speech/lenient_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/number_format.hpp"
#include "speech/syllable_placement.hpp"

namespace talkface::detail {

namespace {

// The costs that decide between the text and generic speech, in the units of the emission scores
// (re-estimated log-likelihoods per 10 ms frame, scaled by kReestimatedWeight). Generic speech
// scores every frame as the class that fits it best; on the test clips a right syllable's frames
// lose 0.0-0.25 a frame to their best class, so generic speech pays 0.1 a frame (kGenericSpeechFrameLogPenalty) and 8 to enter,
// and skipping a syllable of the text costs 20: less, and right syllables that fit a little worse
// than usual were skipped (one in three clips); more, and a changed word was no longer found.
constexpr double kGenericEntryLogPenalty = -8.0;
constexpr double kSkipSyllableLogPenalty = -20.0;
constexpr double kGenericMedianFrames = 30.0;
constexpr std::size_t kGenericMaxFrames = 150;
// Where the syllables of a stretch are spread: each boundary is the quietest frame within this
// share of a syllable's width around its even place.
constexpr double kBoundarySearchShare = 0.35;

bool is_syllable_state(const PhoneState& state) {
    return !is_pause(state.role) && state.role != StateRole::generic_speech;
}

PhoneState generic_state(std::size_t syllable) {
    PhoneState state;
    state.phone_class = kGenericSpeech;
    state.role = StateRole::generic_speech;
    state.syllable = syllable;
    state.median_frames = kGenericMedianFrames;
    state.log_sigma = 0.8;
    state.min_frames = 5;
    state.max_frames = kGenericMaxFrames;
    state.is_optional = true;
    state.has_tail = true;
    state.entry_log_penalty = kGenericEntryLogPenalty;
    state.frame_log_penalty = kGenericSpeechFrameLogPenalty;
    return state;
}

// A place in the chain's order: 2 i + 1 is syllable i, 2 i + 2 the generic speech after it, 0
// the generic speech before the first syllable.
std::size_t place_of(const PhoneState& state, bool is_leading) {
    if (state.role == StateRole::generic_speech) return is_leading ? 0 : 2 * state.syllable + 2;
    return 2 * state.syllable + 1;
}

struct Marked {
    std::size_t place = 0;
    std::size_t first_frame = std::numeric_limits<std::size_t>::max();  // chain frames; none: max
    std::size_t end_frame = 0;
};

std::string joined_text(const Timeline& result, std::size_t first, std::size_t count) {
    std::string text;
    for (std::size_t i = first; i < first + count; ++i) {
        const std::string& piece = result.syllables[i].text;
        const bool is_ascii = std::all_of(piece.begin(), piece.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
        if (!text.empty() && is_ascii) text += ' ';
        text += piece;
    }
    return text;
}

// `count` syllables over frames [first, end) of the audio, split at the quietest frame near each
// even boundary: the syllables of speech the text does not say open the mouth where it is loud.
std::vector<std::size_t> loudness_boundaries(const LoudnessProfile& loudness, std::size_t first, std::size_t end,
                                             std::size_t count) {
    std::vector<std::size_t> bounds{first};
    const double width = static_cast<double>(end - first) / static_cast<double>(count);
    for (std::size_t k = 1; k < count; ++k) {
        const double even = static_cast<double>(first) + width * static_cast<double>(k);
        const auto low = static_cast<std::size_t>(std::max(static_cast<double>(bounds.back() + 1), even - kBoundarySearchShare * width));
        const auto high = static_cast<std::size_t>(std::min(static_cast<double>(end), even + kBoundarySearchShare * width));
        std::size_t best = std::min(static_cast<std::size_t>(even), end);
        for (std::size_t t = low; t < high && t < loudness.activity_db.size(); ++t)
            if (loudness.activity_db[t] < loudness.activity_db[best]) best = t;
        bounds.push_back(std::max(best, bounds.back()));
    }
    bounds.push_back(end);
    return bounds;
}

// TextMismatch::loudness of frames [first, end) of the audio: 0 at the loudness the aligner takes
// for speech, 1 at the recording's loud speech, so that the mouth closes where the cutter hears a
// pause and opens as wide as the loudest syllables on the recording's loud ones.
std::vector<double> loudness_envelope(const LoudnessProfile& loudness, std::size_t first, std::size_t end) {
    const auto step_frames = static_cast<std::size_t>(std::lround(kMismatchLoudnessStepS / kFrameStepS));
    const double floor_db = loudness.activity_threshold_db;
    const double range_db = static_cast<double>(loudness.speech_level_db) - floor_db;
    std::vector<double> envelope;
    end = std::min(end, loudness.activity_db.size());
    for (std::size_t t = first; t < end; t += step_frames) {
        const std::size_t stop = std::min(end, t + step_frames);
        double sum_db = 0.0;
        for (std::size_t i = t; i < stop; ++i) sum_db += loudness.activity_db[i];
        const double above_db = sum_db / static_cast<double>(stop - t) - floor_db;
        const double level = range_db > 0.0 ? above_db / range_db : (above_db > 0.0 ? 1.0 : 0.0);
        envelope.push_back(std::round(std::clamp(level, 0.0, 1.0) * 100.0) / 100.0);
    }
    return envelope;
}

}  // namespace

SentenceChain lenient_chain(const SentenceChain& chain) {
    SentenceChain lenient = chain;
    lenient.states.clear();
    std::vector<std::size_t> states_per_syllable(chain.syllables.size(), 0);
    for (const PhoneState& state : chain.states)
        if (is_syllable_state(state)) ++states_per_syllable[state.syllable];
    for (std::size_t s = 0; s < chain.states.size(); ++s) {
        PhoneState state = chain.states[s];
        if (is_syllable_state(state))
            state.skip_log_penalty = kSkipSyllableLogPenalty / static_cast<double>(states_per_syllable[state.syllable]);
        lenient.states.push_back(state);
        if (s == 0) lenient.states.push_back(generic_state(0));
        const bool ends_syllable = is_syllable_state(state) &&
                                   (s + 1 == chain.states.size() || !is_syllable_state(chain.states[s + 1]) ||
                                    chain.states[s + 1].syllable != state.syllable);
        if (ends_syllable) lenient.states.push_back(generic_state(state.syllable));
    }
    return lenient;
}

void place_lenient(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores,
                   const FeatureTrack& track, const LoudnessProfile& loudness, Timeline& result,
                   std::vector<double>& evidence) {
    const std::size_t count = chain.syllables.size();
    std::vector<std::size_t> states_per_syllable(count, 0), states_on_path(count, 0);
    for (const PhoneState& state : chain.states)
        if (is_syllable_state(state)) ++states_per_syllable[state.syllable];
    std::vector<StateSegment> text_path;
    std::vector<Marked> marked;
    for (const StateSegment& segment : path) {
        const PhoneState& state = chain.states[segment.state];
        if (state.role == StateRole::generic_speech) {
            marked.push_back({place_of(state, segment.state == 1), segment.first_frame, segment.end_frame});
            continue;
        }
        if (is_syllable_state(state)) ++states_on_path[state.syllable];
        text_path.push_back(segment);
    }
    place_syllables(chain, text_path, scores, track, result, evidence);
    for (std::size_t i = 0; i < count; ++i) {
        if (states_on_path[i] == states_per_syllable[i]) continue;
        Marked syllable{2 * i + 1};
        for (const StateSegment& segment : text_path) {
            const PhoneState& state = chain.states[segment.state];
            if (!is_syllable_state(state) || state.syllable != i) continue;
            syllable.first_frame = std::min(syllable.first_frame, segment.first_frame);
            syllable.end_frame = std::max(syllable.end_frame, segment.end_frame);
        }
        marked.push_back(syllable);
    }
    std::sort(marked.begin(), marked.end(), [](const Marked& a, const Marked& b) { return a.place < b.place; });

    const std::size_t offset = chain.searched.first_frame;
    auto time_s = [&](std::size_t frame) {
        return std::min(track.duration_s, static_cast<double>(offset + frame) * kFrameStepS);
    };
    for (std::size_t g = 0; g < marked.size();) {
        // Neighbouring places join; two skipped syllables are neighbours across the generic
        // speech between them that the path did not take.
        std::size_t h = g + 1;
        while (h < marked.size() && (marked[h].place == marked[h - 1].place + 1 ||
                                     (marked[h].place == marked[h - 1].place + 2 && marked[h].place % 2 == 1)))
            ++h;
        std::size_t first = std::numeric_limits<std::size_t>::max(), end = 0;
        std::size_t first_local = count, local_count = 0;
        for (std::size_t m = g; m < h; ++m) {
            first = std::min(first, marked[m].first_frame);
            end = std::max(end, marked[m].end_frame);
            if (marked[m].place % 2 == 1) {
                first_local = std::min(first_local, marked[m].place / 2);
                ++local_count;
            }
        }
        const std::size_t after_place = marked[h - 1].place;
        g = h;
        if (first >= end) {
            // Syllables the speech leaves out: an instant, where the text's path goes on.
            first = end = 0;
            for (const StateSegment& segment : text_path) {
                const PhoneState& state = chain.states[segment.state];
                if (is_syllable_state(state) && 2 * state.syllable + 1 < marked[g - 1].place) first = end = segment.end_frame;
            }
        }
        TextMismatch mismatch;
        mismatch.start_s = time_s(first);
        mismatch.end_s = time_s(end);
        mismatch.loudness = loudness_envelope(loudness, offset + first, offset + end);
        if (local_count > 0) {
            const std::size_t global = chain.syllable_indices[first_local];
            mismatch.first_syllable = global;
            mismatch.syllable_count = local_count;
            mismatch.expected_text = joined_text(result, global, local_count);
            const auto bounds = loudness_boundaries(loudness, offset + first, offset + end, local_count);
            for (std::size_t k = 0; k < local_count; ++k) {
                Syllable& syllable = result.syllables[global + k];
                syllable.start_s = std::min(track.duration_s, static_cast<double>(bounds[k]) * kFrameStepS);
                syllable.end_s = std::min(track.duration_s, static_cast<double>(bounds[k + 1]) * kFrameStepS);
                syllable.final_start_s = syllable.start_s + 0.3 * (syllable.end_s - syllable.start_s);
                syllable.confidence = 0.0;
                // Not measured: set_confidences leaves it at 0.
                evidence[global + k] = std::numeric_limits<double>::quiet_NaN();
            }
        } else {
            mismatch.first_syllable = after_place / 2 < count ? chain.syllable_indices[after_place / 2]
                                                              : chain.syllable_indices.back() + 1;
        }
        const std::size_t sentence = mismatch.syllable_count > 0 ? result.syllables[mismatch.first_syllable].sentence
                                                                 : chain.syllables[std::min(after_place / 2, count - 1)]->sentence;
        result.warnings.push_back(
            "sentence " + std::to_string(sentence + 1) + " at " + format_fixed(mismatch.start_s, 2) + "-" +
            format_fixed(mismatch.end_s, 2) + " s: " +
            (mismatch.syllable_count > 0 ? "the speech does not say \"" + mismatch.expected_text + "\""
                                         : std::string("speech the transcript lacks")) +
            " (lenient alignment: fitted as generic speech, the mouth follows its loudness)");
        result.mismatches.push_back(std::move(mismatch));
    }
}

}  // namespace talkface::detail
