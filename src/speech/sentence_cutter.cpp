#include "speech/sentence_cutter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/number_format.hpp"
#include "common/order_statistics.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/breath_edge.hpp"
#include "speech/held_music.hpp"
#include "speech/lifted_lead_in.hpp"
#include "speech/lifted_noise.hpp"
#include "speech/music_bed.hpp"
#include "speech/repeating_accompaniment.hpp"
#include "speech/run_together.hpp"
#include "speech/steady_tone.hpp"
#include "speech/unvoiced_beat.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

constexpr std::size_t kSmoothingFrames = 5;
constexpr std::size_t kLongestClickFrames = 4;
// Noise floors are a low percentile of each band: the quietest 5% of any recording with pauses
// is noise, whatever its level (learned from the audio, not set by hand as in Lai and Tsai).
constexpr double kFloorPercentile = 0.05;
// The noise's typical level: steady noise (a fan, hiss) lies within a dB or two of its quietest 5%,
// but music's notes and beats spread far above it (bench/ song15: the 10th percentile 8.5 dB up,
// the threshold 7.9 dB, and the music in every pause taken for speech). A recording's pauses take
// more than a tenth of it, so its 10th percentile is noise, whatever kind.
constexpr double kNoisePercentile = 0.10;
// Steady noise stays within kAboveFloorDb of its quietest 5% and its 10th percentile lies ~2 dB up:
// kNoiseWanderDb above that is the same mark for it, and follows the music's level up.
constexpr float kAboveFloorDb = 6.0f;
constexpr float kNoiseWanderDb = 4.0f;
// The activity threshold's place between the floor and the loud frames, in dB (activity_threshold_db):
// a quarter of the way up, and no lower than 35 dB below them, where a room's reverberation fills a clean
// recording's pauses to.
constexpr float kThresholdShareOfSpeech = 0.25f;
constexpr float kReverbFillDb = 35.0f;
// Sentence-cut score: the log duration of a sentence against its syllable count (sd of the log),
// and the reward for ending a sentence at a long pause.
constexpr double kSentenceDurationSigma = 0.35;
constexpr double kPauseWeight = 1.5;
constexpr double kNegativeInfinity = -std::numeric_limits<double>::infinity();
// The floor of what sound there is (the frames above kDigitalSilenceDb) needs a few frames.
constexpr std::size_t kMinSoundFrames = 20;

float column_percentile(const FeatureTrack& track, int column, double fraction) {
    std::vector<float> values(track.frame_count);
    for (std::size_t t = 0; t < track.frame_count; ++t) values[t] = track.at(t, column);
    return percentile_of(std::move(values), fraction);
}

// column_percentile over the frames that are not digital silence; `fallback` where too few are.
float sound_percentile(const FeatureTrack& track, int column, double fraction, float fallback) {
    std::vector<float> values;
    for (std::size_t t = 0; t < track.frame_count; ++t)
        if (track.at(t, kEnergyDb) > kDigitalSilenceDb) values.push_back(track.at(t, column));
    return values.size() < kMinSoundFrames ? fallback : std::max(fallback, percentile_of(std::move(values), fraction));
}

std::string seconds(std::size_t frame) { return format_fixed(static_cast<double>(frame) * kFrameStepS, 2); }

std::string span_text(const FrameSpan& span) { return seconds(span.first_frame) + "-" + seconds(span.end_frame) + " s"; }

// Algorithm 3.1, steps 2-8, literally: V = the loudest sample of the selected pause, silences are
// runs quieter than c2 V lasting longer than c1 times the pause, speaking parts are what is left.
std::vector<FrameSpan> speaking_parts_from_first_pause(const FeatureTrack& track, const AlignOptions& options) {
    const double duration_s = static_cast<double>(track.frame_count) * kFrameStepS;
    if (!(options.first_pause_start_s >= 0.0 && options.first_pause_end_s > options.first_pause_start_s &&
          options.first_pause_end_s <= duration_s + kFrameStepS)) {
        throw InvalidArgument("first_pause", "expected 0 <= start < end <= " + format_fixed(duration_s, 3) +
                                                 " s (the audio's length), found " +
                                                 format_fixed(options.first_pause_start_s, 3) + "-" +
                                                 format_fixed(options.first_pause_end_s, 3) + " s");
    }
    const auto pause_first = static_cast<std::size_t>(options.first_pause_start_s / kFrameStepS);
    const auto pause_end = std::min(track.frame_count,
                                    std::max(pause_first + 1, static_cast<std::size_t>(std::ceil(options.first_pause_end_s / kFrameStepS))));
    float loudest = 0.0f;
    for (std::size_t t = pause_first; t < pause_end; ++t) loudest = std::max(loudest, track.at(t, kPeakAmplitude));
    const double min_pause_frames = (options.first_pause_end_s - options.first_pause_start_s) * options.c1 / kFrameStepS;
    const double noise_level = loudest * options.c2;
    auto is_quiet = [&](std::size_t t) { return track.at(t, kPeakAmplitude) < noise_level; };

    // Step 5 starts from t_s: what precedes it is the first speaking part.
    std::vector<FrameSpan> silences;
    for (std::size_t t = pause_first; t < track.frame_count;) {
        if (!is_quiet(t)) { ++t; continue; }
        std::size_t end = t;
        while (end < track.frame_count && is_quiet(end)) ++end;
        if (static_cast<double>(end - t) > min_pause_frames) silences.push_back({t, end});
        t = end;
    }
    std::vector<FrameSpan> parts;
    std::size_t part_first = 0;
    auto add_part = [&](std::size_t first, std::size_t end) {
        // Quiet edges (the leading silence of the file, a short quiet tail) are not speech.
        while (first < end && is_quiet(first)) ++first;
        while (end > first && is_quiet(end - 1)) --end;
        // A lone click a few milliseconds long is not a sentence.
        if (end - first >= 3) parts.push_back({first, end});
    };
    for (const auto& silence : silences) {
        add_part(part_first, silence.first_frame);
        part_first = silence.end_frame;
    }
    add_part(part_first, track.frame_count);
    return parts;
}

