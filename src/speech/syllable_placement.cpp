#include "speech/syllable_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

#include "common/order_statistics.hpp"
#include "speech/alignment_confidence.hpp"
#include "speech/noise_reach.hpp"

namespace talkface::detail {

namespace {

// Silence before a burst (a pause and the closure together) from which on the closure is taken
// for part of a pause: a stop's closure lasts under 0.2 s.
constexpr std::size_t kPauseBeforeBurstFrames = 20;

// Where a voiced join's transition is taken to start: a quarter of the way from the level before
// to the level after (voiced_join_start). Chosen before measuring; bench/ Session 13: 0, 0.1 and
// 0.25 place alike on the w- tuning rows.
constexpr double kTransitionShare = 0.25;

// A syllable with no initial joined to a voiced sound (syllable_valley_start): its energy valley is
// looked for up to 6 frames before where the path and voiced_join_start put it (a cross-fade of
// 30-80 ms, the path's boundary near its middle: bench/ Session 16 measured 4, 6 and 8 on the
// tuning rows, 6 placed best), and counts where it lies at least 3 dB under the louder side's
// quieter peak, each side's peak taken over 10 frames (a syllable's nucleus lies within 100 ms).
constexpr std::size_t kValleySearchFrames = 6;
constexpr std::size_t kValleySideFrames = 10;
constexpr float kValleyDepthDb = 3.0f;
// Where no valley lies that near, one twice as deep is looked for up to 20 frames back, after the
// syllable before's loudest frame: the path often gives the syllable before the new one's first
// frames (會有 快又 包往 蘇我: the valley 7-12 frames before its start, 10-20 dB deep). bench/
// Session 17 measured 8 to 50 frames back at 4 to 10 dB on the person's tuning rows: 20 and 6
// placed best (50 gained nothing: 是一 whose path is a whole syllable late, in a plateau of i
// 20-36 frames long). Without the peak, espeak-ng's 有一 moved to 有's own onset (its y is
// weaker than its ou), 180 ms early in 19 conditions.
constexpr std::size_t kFarValleySearchFrames = 20;
constexpr float kFarValleyDepthDb = 6.0f;
// A valley's floor: the frames within 1 dB of its lowest (the frame-to-frame scatter of a held
// sound; a WAV and its MP3 or Opus place 公園's 園 alike).
constexpr float kValleyFloorDb = 1.0f;
// A turn out of an apical vowel (apical_vowel_turn): the landmarks' bonus (2 ln of the cepstral
// flux over the sentence's median frame's, spectral_landmarks.cpp) rising 0.5 from its trough, the
// flux by a quarter (e^0.25); a bonus of 0.5 within a frame of the path's start says the path found
// a turn itself. bench/ Session 21 measured 0.25 and 1 beside it on the person's tuning rows.
constexpr float kTurnRise = 0.5f;
// A syllable after a pause whose initial the path holds longer than its duration prior's median
// times exp(this many of its spreads), about the longest 2% of such sounds, took the sound before
// it too (onset_after_pause).
constexpr double kOverlongInitialSpreads = 2.0;

// Whether a syllable whose first state is `initial` starts with a stop's burst: b d g p t k, and
// after a pause (no closure) the affricates z zh j c ch q, whose burst their frication follows,
// weaker at first.
bool opens_with_burst(const PhoneState& initial, const Syllable& syllable) {
    return initial.phone_class == kBurst ||
           (initial.phone_class == kSibilant && !syllable.pinyin.empty() &&
            std::string_view("zcjqZCJQ").find(syllable.pinyin[0]) != std::string_view::npos);
}

// A sound is heard above the noise where the high band stays over the noise's reach this many
// frames running. The noise alone passes its reach one frame in ten: over the 5-20 frames before a
// sibilant's frication is heard, a single frame over it comes by chance most of the time (the
// sibilant then started a frame or two after the path, still early), three running seldom.
// bench/ Session 23 measured 1 to 4 on the person's tuning rows.
constexpr std::size_t kHeardFrames = 3;

// Whether `phone_class` scores at least as well as `own_class` on every frame of `segment`.
bool fits_throughout(const StateSegment& segment, PhoneClass phone_class, PhoneClass own_class,
                     const EmissionScores& scores) {
    for (std::size_t t = segment.first_frame; t < segment.end_frame; ++t)
        if (scores.at(t, phone_class) < scores.at(t, own_class)) return false;
    return true;
}

bool is_voiced_class(PhoneClass phone_class) {
    return phone_class == kNasal || phone_class == kLiquid || (phone_class >= kVowelA && phone_class <= kVowelApical);
}

}  // namespace

std::size_t voiced_join_start(const StateSegment& before, PhoneClass before_class, const StateSegment& first,
                              PhoneClass first_class, const EmissionScores& scores) {
    const std::size_t boundary = first.first_frame;
    if (before.end_frame != boundary || before.end_frame <= before.first_frame || first.end_frame <= first.first_frame ||
        first.end_frame > scores.frame_count)
        return boundary;
    auto rise = [&](std::size_t t) { return static_cast<double>(scores.at(t, first_class)) - scores.at(t, before_class); };
    std::vector<double> values;
    for (std::size_t t = before.first_frame; t < before.end_frame; ++t) values.push_back(rise(t));
    const double level_before = lower_median(values);
    values.clear();
    for (std::size_t t = first.first_frame; t < first.end_frame; ++t) values.push_back(rise(t));
    const double level_after = lower_median(values);
    if (!(level_after > level_before)) return boundary;
    const double threshold = level_before + kTransitionShare * (level_after - level_before);
    std::size_t start = boundary;
    // Half of `before`'s frames at least lie at or under its level, so the walk stops inside it.
    while (start > before.first_frame && rise(start - 1) > threshold) --start;
    return start;
}

namespace {

// The valley of the level in frames [first, end) counted from frame `offset` of `track`, as
// syllable_valley_start takes it, where it lies at least `depth_db` under the quieter of its sides'
// peaks; none: `end`.
std::size_t level_valley(const FeatureTrack& track, std::size_t offset, std::size_t first, std::size_t end, float depth_db) {
    if (end < first + 3) return end;
    auto level = [&](std::size_t t) { return track.at(offset + t, kEnergyDb); };
    std::size_t valley = first;
    for (std::size_t t = first + 1; t < end; ++t)
        if (level(t) < level(valley)) valley = t;
    // A level still falling at the search's first frame, or still rising past the start, is no valley.
    if (valley == first || valley + 1 == end) return end;
    float before = level(valley), after = level(valley);
    for (std::size_t t = valley - std::min(valley, kValleySideFrames); t < valley; ++t) before = std::max(before, level(t));
    for (std::size_t t = valley + 1; t <= valley + kValleySideFrames && offset + t < track.frame_count; ++t)
        after = std::max(after, level(t));
    if (std::min(before, after) - level(valley) < depth_db) return end;
    // A flat floor (a nasal coda) ends where the level begins to rise: its lowest frame would move
    // with a codec's rounding.
    std::size_t rise = valley;
    for (std::size_t t = valley + 1; t + 1 < end; ++t)
        if (level(t) < level(valley) + kValleyFloorDb) rise = t;
    return rise;
}

}  // namespace

std::size_t syllable_valley_start(const FeatureTrack& track, std::size_t offset, std::size_t lowest, std::size_t start) {
    const std::size_t end = std::min(track.frame_count - std::min(track.frame_count, offset), start + 2);
    auto search_from = [&](std::size_t frames) { return std::max(lowest, start >= frames ? start - frames : 0); };
    const std::size_t near = level_valley(track, offset, search_from(kValleySearchFrames), end, kValleyDepthDb);
    if (near != end) return near;
    // That far back a valley may be the syllable before's own onset (有一: the y of 有 is weaker
    // than its ou): the one between the two nuclei lies after the syllable before's loudest frame.
    // That frame is looked for before the level's rise into `start`: where the path starts the
    // syllable late, its own onset rises there already, louder than the syllable before (包忘).
    auto level = [&](std::size_t t) { return track.at(offset + t, kEnergyDb); };
    std::size_t rise_foot = std::min(start, end);
    while (rise_foot < end && rise_foot > lowest + 1 && level(rise_foot - 1) < level(rise_foot)) --rise_foot;
    std::size_t peak = lowest;
    for (std::size_t t = lowest; t < rise_foot; ++t)
        if (level(t) > level(peak)) peak = t;
    const std::size_t far = level_valley(track, offset, std::max(peak, search_from(kFarValleySearchFrames)), end, kFarValleyDepthDb);
    return far != end ? far : start;
}

std::size_t apical_vowel_turn(const EmissionScores& scores, std::size_t vowel_first, std::size_t start) {
    const std::vector<float>& bonus = scores.boundary;
    if (start < 1 || start + 1 >= bonus.size() || vowel_first >= start) return start;
    if (std::max({bonus[start - 1], bonus[start], bonus[start + 1]}) >= kTurnRise) return start;
    // Past the vowel's onset, where the change from the sound before it falls.
    std::size_t t = vowel_first;
    while (t + 1 < start && bonus[t + 1] <= bonus[t]) ++t;
    std::size_t turn = start;
    while (t + 1 < start) {
        const float trough = bonus[t];
        const std::size_t rise = t + 1;
        while (t + 1 < start && bonus[t + 1] >= bonus[t]) ++t;
        // A rise still going at the path's start is the path's own turn.
        if (t + 1 >= start) break;
        if (bonus[t] - trough >= kTurnRise) turn = rise;
        while (t + 1 < start && bonus[t + 1] <= bonus[t]) ++t;
    }
    return turn;
}

float pause_noise_reach(const FeatureTrack& track, const SentenceChain& chain,
                        const std::vector<StateSegment>& path, FeatureColumn column) {
    const std::size_t offset = chain.searched.first_frame;
    std::vector<float> levels;
    for (const StateSegment& segment : path)
        if (is_pause(chain.states[segment.state].role))
            for (std::size_t t = segment.first_frame; t < segment.end_frame && offset + t < track.frame_count;
                 ++t)
                levels.push_back(track.at(offset + t, column));
    return steady_noise_reach(std::move(levels));
}

std::size_t sibilant_onset(const FeatureTrack& track, std::size_t offset, std::size_t first, std::size_t end,
                           float noise_reach_db) {
    std::size_t run = 0;
    for (std::size_t t = first; t < end + kHeardFrames - 1 && offset + t < track.frame_count; ++t) {
        run = track.at(offset + t, kHighBandDb) > noise_reach_db ? run + 1 : 0;
        if (run == kHeardFrames) return first + (t + 1 - kHeardFrames - first) / 2;
    }
    return first;
}

std::size_t closure_after_tail(const FeatureTrack& track, std::size_t offset, std::size_t first,
                               std::size_t burst, float noise_reach_db) {
    if (!(noise_reach_db > kDigitalSilenceDb)) return first;
    for (std::size_t t = first; t < burst && offset + t < track.frame_count; ++t)
        if (track.at(offset + t, kEnergyDb) <= noise_reach_db) return t;
    return first;
}

std::size_t onset_after_pause(const FeatureTrack& track, std::size_t offset, const PhoneState& initial,
                              const StateSegment& segment) {
    const std::size_t first = segment.first_frame;
    const double frames = static_cast<double>(segment.end_frame - first);
    if (frames <= initial.median_frames * std::exp(kOverlongInitialSpreads * initial.log_sigma)) return first;
    auto level = [&](std::size_t t) { return track.at(offset + t, kEnergyDb); };
    std::size_t lowest = first;
    for (std::size_t t = first + 1; t < segment.end_frame; ++t)
        if (level(t) < level(lowest)) lowest = t;
    std::size_t floor_end = lowest;
    for (std::size_t t = lowest + 1; t < segment.end_frame; ++t)
        if (level(t) < level(lowest) + kValleyFloorDb) floor_end = t;
    return lowest == first ? first : floor_end;
}

namespace {

// What placing a chain's syllables reads: the chain, its path, the scores and features it was aligned
// on, and the noise's reach in the path's pauses (pause_noise_reach) in the high band and in energy.
struct PlacementInputs {
    const SentenceChain& chain;
    const std::vector<StateSegment>& path;
    const EmissionScores& scores;
    const FeatureTrack& track;
    float noise_reach_db;
    float noise_level_reach_db;
};

// Where the sound of path[p], a syllable's first state, starts.
std::size_t sound_first_frame(const SentenceChain& chain, const std::vector<StateSegment>& path,
                              std::size_t p) {
    // SPEC: after a pause the closure cannot be told from the pause; the syllable starts
    // at the burst. A pause the transcript does not mark counts when it is longer than
    // any closure (a sentence end in a transcript without punctuation).
    if (chain.states[path[p].state].role == StateRole::closure && p > 0) {
        const StateSegment& before = path[p - 1];
        const StateRole role = chain.states[before.state].role;
        const std::size_t silence =
            before.end_frame - before.first_frame + path[p].end_frame - path[p].first_frame;
        if (role == StateRole::comma_pause ||
            (role == StateRole::short_pause && silence >= kPauseBeforeBurstFrames))
            return path[p].end_frame;
    }
    return path[p].first_frame;
}

// A syllable's start, its path's start moved back or on where the sound says it starts, and whether it
// runs on from the one before, no pause between: only then does a moved start move that one's end
// (after a pause, or as a chain's first, nothing before it is this syllable's to move).
struct SyllableOnset {
    std::size_t start;
    bool runs_on;
};

// The onset of syllable `local`, whose first state is path[p], its sound starting at frame `first`.
SyllableOnset syllable_onset(const PlacementInputs& in, std::size_t local, std::size_t p, std::size_t first) {
    const SentenceChain& chain = in.chain;
    const std::vector<StateSegment>& path = in.path;
    const PhoneState& state = chain.states[path[p].state];
    std::size_t start = first;
    const PhoneState* before = p > 0 ? &chain.states[path[p - 1].state] : nullptr;
    const bool runs_on = before && before->syllable + 1 == local && !is_pause(before->role);
    const bool is_voiced_join = runs_on && state.role != StateRole::closure &&
                                is_voiced_class(before->phone_class) && is_voiced_class(state.phone_class);
    if (is_voiced_join && before->phone_class != state.phone_class)
        start = voiced_join_start(path[p - 1], before->phone_class, path[p], state.phone_class, in.scores);
    if (is_voiced_join && before->phone_class == kVowelApical)
        start = std::min(start, apical_vowel_turn(in.scores, path[p - 1].first_frame, first));
    // A light syllable's one vowel that the new sound fits as well on each of its frames
    // was not heard apart from it: only the turn into it (了一, 的预; bench/ Session 21).
    const bool is_one_vowel = is_voiced_join && before->role == StateRole::final &&
                              before->phone_class >= kVowelA &&
                              !(p >= 2 && chain.states[path[p - 2].state].syllable == before->syllable &&
                                chain.states[path[p - 2].state].role == StateRole::final);
    if (is_one_vowel && before->phone_class != state.phone_class &&
        chain.syllables[local - 1]->pinyin.back() == '5' &&
        fits_throughout(path[p - 1], state.phone_class, before->phone_class, in.scores))
        start = std::min(start, path[p - 1].first_frame);
    // s sh x right after the sound before: no closure, no pause (a short one before a
    // fricative lasts 150 ms at least, phone_chain.cpp).
    const char initial = chain.syllables[local]->pinyin.empty() ? '\0' : chain.syllables[local]->pinyin[0];
    if (runs_on && state.role == StateRole::initial && state.phone_class == kSibilant &&
        (initial == 's' || initial == 'x'))
        start =
            sibilant_onset(in.track, chain.searched.first_frame, first, path[p].end_frame, in.noise_reach_db);
    // A room's closures ring with the vowel before (room_closures.hpp): scored as any
    // sound, not as silence, and the tail there is the room's, not the noise's.
    if (runs_on && state.role == StateRole::closure && state.phone_class == kSilence)
        start = closure_after_tail(in.track, chain.searched.first_frame, first, path[p].end_frame,
                                   in.noise_level_reach_db);
    const bool is_after_pause = p == 0 || is_pause(chain.states[path[p - 1].state].role);
    if (is_after_pause && state.role == StateRole::initial &&
        !opens_with_burst(state, *chain.syllables[local]))
        start = onset_after_pause(in.track, chain.searched.first_frame, state, path[p]);
    if (is_voiced_join && state.role == StateRole::final) {
        // No earlier than the syllable before's vowel: its final's first frame.
        std::size_t q = p - 1;
        while (q > 0 && chain.states[path[q - 1].state].syllable == before->syllable &&
               chain.states[path[q - 1].state].role == StateRole::final)
            --q;
        start = syllable_valley_start(in.track, chain.searched.first_frame, path[q].first_frame + 1, start);
    }
    return {start, runs_on};
}

// A syllable's frames on its chain's path: `first` is the path's start, `start` the syllable's (a voiced
// join's moved back), `end` the path's end, `final_first` its final's first frame, if it has one.
struct SyllablePath {
    std::size_t first = 0, end = 0, start = 0;
    std::optional<std::size_t> final_first;
    bool runs_on = false;
};

SyllablePath syllable_path(const PlacementInputs& in, std::size_t local) {
    SyllablePath placed;
    bool has_start = false;
    for (std::size_t p = 0; p < in.path.size(); ++p) {
        const PhoneState& state = in.chain.states[in.path[p].state];
        if (state.syllable != local || is_pause(state.role)) continue;
        if (!has_start) {
            placed.first = sound_first_frame(in.chain, in.path, p);
            const SyllableOnset onset = syllable_onset(in, local, p, placed.first);
            placed.start = onset.start;
            placed.runs_on = onset.runs_on;
            has_start = true;
        }
        placed.end = in.path[p].end_frame;
        if (state.role == StateRole::final && !placed.final_first)
            placed.final_first = in.path[p].first_frame;
    }
    return placed;
}

}  // namespace

void place_syllables(const SentenceChain& chain, std::size_t chain_index, const std::vector<StateSegment>& path,
                     const std::vector<std::vector<SyllableFrames>>& other_frames, const EmissionScores& scores,
                     const FeatureTrack& track, Timeline& result, std::vector<SyllableEvidence>& evidence) {
    // The last frame may run past the audio's last sample: no time is later than the audio's end.
    auto time_s = [&](std::size_t frame) {
        return std::min(track.duration_s, frame_time_s(chain.searched.first_frame + frame));
    };
    std::vector<SyllableFrames> frames(chain.syllables.size());
    const PlacementInputs in{chain,
                             path,
                             scores,
                             track,
                             pause_noise_reach(track, chain, path, kHighBandDb),
                             pause_noise_reach(track, chain, path, kEnergyDb)};
    for (std::size_t local = 0; local < chain.syllables.size(); ++local) {
        Syllable& syllable = result.syllables[chain.syllable_indices[local]];
        auto [first, end, start, final_first, runs_on] = syllable_path(in, local);
        const std::size_t offset = chain.searched.first_frame;
        const bool is_last = local + 1 == chain.syllables.size();
        if (is_last && chain.ends_before_tail) {
            const std::size_t trimmed = end_before_tail(track, offset + first, offset + end) - offset;
            end = std::max(trimmed, final_first.value_or(first) + 1);
        }
        syllable.start_s = time_s(start);
        // A last syllable the path holds to the voice's quiet end keeps it past the search, to where
        // it falls into the noise (one the path ends before it ended in a pause: a breath may follow);
        // its evidence stays on the frames searched.
        const bool runs_to_quiet_end = is_last && chain.quiet_end > offset + end &&
                                       offset + end >= chain.speech.end_frame - chain.tail_frames;
        syllable.end_s = time_s(runs_to_quiet_end ? chain.quiet_end - offset : std::max(end, first + 1));
        // A syllable ends where the next starts.
        if (start != first && runs_on) {
            Syllable& previous = result.syllables[chain.syllable_indices[local - 1]];
            previous.end_s = start < first ? std::min(previous.end_s, syllable.start_s) : syllable.start_s;
        }
        // A syllable with no initial (y- w-, a vowel) starts with its final: the final moves with it.
        const std::size_t final_frame = final_first.value_or(first);
        syllable.final_start_s = time_s(final_frame == first ? start : final_frame);
        frames[local] = {first, std::max(end, first + 1)};
    }
    const std::vector<SyllableFit> fits = syllable_fit_parts(chain, path, scores, frames);
    const std::vector<double> timing = syllable_timing(chain, path, scores, frames);
    const std::vector<double> steadiness = syllable_steadiness(frames_on_path(chain, path), other_frames);
    for (std::size_t local = 0; local < chain.syllables.size(); ++local)
        evidence[chain.syllable_indices[local]] = {true, chain_index, fits[local], timing[local], steadiness[local]};
}

std::optional<VoicedEnd> voiced_end_past_path(const SentenceChain& chain, const FeatureTrack& track,
                                              const Timeline& result) {
    if (!chain.voiced_past_end || chain.syllable_indices.empty()) return std::nullopt;
    const std::size_t last = chain.syllable_indices.back();
    const auto placed_end = static_cast<std::size_t>(std::lround(result.syllables[last].end_s / kFrameStepS));
    if (placed_end >= chain.quiet_end) return std::nullopt;
    return VoicedEnd{last, std::min(track.duration_s, frame_time_s(chain.quiet_end))};
}

std::vector<AlignedStretch> stretches_of(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    std::vector<AlignedStretch> stretches;
    for (std::size_t p = 0; p < path.size(); ++p) {
        const PhoneState& state = chain.states[path[p].state];
        const bool is_pause_state = is_pause(state.role);
        const std::size_t syllable = chain.syllable_indices[state.syllable];
        const std::size_t first = chain.searched.first_frame + path[p].first_frame;
        const std::size_t end = chain.searched.first_frame + path[p].end_frame;
        if (!stretches.empty() && stretches.back().is_pause == is_pause_state && stretches.back().syllable == syllable) {
            stretches.back().end_frame = end;
            continue;
        }
        const PhoneState* before = p > 0 ? &chain.states[path[p - 1].state] : nullptr;
        const bool is_joined_on = !is_pause_state && state.role == StateRole::final && before &&
                                  before->syllable + 1 == state.syllable && !is_pause(before->role) &&
                                  is_voiced_class(before->phone_class);
        stretches.push_back({first, end, is_pause_state, syllable, is_joined_on});
    }
    return stretches;
}

FrameSpan aligned_span(const Timeline& result, const SentenceChain& chain, std::size_t k) {
    FrameSpan span{std::numeric_limits<std::size_t>::max(), 0};
    for (const std::size_t i : chain.syllable_indices) {
        const Syllable& syllable = result.syllables[i];
        if (syllable.sentence != k) continue;
        span.first_frame = std::min(span.first_frame, static_cast<std::size_t>(std::lround(syllable.start_s / kFrameStepS)));
        span.end_frame = std::max(span.end_frame, static_cast<std::size_t>(std::lround(syllable.end_s / kFrameStepS)));
    }
    return span;
}

void set_start_evidence(const SentenceChain& chain, const std::vector<StateSegment>& path,
                        const EntryMaxMarginals& marginals, std::vector<SyllableEvidence>& evidence) {
    const std::vector<double> sureness = start_sureness(chain, path, marginals);
    const std::vector<double> far = far_start_share(chain, path, marginals);
    for (std::size_t local = 0; local < sureness.size(); ++local) {
        evidence[chain.syllable_indices[local]].sureness = sureness[local];
        evidence[chain.syllable_indices[local]].far_start = far[local];
    }
}

}  // namespace talkface::detail
