#include "speech/lenient_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/number_format.hpp"
#include "common/order_statistics.hpp"
#include "speech/alignment_confidence.hpp"
#include "speech/rival_syllables.hpp"
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
// A syllable's fit (syllable_fits) is an outlier of its chain's where it lies more than this many
// median absolute deviations under their median, the usual bound. Syllables skipped are kept
// skipped only where one of them or a neighbour fits the plain path so badly (unsupported_skips), and
// a syllable beside a skipped one that fits the lenient path so badly joins the mismatch: the
// path skips a changed word's worst syllable and squeezes the other between it and its neighbours
// (a changed word was reported in part in 12 of 40 espeak-ng clips and whole in none, bench/README.md).
constexpr double kOutlierDeviations = 3.0;
// A right syllable's stretch, even one that fits the models as an outlier, fits its own text better
// than all but a few unlike syllables (rival_share: 0 for most, at most 0.08 for espeak-ng's and
// 0.2 for 95% of a person's in the read passages), where a changed word's skipped syllable lets
// 0.06-0.68 of them fit better. Skips are kept only where one of the run's syllables is rivalled
// by more than one in twenty: on the read passages that is most of the marks the outlier rule let
// through (espeak-ng's 車 著 周 春, a person's 婆 出 叫), bench/README.md.
constexpr double kMinRivalShare = 0.05;
// Speech the transcript lacks is at least a syllable of it, and a syllable is rarely shorter than
// three quarters of the sentence's median on its plain path: a shorter generic stretch is a right
// syllable's onset or tail, or a breath, that generic speech fits a little better than the text.
constexpr double kMinGenericSyllableShare = 0.75;
// The held-out gap of a syllable (held_out_fit_gaps, text_fit.hpp): how much better, per frame, free
// sounds fit its speech on the plain path than its text does, on models learned without its half of
// the sentence, so that a wrong text has not taught them its sounds. On the person's read passages
// (align_bench --lenient, tuning, h-clean r-clean r-white20 r-reverb) it tells a changed word's
// syllable from a right one with an AUC of 0.86 (0.93 clean, 0.77 in a room): right syllables median
// -0.03, 95th percentile 0.52; changed ones median 0.55. A syllable beside one a mismatch names
// joins it where its gap is above kMinHeldOutGapBeside: the path names a changed word's worse
// syllable and squeezes the other beside it, which then gaps as the named one does (changed words
// named whole 92 -> 124 of 360 there, right syllables of right texts named 32 -> 35).
constexpr double kMinHeldOutGapBeside = 0.5;
// A run of skipped syllables stays skipped only where one of them gaps at least this much: a
// right syllable the path skips, costing less skipped than fitted, gaps as its neighbours do,
// and the ones the other rules let through are mostly right syllables in noise. On the same
// passages, with kMinHeldOutGapBeside: changed words whole 124 -> 122, right syllables named in
// right texts 35 -> 32, in changed texts 266 -> 239, in texts that lack a word 255 -> 203 (at 0.1:
// 124, 32, 246, 231).
constexpr double kMinHeldOutGapSkipped = 0.2;
// A stretch's edge syllable that gaps under this (its text fits it on models that never heard it)
// is a right neighbour of the changed word, not part of it: it leaves the stretch, where it joined
// as an outlier of the lenient path's fits or was skipped with the word. On the person's read
// passages (tuning, h-clean r-clean r-white20 r-reverb) the stretch over a changed word named a
// right neighbour in 57 of the 122 words found whole; at 0.1 / 0.2 / 0.3: whole 119 / 114 / 108,
// with no neighbour 82 / 85 / 80 (65 before), other syllables named in changed texts 239 -> 203 /
// 176 / 157, right texts' syllables named 32 / 31 / 23 (bench/README.md, Session 16). The tuning
// rows chose 0.1 (fewest words lost to "in part"); the unit test's espeak-ng clip was seen too (its
// changed 校 gaps 0.196, and would leave its stretch at 0.2).
constexpr double kMinHeldOutGapAtEdge = 0.1;
// A syllable is heard as another where its held-out gap is above kMinHeldOutGapHeard and its tone
// gap (tone_contour.hpp: how much better a tone it cannot have fits its pitch than its own) above
// kMinToneGapHeard: a changed word whose sounds the broad classes hear alike (场大 said, 沙发
// written) often differs in its tones. Its skip costs kHeardOtherwiseSkipShare of another's, and a
// skipped run holding one is kept whatever the plain path's fits and the unlike syllables say.
// On the person's read passages (tuning, h-clean r-clean r-white20 r-reverb) a changed syllable
// whose tone differs from the said one's gaps above right ones with an AUC of 0.84 (0.52 where the
// tones are the same); right syllables' tone gaps: median -0.35, 95th percentile 3.8. Right
// syllables with both gaps above 0.5 and 3 were 24 of 4776, above 1.0 and 3 were 3 (bench/README.md,
// Session 17: at 0.5 / 0.8 / 1.0 the right syllables named went 32 -> 50 / 34 / 32).
constexpr double kMinHeldOutGapHeard = 1.0;
constexpr double kMinToneGapHeard = 3.0;
constexpr double kHeardOtherwiseSkipShare = 0.5;
// A skipped syllable whose held-out gap is above this stands, in a skipped run, for an outlier of
// the plain path's fits: in noise and rooms a chain's fits spread so widely that a changed word's
// syllable is no outlier (r-white20: 车 written for 貓, gapping 2.84), while held-out models, which never
// heard its text, tell it apart as well as in quiet. On the person's read passages (tuning,
// h-clean r-clean r-white20 r-reverb) 0.9% of right syllables gap above 1.0 (99th percentile
// 0.98) and 30% of changed ones; the run must still be rivalled and gapped (unsupported_skips).
// Changed words whole / missed 128 / 136 -> 136 / 126 of 360, right texts' syllables named 32 ->
// 38 of 4776; at 0.8 the same words for more marks (bench/README.md, Session 20).
constexpr double kMinHeldOutGapUnlike = 1.0;

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