// The floor of mean_frames_per_syllable, 50 ms a syllable: it keeps a sentence's expected length above 0
// where the longest pauses take up all the speech (a mean of 0 would make every log ratio infinite). Its
// value decides no cut: a cut's sentences hold at most the speech the mean counts, so under a mean of
// kFastestFramesPerSyllable (7) every cut has a sentence too fast for its syllables and is refused, and
// any floor up to 7 cuts the same. It came unexplained with the first cutter (ad6f37c).
constexpr double kFewestMeanFramesPerSyllable = 5.0;

// The speech's frames per syllable, were its sentences cut at its longest pauses (one fewer than the
// sentences, `syllables` their syllable counts) and those pauses left out; at least
// kFewestMeanFramesPerSyllable.
double mean_frames_per_syllable(const LoudnessProfile& loudness, const std::vector<std::size_t>& syllables) {
    const std::size_t boundary_count = syllables.size() - 1;
    std::size_t total_syllables = 0;
    for (std::size_t count : syllables) total_syllables += count;
    std::vector<std::size_t> lengths;
    for (const auto& pause : loudness.pauses) lengths.push_back(pause.length());
    std::sort(lengths.rbegin(), lengths.rend());
    double speech_frames = static_cast<double>(loudness.speech_end_frame - loudness.speech_first_frame);
    for (std::size_t i = 0; i < boundary_count; ++i) speech_frames -= static_cast<double>(lengths[i]);
    return std::max(kFewestMeanFramesPerSyllable, speech_frames / static_cast<double>(total_syllables));
}

// The sentences' spans when the speech is cut at loudness.pauses[chosen[k]], k = 0 .. (in order).
std::vector<FrameSpan> spans_between_pauses(const LoudnessProfile& loudness,
                                            const std::vector<std::size_t>& chosen) {
    std::vector<FrameSpan> spans;
    std::size_t first = loudness.speech_first_frame;
    for (const std::size_t pause : chosen) {
        spans.push_back({first, loudness.pauses[pause].first_frame});
        first = loudness.pauses[pause].end_frame;
    }
    spans.push_back({first, loudness.speech_end_frame});
    return spans;
}

// How long a sentence may grow as the cut's search extends it back over earlier pauses: the search stops
// there, so a cut need not weigh every pause before each boundary. A sentence kLongestSentenceShare times
// its expected length lies ln 6 / kSentenceDurationSigma = 5.1 spreads off it and scores -13.1, twice what
// ending at a pause of 10 s earns (kPauseWeight ln(10 s / kMinPauseS) = 6.6): the cuts the bound leaves out
// score far below those it keeps. kLongestSentenceSlackFrames (3 s) on top: a sentence of one or two
// syllables expects 0.1-0.5 s, and the pauses it holds count in its length. Both came unexplained with the
// first cutter (ad6f37c); bench/ Session 32 (review2): with no bound, the dumps of /work/corpus/espeak,
// human and voice-v are byte-identical, so the bound prunes the search and decides no cut there.
constexpr double kLongestSentenceShare = 6.0;
constexpr double kLongestSentenceSlackFrames = 300.0;

