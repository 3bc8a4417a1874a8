#include "speech/line_among_voices.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

#include "common/order_statistics.hpp"
#include "speech/alignment_checks.hpp"

namespace talkface::detail {

namespace {

// Sound left out never comes this near the loud level: on session 28's short kinds, 3 dB left 9
// tight lines' first syllables out against 5, 8 dB kept 22 babble lines' span starts within 50 ms
// of the line against 24 (bench/README.md, session 29).
constexpr float kNearLoudVoiceDb = 6.0f;
// Read speech runs at 3-8 syllables per second (sentence_cutter.hpp): slower, the text cannot fill
// its speech; faster, what is left cannot hold it.
constexpr double kSlowestSyllablesPerSecond = 3.0;
constexpr double kFastestSyllablesPerSecond = 8.0;
// A voice stands clear of the others where its pitch's correlation (pitch_track.hpp) reaches
// kClearVoicing, and is the line's where its pitch lies within kSameVoiceOctaves of the line's
// (4 semitones: a syllable's tone, high or low, around the voice's loud syllables'); kOwnVoiceFrames
// such frames in a row are a syllable of the line's own. Among several voices one seldom stands
// clear that long: on short_kinds_bench's babble and p-babble, such a run before the line in 10 of
// 51 and 6 of 49 recordings, in the line's first syllable in 17 and 16 (room's: 26 of 53, the
// voices none; bench/README.md, sessions 37 and 38).
constexpr float kClearVoicing = 0.8f;
constexpr double kSameVoiceOctaves = 1.0 / 3.0;
constexpr std::size_t kOwnVoiceFrames = 5;

// Whether the levels from `first` to `last` (read from the line back) rise kNearLoudVoiceDb over a
// lower one nearer the line: a voice's syllables come and go, where a gain's lift climbs toward
// the line within a few dB.
template <typename Iterator>
bool rises_again(Iterator first, Iterator last) {
    float lowest_db = *first;
    for (; first != last; ++first) {
        if (*first >= lowest_db + kNearLoudVoiceDb) return true;
        lowest_db = std::min(lowest_db, *first);
    }
    return false;
}

double frames_for(std::size_t syllables, double syllables_per_second) {
    return static_cast<double>(syllables) / syllables_per_second / kFrameStepS;
}

// Where the line of `syllables` syllables ending at `line_end` starts among other voices a gain
// lifted toward it (a phone's gain control before the line's first loud syllable: issues 12 and
// 13): at the foot of the rise to the first frame whose whole band comes within kNearLoudVoiceDb of
// the loudest frame's, no earlier than the line could start if it holds that frame, said at the
// slowest rate. The activity measured the voices before the line within 0-2 dB of the line
// (each band over its floor, and the floors lie after the line, where the gain is lowest); the
// whole band, which the line's voicing fills, keeps the line 7.5 dB over them (median; bench/
// README.md, session 34). Nothing where what is left out is shorter than a pause, does not rise
// and fall as a voice's syllables do, or is no louder than the sound after the line: the voices
// the gain lifts before the line, it leaves at their level after it, where it fell under the line.
std::optional<std::size_t> start_over_lifted_voices(const FeatureTrack& track, const FrameSpan& speech,
                                                    std::size_t line_end, std::size_t syllables) {
    const auto level = [&](std::size_t t) { return track.at(t, kEnergyDb); };
    std::size_t loudest = speech.first_frame;
    for (std::size_t t = speech.first_frame; t < speech.end_frame; ++t)
        if (level(t) > level(loudest)) loudest = t;
    const auto reach = static_cast<std::size_t>(frames_for(syllables, kSlowestSyllablesPerSecond));
    std::size_t start = loudest > speech.first_frame + reach ? loudest - reach : speech.first_frame;
    while (level(start) < level(loudest) - kNearLoudVoiceDb) ++start;
    while (start > speech.first_frame && level(start - 1) < level(start)) --start;
    if (start < speech.first_frame + kMinPauseFrames || line_end + kMinPauseFrames > track.frame_count)
        return std::nullopt;
    std::vector<float> left_out(start - speech.first_frame);
    for (std::size_t t = speech.first_frame; t < start; ++t) left_out[start - 1 - t] = level(t);
    std::vector<float> after;
    for (std::size_t t = line_end; t < track.frame_count; ++t) after.push_back(level(t));
    if (upper_median(left_out) < upper_median(after)) return std::nullopt;
    if (!rises_again(left_out.begin(), left_out.end())) return std::nullopt;
    return start;
}

bool is_clear(const PitchFrame& frame) {
    return frame.voicing >= kClearVoicing && frame.hz > 0.0f;
}

// The line's pitch: the median of the clear frames in [first, end) within kNearLoudVoiceDb of
// `loud_db`; 0 where there are none.
double pitch_of_line(const FeatureTrack& track, const std::vector<float>& activity, std::size_t first,
                     std::size_t end, float loud_db) {
    std::vector<double> hz;
    for (std::size_t t = first; t < end && t < track.pitch.size(); ++t)
        if (activity[t] >= loud_db - kNearLoudVoiceDb && is_clear(track.pitch[t]))
            hz.push_back(track.pitch[t].hz);
    return hz.empty() ? 0.0 : upper_median(hz);
}

// Whether [first, end) holds kOwnVoiceFrames clear frames in a row within kSameVoiceOctaves of
// `line_hz`, or at any pitch where the line's is not known (0): a syllable of the line's own.
bool holds_line_voice(const FeatureTrack& track, std::size_t first, std::size_t end, double line_hz) {
    std::size_t run = 0;
    for (std::size_t t = first; t < end && t < track.pitch.size(); ++t) {
        const PitchFrame& frame = track.pitch[t];
        const bool is_line_pitch =
            line_hz <= 0.0 || std::abs(std::log2(frame.hz / line_hz)) <= kSameVoiceOctaves;
        run = is_clear(frame) && is_line_pitch ? run + 1 : 0;
        if (run >= kOwnVoiceFrames) return true;
    }
    return false;
}

}  // namespace

FrameSpan line_among_quieter_voices(const FeatureTrack& track, const LoudnessProfile& loudness,
                                    const FrameSpan& speech, std::size_t syllables) {
    const std::vector<float>& activity = loudness.activity_db;
    // Sound that runs from the recording's edge (no pause between) may be other voices; a shorter
    // stretch left out is the line's own weak edge, and so is sound from an edge nearer than a pause.
    // After a pause, the pitch tells (below).
    const bool from_start = speech.first_frame < kMinPauseFrames;
    const bool to_end = speech.end_frame + kMinPauseFrames > activity.size();
    if (!(from_start || to_end || !track.pitch.empty())) return speech;
    const auto at = [&](std::size_t frame) { return activity.begin() + static_cast<std::ptrdiff_t>(frame); };
    const float loud_db =
        percentile_of(std::vector<float>(at(speech.first_frame), at(speech.end_frame)), kSpeechPercentile);
    const float near_db = loud_db - kUnspokenSpeechBelowDb;
    // The largest sum of a run: a quieter voice's loud moments join the line only where the dip
    // between them is shorter than they are loud.
    FrameSpan loud{speech.first_frame, speech.first_frame};
    double best = 0.0;
    double sum = 0.0;
    std::size_t first = speech.first_frame;
    for (std::size_t t = speech.first_frame; t < speech.end_frame; ++t) {
        if (sum <= 0.0) {
            sum = 0.0;
            first = t;
        }
        sum += static_cast<double>(activity[t] - near_db);
        if (sum > best) {
            best = sum;
            loud = {first, t + 1};
        }
    }
    if (loud.length() == 0) return speech;
    // The line holds the run and every frame that comes within kNearLoudVoiceDb of the loud level:
    // the other voices never do, and a syllable of the line's own that a dip parts from the run does
    // (a quieter syllable or a stop's closure between them ends the run). Left out with the voices,
    // it kept the edge at the recording's, and the last syllable was drawn out onto the voices after
    // the line (short_kinds_bench's babble: 180-610 ms late in 10 of 38 tuning lines; bench/README.md,
    // session 36). Its first consonant is quieter: back to the foot of its rise; its last syllable
    // fades: on to the foot of its fall.
    const auto is_near_loud = [&](float db) { return db >= loud_db - kNearLoudVoiceDb; };
    const auto first_near = std::find_if(at(speech.first_frame), at(loud.first_frame), is_near_loud);
    std::size_t start = static_cast<std::size_t>(first_near - activity.begin());
    while (start > speech.first_frame && activity[start - 1] < activity[start]) --start;
    const auto last_near = std::find_if(std::make_reverse_iterator(at(speech.end_frame)),
                                        std::make_reverse_iterator(at(loud.end_frame)), is_near_loud);
    std::size_t end = static_cast<std::size_t>(last_near.base() - activity.begin());
    while (end < speech.end_frame && activity[end] < activity[end - 1]) ++end;
    // Sound left out is another voice where it is at least a pause long and rises and falls as a
    // voice's syllables do.
    const auto is_quieter_voice = [&](std::size_t from, std::size_t to, auto first_read, auto last_read) {
        return to >= from + kMinPauseFrames && rises_again(first_read, last_read);
    };
    // The start moves after a pause too, where the pitch says the sound left out is other voices':
    // their own quiet stretches are pauses to the profile, and the voices between such a stretch and
    // the line kept the first syllable 180-450 ms early (short_kinds_bench's babble 小心後面, p-babble
    // 撤). Where what is left out holds a run of the line's own voice, it is the line's quieter first
    // syllable after a silence (room's 先別急著開團: 先 284 ms late without this; bench/README.md,
    // sessions 37 and 38).
    const bool is_others_before =
        from_start ||
        (!track.pitch.empty() && !holds_line_voice(track, speech.first_frame, start,
                                                   pitch_of_line(track, activity, start, end, loud_db)));
    FrameSpan line = speech;
    if (is_others_before && is_quieter_voice(speech.first_frame, start, std::make_reverse_iterator(at(start)),
                                             std::make_reverse_iterator(at(speech.first_frame))))
        line.first_frame = start;
    else if (const auto lifted_start =
                 from_start ? start_over_lifted_voices(track, speech, end, syllables) : std::nullopt)
        line.first_frame = *lifted_start;
    // Where the other voices sound before the line too and its start was not found, a span cut at
    // its end alone squeezes the syllables onto the voices before it (short_kinds_bench's held-out
    // p-vfast-combo 20.5 -> 15.7% within 50 ms, p-babble 41.0 -> 37.3%: bench/README.md, session 33).
    const bool is_start_unknown = from_start && line.first_frame == speech.first_frame;
    if (to_end && !is_start_unknown && is_quieter_voice(end, speech.end_frame, at(end), at(speech.end_frame)))
        line.end_frame = end;
    // A line of N syllables holds about N voiced peaks: a span with fewer left a quieter syllable of
    // the line's own out with the voices (a last syllable under the voices a phone's gain lifted after
    // the line; a cut's first syllable), and one too short for its syllables even said fast did too.
    const bool holds_its_syllables =
        static_cast<double>(line.length()) >= frames_for(syllables, kFastestSyllablesPerSecond) &&
        count_nuclei(track, loudness, line) >= syllables;
    // Speech no slower than its syllables could be said leaves the other voices little of it: the
    // line is cut from it only where both its edges are found, as one edge moved alone squeezes the
    // syllables onto the voices left at the other (short_kinds_bench's held-out babble 大家準備好了嗎,
    // its end alone found: its syllables 100-300 ms early; bench/README.md, session 36).
    const bool is_slower_than_text =
        static_cast<double>(speech.length()) > frames_for(syllables, kSlowestSyllablesPerSecond);
    const bool is_found_at_both_edges =
        line.first_frame != speech.first_frame && line.end_frame != speech.end_frame;
    return holds_its_syllables && (is_slower_than_text || is_found_at_both_edges) ? line : speech;
}

bool is_one_spoken_line(const Timeline& transcript) {
    const std::vector<std::size_t> syllables = syllables_per_sentence(transcript);
    const auto is_spoken = [](std::size_t count) { return count > 0; };
    return std::count_if(syllables.begin(), syllables.end(), is_spoken) == 1;
}

std::optional<SentenceCut> line_cut_among_voices(const FeatureTrack& track, const LoudnessProfile& loudness,
                                                 const Timeline& transcript, const SentenceCut& cut) {
    if (!is_one_spoken_line(transcript)) return std::nullopt;
    const std::vector<std::size_t> syllables = syllables_per_sentence(transcript);
    const auto is_spoken = [](std::size_t count) { return count > 0; };
    const auto k = static_cast<std::size_t>(std::find_if(syllables.begin(), syllables.end(), is_spoken) -
                                            syllables.begin());
    const FrameSpan line = line_among_quieter_voices(track, loudness, cut.spans.at(k), syllables[k]);
    if (line.first_frame == cut.spans[k].first_frame && line.end_frame == cut.spans[k].end_frame)
        return std::nullopt;
    // Sentences without a syllable before it sit at its start (place_spoken_spans) and move with it.
    SentenceCut narrowed = cut;
    for (FrameSpan& span : narrowed.spans)
        if (span.length() == 0 && span.first_frame == cut.spans[k].first_frame)
            span = {line.first_frame, line.first_frame};
    narrowed.spans[k] = line;
    narrowed.limits.assign(narrowed.spans.size(), {0, std::numeric_limits<std::size_t>::max()});
    const bool is_narrowed_at_end = line.end_frame != cut.spans[k].end_frame;
    const bool is_narrowed_at_start = line.first_frame != cut.spans[k].first_frame;
    narrowed.limits[k] = {
        is_narrowed_at_start && line.first_frame > kMinPauseFrames ? line.first_frame - kMinPauseFrames : 0,
        is_narrowed_at_end ? line.end_frame + kMinPauseFrames : std::numeric_limits<std::size_t>::max()};
    return narrowed;
}

}  // namespace talkface::detail