// The fit under which a syllable's is an outlier among `fits` (those `is_counted`); none with
// fewer than three, or none spread, to tell the usual spread from.
double outlier_bound(const std::vector<double>& fits, const std::vector<bool>& is_counted) {
    std::vector<double> counted;
    for (std::size_t i = 0; i < fits.size(); ++i)
        if (is_counted[i]) counted.push_back(fits[i]);
    if (counted.size() < 3) return -std::numeric_limits<double>::infinity();
    const double median = upper_median(counted);
    for (double& fit : counted) fit = std::abs(fit - median);
    const double deviation = upper_median(counted);
    return deviation > 0.0 ? median - kOutlierDeviations * deviation : -std::numeric_limits<double>::infinity();
}

// Per syllable of `chain`, whether `path` passes every one of its states.
std::vector<bool> whole_syllables(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    std::vector<std::size_t> states_per_syllable(chain.syllables.size(), 0), states_on_path(chain.syllables.size(), 0);
    for (const PhoneState& state : chain.states)
        if (is_syllable_state(state)) ++states_per_syllable[state.syllable];
    for (const StateSegment& segment : path)
        if (is_syllable_state(chain.states[segment.state])) ++states_on_path[chain.states[segment.state].syllable];
    std::vector<bool> is_whole(chain.syllables.size());
    for (std::size_t i = 0; i < is_whole.size(); ++i) is_whole[i] = states_on_path[i] == states_per_syllable[i];
    return is_whole;
}

// Whether syllable `i` has a value (per syllable, as unsupported_skips takes rival shares and
// held-out gaps) under `bound`: judged (not NaN, not missing) and found wanting.
bool is_judged_under(const std::vector<double>& values, std::size_t i, double bound) {
    return i < values.size() && !std::isnan(values[i]) && values[i] < bound;
}

// Whether a syllable of [first, end) has a value of at least `bound`, or none to judge it by: a
// syllable not judged does not speak against the skip.
bool reaches_or_unjudged(const std::vector<double>& values, std::size_t first, std::size_t end, double bound) {
    for (std::size_t i = first; i < end; ++i)
        if (!is_judged_under(values, i, bound)) return true;
    return false;
}