// The cut of the sentences (their syllable counts) at pauses that scores best; empty if no cut
// gives every sentence room for its syllables.
std::vector<FrameSpan> choose_sentence_pauses(const LoudnessProfile& loudness, const std::vector<std::size_t>& syllables) {
    const std::size_t sentence_count = syllables.size();
    const auto& pauses = loudness.pauses;
    const std::size_t boundary_count = sentence_count - 1;
    const double frames_per_syllable = mean_frames_per_syllable(loudness, syllables);
    // paused_before[i]: the frames of pauses 0..i-1, for the pauses a sentence holds.
    std::vector<std::size_t> paused_before(pauses.size() + 1, 0);
    for (std::size_t i = 0; i < pauses.size(); ++i) paused_before[i + 1] = paused_before[i] + pauses[i].length();

    // The sentence from frame first to end holds pauses inner_first..inner_end-1.
    auto sentence_score = [&](std::size_t first, std::size_t end, std::size_t inner_first, std::size_t inner_end,
                              std::size_t sentence) {
        // Far too short for its syllables, however the rest fits: a note of music before the first
        // sentence, taken for a sentence, shifted every sentence after it by one. Its speech is
        // what check_sentence_lengths counts, the frames outside the pauses it holds: music after
        // the last word, cut in two by a rest, held a sentence at 7.4 frames a syllable, but 4.6 of speech.
        if (end <= first) return kNegativeInfinity;
        const std::size_t paused = paused_before[inner_end] - paused_before[inner_first];
        if (static_cast<double>(end - first - paused) < kFastestFramesPerSyllable * static_cast<double>(syllables[sentence]))
            return kNegativeInfinity;
        const double expected = frames_per_syllable * static_cast<double>(syllables[sentence]);
        const double z = std::log(static_cast<double>(end - first) / expected) / kSentenceDurationSigma;
        return -0.5 * z * z;
    };
    auto pause_score = [&](std::size_t pause) {
        return kPauseWeight * std::log(static_cast<double>(pauses[pause].length()) * kFrameStepS / kMinPauseS);
    };
    auto too_long = [&](std::size_t first, std::size_t end, std::size_t sentence) {
        return static_cast<double>(end - first) >
               kLongestSentenceShare * frames_per_syllable * static_cast<double>(syllables[sentence]) +
                   kLongestSentenceSlackFrames;
    };

    // Dynamic programming over (boundary k, pause c): the best cut of sentences 0..k with sentence
    // k ending at pause c.
    const std::size_t pause_count = pauses.size();
    std::vector<double> score(boundary_count * pause_count, kNegativeInfinity);
    std::vector<std::size_t> previous(boundary_count * pause_count, 0);
    for (std::size_t c = 0; c + boundary_count <= pause_count; ++c)
        score[c] = sentence_score(loudness.speech_first_frame, pauses[c].first_frame, 0, c, 0) + pause_score(c);
    for (std::size_t k = 1; k < boundary_count; ++k) {
        for (std::size_t c = k; c + boundary_count - k <= pause_count; ++c) {
            double best = kNegativeInfinity;
            std::size_t best_previous = 0;
            for (std::size_t p = c; p-- > k - 1;) {
                if (too_long(pauses[p].end_frame, pauses[c].first_frame, k)) break;
                const double candidate = score[(k - 1) * pause_count + p];
                if (candidate == kNegativeInfinity) continue;
                const double total = candidate + sentence_score(pauses[p].end_frame, pauses[c].first_frame, p + 1, c, k);
                if (total > best) { best = total; best_previous = p; }
            }
            if (best == kNegativeInfinity) continue;
            score[k * pause_count + c] = best + pause_score(c);
            previous[k * pause_count + c] = best_previous;
        }
    }
    double best = kNegativeInfinity;
    std::size_t last = 0;
    for (std::size_t c = boundary_count - 1; c < pause_count; ++c) {
        const double candidate = score[(boundary_count - 1) * pause_count + c];
        if (candidate == kNegativeInfinity) continue;
        const double total = candidate + sentence_score(pauses[c].end_frame, loudness.speech_end_frame, c + 1, pause_count, boundary_count);
        if (total > best) { best = total; last = c; }
    }
    // No cut gives every sentence room for its syllables: the pauses do not single the sentence
    // ends out (music over a pause, two pauses in one), and the syllables must place them.
    if (best == kNegativeInfinity) return {};
    std::vector<std::size_t> chosen(boundary_count);
    for (std::size_t k = boundary_count; k-- > 0;) {
        chosen[k] = last;
        last = previous[k * pause_count + last];
    }
    return spans_between_pauses(loudness, chosen);
}

// The cut of every sentence from that of the spoken ones: a sentence without syllables (only
// symbols) takes no time and sits at the next spoken one's start.
void place_spoken_spans(const std::vector<std::size_t>& all_counts, const std::vector<std::size_t>& spoken,
                        const std::vector<FrameSpan>& spoken_spans, const std::vector<bool>& spoken_runs_on,
                        SentenceCut& cut) {
    cut.spans.resize(all_counts.size());
    cut.runs_on.assign(all_counts.size(), false);
    std::size_t next_spoken = 0;
    for (std::size_t k = 0; k < all_counts.size(); ++k) {
        if (next_spoken < spoken.size() && spoken[next_spoken] == k) {
            cut.runs_on[k] = spoken_runs_on[next_spoken];
            cut.spans[k] = spoken_spans[next_spoken++];
        } else {
            const std::size_t at = next_spoken < spoken_spans.size() ? spoken_spans[next_spoken].first_frame
                                   : spoken_spans.empty()           ? 0
                                                                    : spoken_spans.back().end_frame;
            cut.spans[k] = {at, at};
        }
    }
}

// Smoothed activity from per-frame activity `raw` (the loudest band above its floor).
std::vector<float> smoothed_activity(const std::vector<float>& raw) {
    const std::size_t frames = raw.size();
    std::vector<float> activity(frames);
    for (std::size_t t = 0; t < frames; ++t) {
        const std::size_t first = t >= kSmoothingFrames / 2 ? t - kSmoothingFrames / 2 : 0;
        const std::size_t end = std::min(frames, t + kSmoothingFrames / 2 + 1);
        float sum = 0.0f;
        for (std::size_t i = first; i < end; ++i) sum += raw[i];
        activity[t] = sum / static_cast<float>(end - first);
    }
    return activity;
}

// `profile.activity_db` smoothed from the per-frame activity `raw`, with what is no speech however loud
// taken down to a pause's level: a steady tone (its frames in `raw` set to the floor and listed in
// profile.tones), music held through the pauses and a beat's hits between the pauses it cuts up.
void take_down_tones_and_music(const FeatureTrack& track, const std::vector<float>& share,
                               const std::vector<bool>& tone, std::vector<float>& raw, LoudnessProfile& profile) {
    const std::size_t frames = track.frame_count;
    profile.activity_db = smoothed_activity(raw);
    // A steady tone (a beep) as loud as speech is no speech: its frames read as the floor, and the
    // threshold stays where the recording's levels put it. Quieter tones (a hum in the pauses) are
    // left: they are no speech already.
    profile.tones.clear();
    for (std::size_t t = 0; t < frames; ++t) {
        if (!tone[t] || raw[t] < profile.activity_threshold_db) continue;
        raw[t] = 0.0f;
        if (profile.tones.empty() || profile.tones.back().end_frame < t) profile.tones.push_back({t, t + 1});
        else profile.tones.back().end_frame = t + 1;
    }
    if (!profile.tones.empty()) profile.activity_db = smoothed_activity(raw);
    // Music held through the pauses is as loud as the quieter speech: where it is held, the frame
    // is no louder than a pause can be. So are a beat's hits between the pauses it cuts up, where
    // the beat's repeats explain them. (The same changing shares judge music before the voice and
    // after it, below.)
    const std::vector<bool> held =
        held_music_frames(track, share, profile.activity_db, profile.activity_threshold_db);
    const float pause_db = std::nextafter(profile.activity_threshold_db, -std::numeric_limits<float>::infinity());
    for (std::size_t t = 0; t < frames; ++t)
        if (held[t]) profile.activity_db[t] = std::min(profile.activity_db[t], pause_db);
    const std::vector<bool> repeated = repeated_hits_between_pauses(
        profile.activity_db, profile.activity_threshold_db, accompaniment_period_frames(track, profile.high_sound_floor_db));
    for (std::size_t t = 0; t < frames; ++t)
        if (repeated[t]) profile.activity_db[t] = pause_db;
}

// The pauses between frames first and end: runs of kMinPauseFrames or more that are no speech.
std::vector<FrameSpan> pauses_between(const LoudnessProfile& profile, std::size_t first, std::size_t end) {
    std::vector<FrameSpan> pauses;
    for (std::size_t t = first; t < end;) {
        if (is_speech_frame(profile, t)) {
            ++t;
            continue;
        }
        std::size_t pause_end = t;
        while (pause_end < end && !is_speech_frame(profile, pause_end)) ++pause_end;
        if (pause_end - t >= kMinPauseFrames) pauses.push_back({t, pause_end});
        t = pause_end;
    }
    return pauses;
}

// kUnspokenSpeechBelowDb under the speech's level (its median speech frame between frames first and end):
// sound at a recording's edge that never reaches it is the noise's (find_speech).
float unspoken_below_db(const LoudnessProfile& profile, std::size_t first, std::size_t end) {
    std::vector<float> speech_db;
    for (std::size_t t = first; t < end; ++t)
        if (is_speech_frame(profile, t)) speech_db.push_back(profile.activity_db[t]);
    return speech_db.empty() ? 0.0f : percentile_of(speech_db, 0.5) - kUnspokenSpeechBelowDb;
}

// A click (a button pressed to record, a plug, a mouse) before the speech or after it, frames first to
// end: sound too short for any syllable, set apart by a pause. A 20 ms click holds two or three frames
// of `raw` at `threshold_db` or above before smoothing (the analysis window spreads it). On every corpus
// of bench/ the stretches this drops at a recording's ends held no syllable's start: their alignments
// are the same to the digit (session 12).
bool is_click(const std::vector<float>& raw, float threshold_db, std::size_t first, std::size_t end) {
    const auto loud = std::count_if(raw.begin() + static_cast<std::ptrdiff_t>(first),
                                    raw.begin() + static_cast<std::ptrdiff_t>(end),
                                    [&](float db) { return db >= threshold_db; });
    return loud <= static_cast<std::ptrdiff_t>(kLongestClickFrames);
}