// Syllables of the text's path (`is_whole`) next to a syllable it skips whose fit on the whole
// path is an outlier of the chain's, added to `marked`, outward until a syllable fits as usual;
// an outlier joins only where its held-out gap (`held_out_gaps`, per syllable; NaN or missing: not
// judged so) is at least kMinHeldOutGapAtEdge: the models re-estimated on the recording fit a
// right neighbour of a changed word badly as often as the word. A syllable that fits as usual
// joins too where its held-out gap is above kMinHeldOutGapBeside. Generic speech
// alone is not grown from: it is where the speech has words the text lacks, and the syllables
// around those are said (grown from by the held-out gap too, right syllables named in texts that
// lack a word went 209 -> 694 on the passages of kMinHeldOutGapBeside).
void add_outliers_beside(const std::vector<double>& fits, const std::vector<bool>& is_whole,
                         const std::vector<SyllableFrames>& frames, const std::vector<double>& held_out_gaps,
                         std::vector<Marked>& marked) {
    const double bound = outlier_bound(fits, is_whole);
    std::vector<bool> is_marked(fits.size());
    for (std::size_t i = 0; i < fits.size(); ++i) is_marked[i] = !is_whole[i];
    for (bool is_grown = true; is_grown;) {
        is_grown = false;
        for (std::size_t i = 0; i < fits.size(); ++i) {
            const bool is_beside = (i > 0 && is_marked[i - 1]) || (i + 1 < fits.size() && is_marked[i + 1]);
            const bool is_gapped = i < held_out_gaps.size() && held_out_gaps[i] > kMinHeldOutGapBeside;
            const bool is_outlier = fits[i] < bound && !is_judged_under(held_out_gaps, i, kMinHeldOutGapAtEdge);
            if (is_marked[i] || !is_beside || (!is_outlier && !is_gapped)) continue;
            marked.push_back({2 * i + 1, frames[i].first_frame, frames[i].end_frame});
            is_marked[i] = is_grown = true;
        }
    }
}

// The fit of the syllables of a chain with a mismatch that are not in one (measured), measured
// again on the whole lenient `path`: measured on the text's path alone, the margins of a syllable
// beside generic speech read its frames as silence, so that syllables beside a mismatch, nearly
// all in place, came out with confidences under 0.1. Their timing and steadiness stay the text
// path's (place_syllables): generic speech has no duration prior of a syllable's.
void set_fit_beside(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores,
                    const Timeline& result, std::vector<SyllableEvidence>& evidence) {
    const auto offset = static_cast<long>(chain.searched.first_frame);
    std::vector<std::size_t> kept;
    std::vector<SyllableFrames> frames;
    for (std::size_t local = 0; local < chain.syllables.size(); ++local) {
        const std::size_t global = chain.syllable_indices[local];
        if (!evidence[global].is_measured) continue;
        const Syllable& syllable = result.syllables[global];
        const long first = std::max(0L, std::lround(syllable.start_s / kFrameStepS) - offset);
        const long end = std::max(first + 1, std::lround(syllable.end_s / kFrameStepS) - offset);
        kept.push_back(local);
        frames.push_back({static_cast<std::size_t>(first), static_cast<std::size_t>(end)});
    }
    const std::vector<SyllableFit> fits = syllable_fit_parts(chain, path, scores, frames);
    for (std::size_t k = 0; k < kept.size(); ++k) evidence[chain.syllable_indices[kept[k]]].fit = fits[k];
}

}  // namespace