// Whether `sound`, set apart from `voice` after it by quiet shorter than a pause, is a click: too
// short for any syllable (is_click, on `raw`), and lacking harmonics beside the voice as a beat does
// (loud_harmonic_share, is_beat_beside_voice): a click's power spreads over its band.
// A first syllable short and weak enough in noise for is_click holds its vowel's harmonics (bench/
// voice-v v-fast-pink15 held-out-006's 警: 4 loud frames, all harmonic; the short kinds' clicks 0-1
// of 1-5).
bool is_close_click(const FeatureTrack& track, const std::vector<float>& raw, const LoudnessProfile& profile,
                    const FrameSpan& sound, const FrameSpan& voice) {
    const auto harmonic_share = [&](const FrameSpan& span) {
        return loud_harmonic_share(track, profile.activity_db, profile.activity_threshold_db,
                                   span.first_frame, span.end_frame);
    };
    return is_click(raw, profile.activity_threshold_db, sound.first_frame, sound.end_frame) &&
           is_beat_beside_voice(harmonic_share(sound), harmonic_share(voice));
}

// Whether the recording is a line cut to its sound, its speech from frame first to end and
// profile.pauses set. Quiet shorter than a pause between the recording's edges and its speech is the
// speech's own weak edge, as such a gap inside it is a closure. Where there is no pause at all, the
// floors are the speech's weakest sound (a line cut to its sound: 好's h, which then reads as silence);
// digital zeros at an edge are a pause of their own, however short.
bool is_cut_to_sound(const FeatureTrack& track, const LoudnessProfile& profile, std::size_t first,
                     std::size_t end) {
    const std::size_t frames = track.frame_count;
    return first < end && profile.pauses.empty() && first < kMinPauseFrames &&
           frames - end < kMinPauseFrames && track.at(0, kEnergyDb) > kDigitalSilenceDb &&
           track.at(frames - 1, kEnergyDb) > kDigitalSilenceDb;
}

// `profile` (its floors, levels and threshold set) completed from the per-frame activity `raw`:
// its tones, its smoothed activity with music and beats taken down to a pause's level, its pauses
// and where its speech starts and ends. `share` is changing_shares(track), `tone` steady_tone_frames(track).
void find_speech(const FeatureTrack& track, const std::vector<float>& share, const std::vector<bool>& tone,
                 std::vector<float> raw, LoudnessProfile& profile) {
    const std::size_t frames = track.frame_count;
    profile.unvoiced_edges.clear();
    profile.music_before_voice = {};
    profile.voice_under_music = {};
    take_down_tones_and_music(track, share, tone, raw, profile);
    std::size_t first_speech = 0;
    while (first_speech < frames && !is_speech_frame(profile, first_speech)) ++first_speech;
    std::size_t end_speech = frames;
    while (end_speech > first_speech && !is_speech_frame(profile, end_speech - 1)) --end_speech;
    std::vector<FrameSpan> pauses = pauses_between(profile, first_speech, end_speech);
    // Before the first pause and after the last: sound that never comes within
    // kUnspokenSpeechBelowDb of the speech's level (the median speech frame) is the noise's, not
    // speech (music or a door before the speaker starts): the speech starts after it.
    const float noise_below_db = unspoken_below_db(profile, first_speech, end_speech);
    const auto is_noise_only = [&](std::size_t first, std::size_t end) {
        return std::all_of(profile.activity_db.begin() + static_cast<std::ptrdiff_t>(first),
                           profile.activity_db.begin() + static_cast<std::ptrdiff_t>(end),
                           [&](float db) { return db < noise_below_db; });
    };
    const auto is_not_speech = [&](std::size_t first, std::size_t end) {
        return is_noise_only(first, end) || is_click(raw, profile.activity_threshold_db, first, end);
    };
    // Music before the voice comes in or after it ends is as loud as the speech, but holds its
    // notes (held_music.hpp; a last word and the music ringing on after it are shorter).
    const FrameSpan sound{first_speech, end_speech};
    const EdgeMusic edge_music = find_edge_music(
        track, share, profile.activity_db, profile.activity_threshold_db, pauses, sound,
        [&](const FrameSpan& stretch) { return is_not_speech(stretch.first_frame, stretch.end_frame); });
    std::size_t leading = edge_music.leading;
    std::size_t trailing = edge_music.trailing;
    if (leading > 0) first_speech = pauses[leading - 1].end_frame;
    if (trailing < pauses.size()) end_speech = pauses[trailing].first_frame;
    // Music that plays on under the first words, with no pause between them (music_bed.hpp).
    if (const auto bed =
            find_voice_under_music(track, share, profile.activity_db, profile.activity_threshold_db, pauses,
                                   sound, edge_music, kMinPauseFrames)) {
        first_speech = bed->entry;
        leading = bed->leading;
        profile.music_before_voice = {bed->stretch.first_frame, bed->entry};
        profile.voice_under_music = {bed->entry, bed->stretch.end_frame};
        pauses.insert(pauses.begin() + static_cast<std::ptrdiff_t>(leading), bed->pauses.begin(),
                      bed->pauses.end());
        trailing += bed->pauses.size();
    }
    // A breath before the first words (a rustle, a cough's hiss): sound set apart by a pause and never
    // voiced, beside a voice that is; every syllable has a voiced vowel. The band-ratio voicing only
    // before the first words: after the last, music's quieter tail reads unvoiced by it too (bench/
    // r-music tuning-007, session 28). A breath has no fundamental either (breath_edge.hpp), which
    // music's tail keeps (its bass): on both edges, sound with none beside a voice with one is a breath.
    const auto is_breath = [&](const FrameSpan& stretch, const FrameSpan& voice, bool is_before) {
        const bool is_dropped = is_breath_beside_voice(track, profile, stretch, voice, is_before);
        if (is_dropped) profile.unvoiced_edges.push_back(stretch);
        return is_dropped;
    };
    // The voice beside an edge's stretch runs up to the other edge's stretch, where one lies beyond
    // it: that may be a breath too, and counted in the voice it held the voice's share under a
    // voice's (bench/ short kinds p-breath, a breath on both edges: held-out 快走 530 ms early, tuning
    // 你在哪呢 301 ms).
    const auto voice_after = [&](std::size_t pause) {
        return FrameSpan{pauses[pause].end_frame,
                         pause + 1 < trailing ? pauses[trailing - 1].first_frame : end_speech};
    };
    const auto voice_before = [&](std::size_t pause) {
        return FrameSpan{leading < pause ? pauses[leading].end_frame : first_speech,
                         pauses[pause].first_frame};
    };
    while (leading < trailing &&
           (is_not_speech(first_speech, pauses[leading].first_frame) ||
            is_breath({first_speech, pauses[leading].first_frame}, voice_after(leading), true)))
        first_speech = pauses[leading++].end_frame;
    while (trailing > leading &&
           (is_not_speech(pauses[trailing - 1].end_frame, end_speech) ||
            is_breath({pauses[trailing - 1].end_frame, end_speech}, voice_before(trailing - 1), false)))
        end_speech = pauses[--trailing].first_frame;
    // A click closer to the first words than a pause: the smoothing spreads its two or three frames
    // and the first word's onset over the quiet between, which then reads shorter than a pause
    // (a click 0.135 s before the line reads 9-10 quiet frames, a pause 12). Taken for the line's start, it
    // drew to itself a first syllable with no closure to fill the quiet (bench/ short kinds, click: held-out
    // 好的's 好 149 ms early, tuning 你聽得到我嗎's 你 108 ms). The quiet after it is no syllable's either:
    // after a click, as after a pause, a closure cannot be told from the quiet (SPEC), and searched into, a
    // first stop's closure took it (tuning 快跑's 快 61 ms early, where with the click read as speech it was
    // 21).
    const std::size_t first_words_end = leading < trailing ? pauses[leading].first_frame : end_speech;
    if (const auto gap = find_gap_after_first_sound(profile, first_speech, first_words_end);
        gap && is_close_click(track, raw, profile, {first_speech, gap->first_frame},
                              {gap->end_frame, first_words_end})) {
        profile.unvoiced_edges.push_back({first_speech, gap->end_frame});
        first_speech = gap->end_frame;
    }
    // A breath that ends closer to the first words than a pause: the quiet between is still longer
    // than a closure inside a word.
    if (const auto breath = find_close_breath(track, profile, first_speech, first_words_end)) {
        profile.unvoiced_edges.push_back(*breath);
        first_speech = breath->end_frame;
        while (!is_speech_frame(profile, first_speech)) ++first_speech;
    }
    profile.pauses.assign(pauses.begin() + static_cast<std::ptrdiff_t>(leading), pauses.begin() + static_cast<std::ptrdiff_t>(trailing));
    profile.is_cut_to_sound = is_cut_to_sound(track, profile, first_speech, end_speech);
    if (profile.is_cut_to_sound) {
        first_speech = 0;
        end_speech = frames;
    }
    profile.speech_first_frame = first_speech;
    profile.speech_end_frame = end_speech;
}

// The floors of the energy and of each band (kFloorPercentile of every frame) and of the frames
// with sound in them (sound_percentile).
void set_floors(const FeatureTrack& track, LoudnessProfile& profile) {
    profile.energy_floor_db = column_percentile(track, kEnergyDb, kFloorPercentile);
    profile.low_floor_db = column_percentile(track, kLowBandDb, kFloorPercentile);
    profile.mid_floor_db = column_percentile(track, kMidBandDb, kFloorPercentile);
    profile.high_floor_db = column_percentile(track, kHighBandDb, kFloorPercentile);
    profile.energy_sound_floor_db =
        sound_percentile(track, kEnergyDb, kFloorPercentile, profile.energy_floor_db);
    profile.low_sound_floor_db = sound_percentile(track, kLowBandDb, kFloorPercentile, profile.low_floor_db);
    profile.high_sound_floor_db =
        sound_percentile(track, kHighBandDb, kFloorPercentile, profile.high_floor_db);
}