PhoneState generic_speech_state(std::size_t syllable) {
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

void add_rival_shares(const SentenceChain& lenient, const std::vector<StateSegment>& path,
                      const std::vector<SyllableFrames>& plain_frames, const EmissionScores& scores,
                      std::vector<double>& shares) {
    if (plain_frames.size() != lenient.syllables.size()) return;
    shares.resize(lenient.syllables.size(), std::numeric_limits<double>::quiet_NaN());
    const std::vector<bool> is_whole = whole_syllables(lenient, path);
    for (std::size_t i = 0; i < is_whole.size(); ++i)
        if (!is_whole[i] && std::isnan(shares[i])) shares[i] = rival_share(lenient, i, plain_frames[i], scores);
}

std::vector<bool> heard_otherwise(const std::vector<double>& held_out_gaps, const std::vector<double>& tone_gaps) {
    std::vector<bool> is_heard(held_out_gaps.size());
    for (std::size_t i = 0; i < is_heard.size() && i < tone_gaps.size(); ++i)
        is_heard[i] = held_out_gaps[i] > kMinHeldOutGapHeard && tone_gaps[i] > kMinToneGapHeard;
    return is_heard;
}

SentenceChain lenient_chain(const SentenceChain& chain, const std::vector<bool>& is_heard_otherwise) {
    SentenceChain lenient = chain;
    lenient.states.clear();
    std::vector<std::size_t> states_per_syllable(chain.syllables.size(), 0);
    for (const PhoneState& state : chain.states)
        if (is_syllable_state(state)) ++states_per_syllable[state.syllable];
    for (std::size_t s = 0; s < chain.states.size(); ++s) {
        PhoneState state = chain.states[s];
        if (is_syllable_state(state))
            state.skip_log_penalty = kSkipSyllableLogPenalty / static_cast<double>(states_per_syllable[state.syllable]) *
                                     (state.syllable < is_heard_otherwise.size() && is_heard_otherwise[state.syllable] ? kHeardOtherwiseSkipShare : 1.0);
        lenient.states.push_back(state);
        if (s == 0) lenient.states.push_back(generic_speech_state(0));
        const bool ends_syllable = is_syllable_state(state) &&
                                   (s + 1 == chain.states.size() || !is_syllable_state(chain.states[s + 1]) ||
                                    chain.states[s + 1].syllable != state.syllable);
        if (ends_syllable) lenient.states.push_back(generic_speech_state(state.syllable));
    }
    return lenient;
}

std::vector<double> fits_on_path(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                 const EmissionScores& scores) {
    return syllable_fits(chain, path, scores, frames_on_path(chain, path));
}

std::vector<std::size_t> unsupported_skips(const SentenceChain& lenient, const std::vector<StateSegment>& path,
                                           const std::vector<double>& plain_fits, const std::vector<double>& rival_shares,
                                           const std::vector<double>& held_out_gaps, const std::vector<bool>& is_heard_otherwise) {
    if (plain_fits.size() != lenient.syllables.size()) return {};
    const double bound = outlier_bound(plain_fits, std::vector<bool>(plain_fits.size(), true));
    const std::vector<bool> is_whole = whole_syllables(lenient, path);
    std::vector<std::size_t> unsupported;
    for (std::size_t first = 0; first < is_whole.size(); ++first) {
        if (is_whole[first]) continue;
        std::size_t end = first;
        while (end < is_whole.size() && !is_whole[end]) ++end;
        bool is_outlier = false;
        for (std::size_t j = first > 0 ? first - 1 : 0; j < std::min(is_whole.size(), end + 1); ++j)
            if (plain_fits[j] < bound) is_outlier = true;
        for (std::size_t i = first; i < end && i < held_out_gaps.size(); ++i)
            if (held_out_gaps[i] > kMinHeldOutGapUnlike) is_outlier = true;
        const bool is_rivalled = reaches_or_unjudged(rival_shares, first, end, kMinRivalShare);
        const bool is_gapped = reaches_or_unjudged(held_out_gaps, first, end, kMinHeldOutGapSkipped);
        bool is_heard = false;
        for (std::size_t i = first; i < end && i < is_heard_otherwise.size(); ++i) is_heard = is_heard || is_heard_otherwise[i];
        if (!is_heard && (!is_outlier || !is_rivalled || !is_gapped)) {
            for (std::size_t i = first; i < end; ++i) unsupported.push_back(i);
        } else {
            // A run kept loses the edge syllables that gap under kMinHeldOutGapAtEdge: the path
            // skipped a right neighbour of the changed word with it. A syllable that gaps more, or
            // is not judged, stops each end (the run has one: it is kept).
            std::size_t kept_first = first, kept_end = end;
            while (kept_first < kept_end && is_judged_under(held_out_gaps, kept_first, kMinHeldOutGapAtEdge))
                unsupported.push_back(kept_first++);
            while (kept_end > kept_first && is_judged_under(held_out_gaps, kept_end - 1, kMinHeldOutGapAtEdge))
                unsupported.push_back(--kept_end);
        }
        first = end;
    }
    return unsupported;
}

std::vector<std::size_t> short_generic(const SentenceChain& lenient, const std::vector<StateSegment>& path,
                                       const std::vector<SyllableFrames>& plain_frames) {
    std::vector<double> lengths;
    for (const SyllableFrames& frames : plain_frames)
        if (frames.end_frame > frames.first_frame) lengths.push_back(static_cast<double>(frames.end_frame - frames.first_frame));
    if (lengths.empty()) return {};
    const double shortest = kMinGenericSyllableShare * upper_median(lengths);
    std::vector<std::size_t> short_states;
    for (const StateSegment& segment : path)
        if (lenient.states[segment.state].role == StateRole::generic_speech &&
            static_cast<double>(segment.end_frame - segment.first_frame) < shortest)
            short_states.push_back(segment.state);
    return short_states;
}

void forbid_states(SentenceChain& lenient, const std::vector<std::size_t>& states) {
    for (std::size_t s : states) lenient.states[s].entry_log_penalty = -std::numeric_limits<double>::infinity();
}

void forbid_skips(SentenceChain& lenient, const std::vector<std::size_t>& syllables) {
    for (PhoneState& state : lenient.states)
        if (is_syllable_state(state) && std::find(syllables.begin(), syllables.end(), state.syllable) != syllables.end())
            state.skip_log_penalty = -std::numeric_limits<double>::infinity();
}

bool takes_text_whole(const SentenceChain& lenient, const std::vector<StateSegment>& path) {
    const std::vector<bool> is_whole = whole_syllables(lenient, path);
    return std::all_of(is_whole.begin(), is_whole.end(), [](bool whole) { return whole; }) &&
           std::none_of(path.begin(), path.end(), [&](const StateSegment& segment) {
               return lenient.states[segment.state].role == StateRole::generic_speech;
           });
}

namespace {

// The path's generic speech as marked places; the rest of the path, the text's, into `text_path`.
std::vector<Marked> generic_speech_marks(const SentenceChain& chain, const std::vector<StateSegment>& path,
                                         std::vector<StateSegment>& text_path) {
    std::vector<Marked> marked;
    for (const StateSegment& segment : path) {
        const PhoneState& state = chain.states[segment.state];
        if (state.role == StateRole::generic_speech) {
            marked.push_back({place_of(state, segment.state == 1), segment.first_frame, segment.end_frame});
            continue;
        }
        text_path.push_back(segment);
    }
    return marked;
}

// Adds to `marked` the syllables the path does not take whole and the outliers beside generic
// speech, and sorts it by place.
void add_syllable_marks(const SentenceChain& chain, const std::vector<StateSegment>& path,
                        const std::vector<double>& held_out_gaps, const EmissionScores& scores,
                        std::vector<Marked>& marked) {
    const std::vector<SyllableFrames> frames = frames_on_path(chain, path);
    const std::vector<bool> is_whole = whole_syllables(chain, path);
    for (std::size_t i = 0; i < chain.syllables.size(); ++i)
        if (!is_whole[i]) marked.push_back({2 * i + 1, frames[i].first_frame, frames[i].end_frame});
    // Fitted on the whole path: beside generic speech the text's path alone would be silence.
    add_outliers_beside(syllable_fits(chain, path, scores, frames), is_whole, frames, held_out_gaps, marked);
    std::sort(marked.begin(), marked.end(), [](const Marked& a, const Marked& b) { return a.place < b.place; });
}

// Marks [begin, end) that join into one mismatch: their frames and the syllables among them.
struct MarkedRun {
    std::size_t end = 0;  // one past the run's last mark
    std::size_t first_frame = std::numeric_limits<std::size_t>::max(), end_frame = 0;
    std::size_t first_local = 0, local_count = 0;  // the chain's syllables in the run
    std::size_t after_place = 0;                   // the run's last place
};

MarkedRun marked_run(const std::vector<Marked>& marked, std::size_t begin, std::size_t count) {
    MarkedRun run;
    // Neighbouring places join; two skipped syllables are neighbours across the generic
    // speech between them that the path did not take.
    run.end = begin + 1;
    while (run.end < marked.size() &&
           (marked[run.end].place == marked[run.end - 1].place + 1 ||
            (marked[run.end].place == marked[run.end - 1].place + 2 && marked[run.end].place % 2 == 1)))
        ++run.end;
    run.first_local = count;
    for (std::size_t m = begin; m < run.end; ++m) {
        run.first_frame = std::min(run.first_frame, marked[m].first_frame);
        run.end_frame = std::max(run.end_frame, marked[m].end_frame);
        if (marked[m].place % 2 == 1) {
            run.first_local = std::min(run.first_local, marked[m].place / 2);
            ++run.local_count;
        }
    }
    run.after_place = marked[run.end - 1].place;
    return run;
}

// Where syllables the speech leaves out stand: an instant, the end of the text's path's last
// syllable before `place`, where the text's path goes on (0 if none is).
std::size_t instant_before(const SentenceChain& chain, const std::vector<StateSegment>& text_path,
                           std::size_t place) {
    std::size_t instant = 0;
    for (const StateSegment& segment : text_path) {
        const PhoneState& state = chain.states[segment.state];
        if (is_syllable_state(state) && 2 * state.syllable + 1 < place) instant = segment.end_frame;
    }
    return instant;
}

// The run's syllables, unsaid, spread over its loudness's boundaries and left unmeasured; the
// mismatch names them.
void spread_unsaid_syllables(const SentenceChain& chain, const MarkedRun& run, std::size_t offset,
                             const FeatureTrack& track, const LoudnessProfile& loudness, Timeline& result,
                             std::vector<SyllableEvidence>& evidence, TextMismatch& mismatch) {
    const std::size_t global = chain.syllable_indices[run.first_local];
    mismatch.first_syllable = global;
    mismatch.syllable_count = run.local_count;
    mismatch.expected_text = joined_text(result, global, run.local_count);
    const auto bounds =
        loudness_boundaries(loudness, offset + run.first_frame, offset + run.end_frame, run.local_count);
    for (std::size_t k = 0; k < run.local_count; ++k) {
        Syllable& syllable = result.syllables[global + k];
        syllable.start_s = std::min(track.duration_s, frame_time_s(bounds[k]));
        syllable.end_s = std::min(track.duration_s, frame_time_s(bounds[k + 1]));
        syllable.final_start_s = syllable.start_s + 0.3 * (syllable.end_s - syllable.start_s);
        syllable.confidence = 0.0;
        // Not measured: set_confidences leaves it at 0.
        evidence[global + k].is_measured = false;
    }
}

std::string mismatch_warning(const TextMismatch& mismatch, std::size_t sentence) {
    return "sentence " + std::to_string(sentence + 1) + " at " + format_fixed(mismatch.start_s, 2) + "-" +
           format_fixed(mismatch.end_s, 2) + " s: " +
           (mismatch.syllable_count > 0 ? "the speech does not say \"" + mismatch.expected_text + "\""
                                        : std::string("speech the transcript lacks")) +
           " (lenient alignment: fitted as generic speech, the mouth follows its loudness)";
}

}  // namespace

void place_lenient(const SentenceChain& chain, std::size_t chain_index, const std::vector<StateSegment>& path,
                   const std::vector<std::vector<SyllableFrames>>& other_frames,
                   const std::vector<double>& held_out_gaps, const EmissionScores& scores,
                   const FeatureTrack& track, const LoudnessProfile& loudness, Timeline& result,
                   std::vector<SyllableEvidence>& evidence) {
    const std::size_t count = chain.syllables.size();
    std::vector<StateSegment> text_path;
    std::vector<Marked> marked = generic_speech_marks(chain, path, text_path);
    place_syllables(chain, chain_index, text_path, other_frames, scores, track, result, evidence);
    add_syllable_marks(chain, path, held_out_gaps, scores, marked);

    const std::size_t offset = chain.searched.first_frame;
    auto time_s = [&](std::size_t frame) {
        return std::min(track.duration_s, frame_time_s(offset + frame));
    };
    for (std::size_t g = 0; g < marked.size();) {
        MarkedRun run = marked_run(marked, g, count);
        g = run.end;
        if (run.first_frame >= run.end_frame)
            run.first_frame = run.end_frame = instant_before(chain, text_path, run.after_place);
        TextMismatch mismatch;
        mismatch.start_s = time_s(run.first_frame);
        mismatch.end_s = time_s(run.end_frame);
        mismatch.loudness = loudness_envelope(loudness, offset + run.first_frame, offset + run.end_frame);
        if (run.local_count > 0) {
            spread_unsaid_syllables(chain, run, offset, track, loudness, result, evidence, mismatch);
        } else {
            mismatch.first_syllable = run.after_place / 2 < count
                                          ? chain.syllable_indices[run.after_place / 2]
                                          : chain.syllable_indices.back() + 1;
        }
        const std::size_t sentence =
            mismatch.syllable_count > 0 ? result.syllables[mismatch.first_syllable].sentence
                                        : chain.syllables[std::min(run.after_place / 2, count - 1)]->sentence;
        result.warnings.push_back(mismatch_warning(mismatch, sentence));
        result.mismatches.push_back(std::move(mismatch));
    }
    if (!marked.empty()) set_fit_beside(chain, path, scores, result, evidence);
}

}  // namespace talkface::detail