// Each frame's loudness in dB above the floors: the band that rises most above its own, 0 at the floors.
std::vector<float> above_floors(const FeatureTrack& track, const LoudnessProfile& profile) {
    std::vector<float> raw(track.frame_count);
    for (std::size_t t = 0; t < track.frame_count; ++t) {
        raw[t] = std::max({track.at(t, kLowBandDb) - profile.low_floor_db,
                           track.at(t, kMidBandDb) - profile.mid_floor_db,
                           track.at(t, kHighBandDb) - profile.high_floor_db, 0.0f});
    }
    return raw;
}

// The activity threshold between the noise and the speech, in dB above the floors as the loud frames'
// and the noise's typical levels are: kThresholdShareOfSpeech of the way up and at most kReverbFillDb
// below the loud frames, never less than kAboveFloorDb above the floor nor kNoiseWanderDb above the noise.
float activity_threshold_db(float speech_level_db, float noise_level_db) {
    return std::max({kThresholdShareOfSpeech * speech_level_db, speech_level_db - kReverbFillDb,
                     kAboveFloorDb, noise_level_db + kNoiseWanderDb});
}

// measure_loudness, with `lead_in` (empty, or noise a gain lifted before the first words) read
// as that noise.
LoudnessProfile measure_loudness_with(const FeatureTrack& track, const FrameSpan& lead_in) {
    LoudnessProfile profile;
    set_floors(track, profile);
    const std::size_t frames = track.frame_count;
    std::vector<float> raw = above_floors(track, profile);
    profile.activity_db = smoothed_activity(raw);
    profile.speech_level_db = percentile_of(profile.activity_db, kSpeechPercentile);
    const float speech_level_db = profile.speech_level_db;
    profile.activity_threshold_db =
        activity_threshold_db(speech_level_db, percentile_of(profile.activity_db, kNoisePercentile));
    const std::vector<float> share = changing_shares(track);
    const std::vector<bool> tone = steady_tone_frames(track);
    find_speech(track, share, tone, raw, profile);
    // Noise a gain control lifts in the pauses is a pause at any gain (lifted_noise.hpp), but only
    // between the speech's edges as the music rules find them without the lift: the quiet between
    // a sung intro's phrases keeps the floor's shape too, and read as pauses it cut the intro into
    // stretches the edge-music rule no longer set apart (bench/README.md, sessions 27 and 28). The
    // threshold stays where the whole recording's levels put it: taken after the lift, it falls
    // with the lifted noise, and p-agc's tuning passages read 91.0% within 50 ms, one refused,
    // where they read 97.0% (session 27).
    std::vector<float> lift = noise_lift_db(track, profile.low_floor_db, profile.mid_floor_db,
                                            profile.high_floor_db, speech_level_db, kMinPauseFrames,
                                            {profile.speech_first_frame, profile.speech_end_frame});
    // All of a lifted lead-in is the noise, and no sentence is searched into it.
    for (std::size_t t = lead_in.first_frame; t < lead_in.end_frame; ++t) lift[t] = std::max(lift[t], raw[t]);
    if (std::any_of(lift.begin(), lift.end(), [](float db) { return db > 0.0f; })) {
        for (std::size_t t = 0; t < frames; ++t) raw[t] = std::max(0.0f, raw[t] - lift[t]);
        find_speech(track, share, tone, raw, profile);
    }
    if (lead_in.length() > 0)
        profile.unvoiced_edges.insert(profile.unvoiced_edges.begin(),
                                      {0, std::min(lead_in.end_frame, profile.speech_first_frame)});
    return profile;
}

}  // namespace

std::vector<std::size_t> syllables_per_sentence(const Timeline& transcript) {
    std::vector<std::size_t> counts(transcript.sentences.size(), 0);
    for (const auto& syllable : transcript.syllables) ++counts.at(syllable.sentence);
    return counts;
}

LoudnessProfile measure_loudness(const FeatureTrack& track) {
    return measure_loudness_with(track, {0, 0});
}

std::optional<LoudnessProfile> loudness_after_lifted_lead_in(const FeatureTrack& track,
                                                             const LoudnessProfile& loudness) {
    if (loudness.speech_first_frame >= kMinPauseFrames) return std::nullopt;
    const auto lead_in = lifted_lead_in(track, loudness.low_floor_db, loudness.mid_floor_db,
                                        loudness.high_floor_db, kMinPauseFrames);
    if (!lead_in) return std::nullopt;
    return measure_loudness_with(track, *lead_in);
}

SentenceCut cut_sentences(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                          const AlignOptions& options) {
    const std::vector<std::size_t> all_counts = syllables_per_sentence(transcript);
    // Sentences without a syllable (only symbols) take no time: they sit at the next one's start.
    std::vector<std::size_t> spoken;
    std::vector<std::size_t> spoken_counts;
    for (std::size_t k = 0; k < all_counts.size(); ++k) {
        if (all_counts[k] == 0) continue;
        spoken.push_back(k);
        spoken_counts.push_back(all_counts[k]);
    }
    SentenceCut cut;
    std::vector<FrameSpan> spoken_spans;
    std::vector<bool> spoken_runs_on(spoken.size(), false);
    if (options.sentence_cut == SentenceCutMode::first_pause) {
        spoken_spans = speaking_parts_from_first_pause(track, options);
        if (spoken_spans.size() != spoken.size()) {
            std::string found;
            for (const auto& span : spoken_spans) found += (found.empty() ? "" : ", ") + span_text(span);
            throw AlignmentError("Algorithm 3.1 with the first pause " + format_fixed(options.first_pause_start_s, 2) +
                                 "-" + format_fixed(options.first_pause_end_s, 2) + " s found " +
                                 std::to_string(spoken_spans.size()) + " speaking parts (" + found +
                                 ") but the transcript has " + std::to_string(spoken.size()) +
                                 " spoken sentences; select another pause, or use the automatic mode");
        }
    } else if (spoken.size() == 1) {
        spoken_spans.push_back({loudness.speech_first_frame, loudness.speech_end_frame});
    } else {
        if (loudness.pauses.size() + 1 >= spoken.size()) spoken_spans = choose_sentence_pauses(loudness, spoken_counts);
        if (spoken_spans.empty()) {
            // Some sentence ends have no pause, or none the sentences' lengths can be cut at:
            // which ones, only the syllables can tell.
            spoken_spans.assign(spoken.size(), {loudness.speech_first_frame, loudness.speech_end_frame});
            spoken_runs_on.assign(spoken.size(), true);
            spoken_runs_on.back() = false;
        } else {
            spoken_runs_on = find_run_together(spoken_spans, spoken_counts, loudness);
            cut.is_in_doubt = are_sentence_ends_in_doubt(spoken_spans, spoken_counts, loudness);
        }
    }
    place_spoken_spans(all_counts, spoken, spoken_spans, spoken_runs_on, cut);
    return cut;
}

SentenceCut given_sentence_cut(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                               const std::vector<GivenSpan>& spans_s) {
    const std::vector<std::size_t> all_counts = syllables_per_sentence(transcript);
    if (spans_s.size() != all_counts.size())
        throw InvalidArgument("spans", "expected one span per sentence (" + std::to_string(all_counts.size()) +
                                           "), found " + std::to_string(spans_s.size()));
    const double duration_s = static_cast<double>(track.frame_count) * kFrameStepS;
    std::vector<std::size_t> spoken;
    std::vector<FrameSpan> limits;
    for (std::size_t k = 0; k < all_counts.size(); ++k) {
        if (all_counts[k] == 0) continue;
        const GivenSpan& given = spans_s[k];
        if (!(std::isfinite(given.start_s) && std::isfinite(given.end_s) && given.start_s >= 0.0 &&
              given.end_s > given.start_s && given.start_s < duration_s)) {
            throw InvalidArgument("spans", "sentence " + std::to_string(k + 1) + " (" +
                                               quote_start(transcript.sentences[k].text) + "): expected 0 <= start < end, start inside the " +
                                               format_fixed(duration_s, 3) + " s of audio, found " +
                                               format_fixed(given.start_s, 3) + "-" + format_fixed(given.end_s, 3) + " s");
        }
        spoken.push_back(k);
        const auto first = static_cast<std::size_t>(std::floor(given.start_s / kFrameStepS));
        const auto end = std::min(track.frame_count, static_cast<std::size_t>(std::ceil(given.end_s / kFrameStepS)));
        limits.push_back({first, std::max(end, first + 1)});
    }
    std::vector<FrameSpan> spoken_spans;
    std::vector<bool> spoken_runs_on(spoken.size(), false);
    for (std::size_t i = 0; i < spoken.size(); ++i) {
        // The syllables' durations follow the speech, not the quiet edges a cue leaves around it.
        const FrameSpan& limit = limits[i];
        std::size_t first = limit.first_frame;
        std::size_t end = limit.end_frame;
        while (first < end && !is_speech_frame(loudness, first)) ++first;
        while (end > first && !is_speech_frame(loudness, end - 1)) --end;
        spoken_spans.push_back(end > first ? FrameSpan{first, end} : limit);
        // One cue for both, or a cue across the end of one: a cue that starts where the last ended does not.
        if (i + 1 < spoken.size()) spoken_runs_on[i] = spans_s[spoken[i + 1]].start_s < spans_s[spoken[i]].end_s;
    }
    SentenceCut cut;
    place_spoken_spans(all_counts, spoken, spoken_spans, spoken_runs_on, cut);
    cut.limits.assign(all_counts.size(), {0, track.frame_count});
    for (std::size_t i = 0; i < spoken.size(); ++i) cut.limits[spoken[i]] = limits[i];
    return cut;
}

}  // namespace talkface::detail
