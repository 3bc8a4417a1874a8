#include "speech/sentence_chains.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/order_statistics.hpp"
#include "speech/level_line.hpp"
#include "speech/noise_reach.hpp"
#include "speech/room_closures.hpp"

namespace talkface::detail {

namespace {

// Each sentence is searched with this much of the pauses around it, so that its first and last
// sounds are free to start and end where the audio says.
constexpr std::size_t kEdgeFrames = 30;
// How far below the loudest frame of the end of a sentence its last sound ends (end_before_tail):
// a room's tail starts 13-20 dB below the last vowel, which may itself be 10 dB below the louder
// syllables before it; the last 0.6 s hold a syllable's vowel, or behind a large room's long tail
// its ringing (kVowelPeakReachFrames). (bench/ reverb: 15-20 dB
// find every sentence end, 25 dB leaves a tenth of them in the tail.)
constexpr float kTailFallDb = 18.0f;
constexpr std::size_t kTailReferenceFrames = 60;
// Where a room's tail is long (up to 0.6 s in a large room) the reference window lies mostly in it,
// and its loudest frame is its first, or one of its first, in the ringing of the last vowel: the
// reference is then followed back to that vowel's peak while a frame at most this many frames
// earlier stands over it (a vowel's own ripple; a closure or a pause between syllables is longer
// only where the syllable before it is louder, which the window would have held anyway).
// (bench/README.md Session 35 (room3), the short kinds' rooms, tuning: 3, 5, 8, 12 frames put
// 82.1, 83.3, 84.0, 82.1% of onsets within 50 ms, main 81.5.)
constexpr std::size_t kVowelPeakReachFrames = 8;
// A sentence end that end_before_tail moves this far is a room's tail: a voice's own fall past
// kTailFallDb takes a frame or two (bench/: 0-2 frames in every condition but reverb, 3-26 there).
constexpr std::size_t kRoomTailFrames = 3;
// A room's tail falls smoothly; a quiet stretch after the last loud one that rises this far again
// after a dip is speech (bench/ human speech: a quiet third-tone syllable after a closure, 15-25 dB
// under the one before, rises 20-40 dB out of its closure; a tail's 25 ms frames ripple by 1-3 dB).
constexpr float kTailRiseDb = 10.0f;
// Past kTailFallDb a room's tail is surely ringing, which falls on a line at the room's own decay; the
// ringing starts where the level, followed back, leaves that line drawn back by more than the
// ringing's ripple (a tail's 25 ms frames ripple by 1-3 dB). The line is fitted to at most
// kRingingFitFrames of the tail and at least kLeastRingingFitFrames: a shorter tail is the noise
// floor's or a fade's. (bench/README.md Session 33 (room), the short kinds' rooms, tuning: 21 of 38
// line ends within 5 frames, the mark alone 10.)
constexpr float kRingingRippleDb = 4.0f;
// A large room's ringing is a comb of its reflections: a frame or two of it may dip further under its
// line than the ripple, where one reflection has died and the next not come (the short kinds' rooms:
// 4-6 dB for one or two frames), and the level followed back goes on past them; a voice's fade stays
// under the line longer. (bench/README.md Session 37 (room4), the short kinds' rooms, tuning: the
// walk's end within 5 frames of the voice's in 19 of 38 lines where 2, 3, 4 or 6 frames are passed,
// 18 where 1, 17 where none; onsets within 50 ms 84.0 -> 86.4%.)
constexpr std::size_t kRingingDipFrames = 2;
constexpr std::size_t kRingingFitFrames = 30;
constexpr std::size_t kLeastRingingFitFrames = 8;
// Past the end of a voice in a room, the search reaches only this far into the tail.
constexpr std::size_t kTailEdgeFrames = 5;
// Outside a room a fall past kTailFallDb is the voice's own quiet end (a nasal coda's murmur, the
// coder's tail through a telephone band), which falls on to the noise between the sentences: the
// voice has stopped where the level stays at or under the noise's reach (steady_noise_reach of the
// recording's pauses, which the noise alone passes one frame in ten) this many frames running.
// (bench/README.md Session 37 (phoneend), the phone kinds, tuning boundaries p-speex8, p-g726,
// p-mp3: 1 frame 173, 173, 171; 3 and 5 frames 173, 174, 172; main 168, 169, 164.)
constexpr std::size_t kQuietFrames = 3;
// A voice that comes back after its quiet end fell into the noise (a neutral-tone vowel after a
// fricative the band took away) holds over the level the noise passes one frame in a hundred this
// many frames running, as a short vowel lasts; a steady noise's swells last less. (bench/README.md
// Session 38 (phoneend2): 休息's i 7-10 frames through every codec; a pink noise's swell 3 frames,
// which 3 frames took for a voice, espeak-ng pink20 tuning-018's 了 then ending 235 ms late.)
constexpr std::size_t kVoiceBackFrames = 6;
// Where only the voicing tells (below), a voice also comes back in this many frames running that
// cross zero less often than the pauses' frames do but one in ten: a short vowel surely voiced.
// (bench/README.md Session 41 (phoneend4): p-opus6's 休息, its i after the x 4 frames voiced, under
// the pauses' 10th percentile, 0.08-0.14 of the samples; p-fast-combo held-out-003's street noise
// after 孩子 5 frames voiced, 2 under the 10th percentile: 4 voiced frames, or 4 under the 15th,
// ran 孩子's end 180 ms late; 6 voiced frames bring p-loss's 休息 back.)
constexpr std::size_t kVoicedBackFrames = 4;
constexpr double kVoicedBackCrossingShare = 0.1;
// What the silence at each edge of a recording cut to its sound may take: a phone's coder puts
// the sound a few ms after the file's start and ramps into it over its first 20 ms frame (AMR-NB),
// and its band limit smears the onset. One frame held the phone's first syllables to the ramp
// (bench/short_onsets_bench.py, tuning: person-phone 91.9% within 50 ms, two frames 92.7%, three
// 92.7%; main 91.5%); the weak first sound that set the floors reaches past it (espeak-ng's h of
// 好, 80 ms).
constexpr std::size_t kCutEdgeFrames = 2;

// The loudest frame of [from, end) (from < end).
std::size_t loudest_in(const FeatureTrack& track, std::size_t from, std::size_t end) {
    std::size_t loudest = end - 1;
    for (std::size_t t = from; t < end; ++t)
        if (track.at(t, kEnergyDb) > track.at(loudest, kEnergyDb)) loudest = t;
    return loudest;
}

// Where the end of a sentence's voice in [first, end) (first < end) is measured from: the loudest
// frame of its last kTailReferenceFrames, followed back to the peak of the vowel whose ringing it
// is where louder frames lie just before it (kVowelPeakReachFrames) and what follows it only
// falls, as a tail does: where the level rises again by kTailRiseDb after a dip, a syllable of its
// own follows (fast speech holds several in the window) and the window's loudest is its vowel.
std::size_t loudest_before(const FeatureTrack& track, std::size_t first, std::size_t end) {
    std::size_t peak =
        loudest_in(track, end > first + kTailReferenceFrames ? end - kTailReferenceFrames : first, end);
    float dip_db = track.at(peak, kEnergyDb);
    for (std::size_t t = peak + 1; t < end; ++t) {
        dip_db = std::min(dip_db, track.at(t, kEnergyDb));
        if (track.at(t, kEnergyDb) > dip_db + kTailRiseDb) return peak;
    }
    while (peak > first) {
        const std::size_t louder = loudest_in(
            track, peak > first + kVowelPeakReachFrames ? peak - kVowelPeakReachFrames : first, peak);
        if (track.at(louder, kEnergyDb) <= track.at(peak, kEnergyDb)) break;
        peak = louder;
    }
    return peak;
}

// Frames of `span` that are not in a pause: what the syllables fill, so that the vowels' duration
// priors follow the speaking rate, not the pauses (a transcript without punctuation runs over the
// pauses between its sentences).
std::size_t speech_frames(const LoudnessProfile& loudness, const FrameSpan& span) {
    std::size_t frames = span.length();
    for (const auto& pause : loudness.pauses)
        if (pause.first_frame >= span.first_frame && pause.end_frame <= span.end_frame) frames -= pause.length();
    return frames;
}

// The recording's noise in its pauses, whole band: the level it stays under (steady_noise_reach),
// and the level it passes one frame in a hundred, which a voice coming back stands over. That one
// is read from the noise's steady middle, not its loudest frames (a pause's edges hold the voice's
// and breaths): where a noise's levels in dB lie as a normal spread does, their 99th percentile
// stands over their 90th by kRareOverReach of the spread between their 10th and 90th.
constexpr float kRareOverReach = 0.41f;
// Where the noise's level swings too far for a reach (a coder's gated comfort noise: Opus at 6 kbit/s
// swings -61 to -72 dB from frame to frame, and a vowel's voiced tail lies in it at -56 to -58 dB), its
// voicing can still tell the voice from it: a voiced frame crosses zero a few times a period of its low
// harmonics, a noise spread over the band far more often. A frame reads voiced where it crosses zero
// less often than kVoicedCrossingShare of the pauses' frames do and stands over the level
// kVoicedOverLevelShare of them stay under: the comfort noise's quiet phases cross less often than its
// loud ones, and an AGC's pumping (p-agc) lifts a low rumble that hardly crosses at all.
// (bench/README.md Session 40 (opusend), p-opus6: the pauses' 25th percentile 0.15-0.17 of the samples
// at 16 kHz, the vowels' tails 0.06-0.14, the noise's quiet phases 0.13-0.16, which without the level
// held 6 frames "voiced" running and ran ends 116-174 ms late; over the pauses' median level p-agc's
// ends ran up to 100 ms late, its pumped rumble crossing on 0.01-0.035 of the samples.)
constexpr double kVoicedCrossingShare = 0.25;
constexpr double kVoicedOverLevelShare = 0.75;
// The voicing tells only where that share of the pauses' crossings is more than this many times the
// voice's vowels' (their median over the sentences' frames louder than the sentences' median): p-opus6
// 1.65-2.05 in every passage; espeak-ng's music15 and music20 0.36-0.48, song15 0.48-1.19, human
// r-music mostly under 1.5 (its drums' passages 1.6-2.1), p-babble 0.42-0.88; p-agc's pink noise
// 0.96-2.27 ...
constexpr float kNoiseOverVowelCrossings = 1.5f;
// ... and where the noise alone reads voiced kQuietFrames running (as long as a voice's end takes to
// fall into it) on at most this share of the pauses' frames: music's held notes do (r-music's drums
// and piano, where the crossings pass the bar above: 0.13-0.15 at the pauses' median level; p-opus6
// 0-0.07).
constexpr double kNoiseVoicedRunShare = 0.1;

struct PauseNoise {
    float reach_db;
    float rare_db;
    // Where reach_db cannot tell (infinite) and the voicing can: the zero-crossing share a voiced frame
    // stays under (kVoicedCrossingShare), one read back under (kVoicedBackCrossingShare), and the
    // level both stand over (kVoicedOverLevelShare); 0 and +infinity where neither tells.
    float voiced_crossings = 0.0f;
    float voiced_back_crossings = 0.0f;
    float voice_over_db = std::numeric_limits<float>::infinity();
};

// Whether frame t stands over the noise's level for a voiced frame and crosses zero less often than
// `crossings` of its samples.
bool reads_voiced(const FeatureTrack& track, std::size_t t, const PauseNoise& noise, float crossings) {
    return track.at(t, kEnergyDb) > noise.voice_over_db && track.at(t, kZeroCrossings) < crossings;
}

// The zero-crossing share of a voice's vowels: the median over its sentences' frames louder than
// their median (0 where they have none).
float vowels_crossings(const FeatureTrack& track, const std::vector<SentenceChain>& chains) {
    std::vector<std::size_t> frames;
    for (const SentenceChain& chain : chains)
        for (std::size_t t = chain.speech.first_frame;
             t < std::min(chain.speech.end_frame, track.frame_count); ++t)
            frames.push_back(t);
    if (frames.empty()) return 0.0f;
    std::vector<float> levels;
    for (const std::size_t t : frames) levels.push_back(track.at(t, kEnergyDb));
    const float middle_db = upper_median(std::move(levels));
    std::vector<float> crossings;
    for (const std::size_t t : frames)
        if (track.at(t, kEnergyDb) > middle_db) crossings.push_back(track.at(t, kZeroCrossings));
    return crossings.empty() ? 0.0f : upper_median(std::move(crossings));
}

// The share of the pauses' frames that read voiced (reads_voiced) kQuietFrames or more running.
double voiced_run_share(const FeatureTrack& track, const LoudnessProfile& loudness, const PauseNoise& noise) {
    std::size_t frames = 0;
    std::size_t in_runs = 0;
    for (const FrameSpan& pause : loudness.pauses) {
        std::size_t run = 0;
        const std::size_t end = std::min(pause.end_frame, track.frame_count);
        for (std::size_t t = pause.first_frame; t <= end; ++t) {
            if (t < end && reads_voiced(track, t, noise, noise.voiced_crossings)) {
                ++run;
                continue;
            }
            if (run >= kQuietFrames) in_runs += run;
            run = 0;
        }
        frames += end - std::min(end, pause.first_frame);
    }
    return frames == 0 ? 0.0 : static_cast<double>(in_runs) / static_cast<double>(frames);
}

PauseNoise pauses_noise(const FeatureTrack& track, const LoudnessProfile& loudness,
                        const std::vector<SentenceChain>& chains) {
    std::vector<float> levels;
    std::vector<float> crossings;
    for (const FrameSpan& pause : loudness.pauses)
        for (std::size_t t = pause.first_frame; t < std::min(pause.end_frame, track.frame_count); ++t) {
            levels.push_back(track.at(t, kEnergyDb));
            crossings.push_back(track.at(t, kZeroCrossings));
        }
    const float reach_db = steady_noise_reach(levels);
    const PauseNoise by_level{reach_db, reach_db + kRareOverReach * noise_spread(levels)};
    if (std::isfinite(reach_db) || crossings.empty()) return by_level;
    PauseNoise by_voicing = by_level;
    by_voicing.voiced_crossings = percentile_of(crossings, kVoicedCrossingShare);
    by_voicing.voiced_back_crossings = percentile_of(std::move(crossings), kVoicedBackCrossingShare);
    by_voicing.voice_over_db = percentile_of(std::move(levels), kVoicedOverLevelShare);
    const bool tells =
        by_voicing.voiced_crossings > kNoiseOverVowelCrossings * vowels_crossings(track, chains) &&
        voiced_run_share(track, loudness, by_voicing) <= kNoiseVoicedRunShare;
    return tells ? by_voicing : by_level;
}

// Where a voice's quiet end from `mark` on has fallen into the noise: the first of kQuietFrames
// frames running that read as the noise (`is_noise`), unless the voice comes back, kVoiceBackFrames
// running `is_back` or kVoicedBackFrames running `is_surely_back`, and falls into the noise again
// before `end` (a neutral-tone vowel after a fricative the band took away: 休息's i after its x,
// bench/README.md Session 38 (phoneend2)): it is followed on to there. `mark` where it never falls
// before `end` (music or another voice on after it: nothing tells where the voice stopped). A sound
// that comes back and runs on to `end` is the next one's, not this voice's.
template <typename IsNoise, typename IsBack, typename IsSurelyBack>
std::size_t end_in_noise(std::size_t mark, std::size_t end, IsNoise is_noise, IsBack is_back,
                         IsSurelyBack is_surely_back) {
    std::size_t fallen = mark;
    bool is_voice = true;
    // Frames running that say the sound has changed from voice to noise or back (`run`), and surely
    // back (`sure_run`).
    std::size_t run = 0;
    std::size_t sure_run = 0;
    for (std::size_t t = mark; t < end; ++t) {
        if (is_voice) {
            run = is_noise(t) ? run + 1 : 0;
            if (run < kQuietFrames) continue;
        } else {
            run = is_back(t) ? run + 1 : 0;
            sure_run = is_surely_back(t) ? sure_run + 1 : 0;
            if (run < kVoiceBackFrames && sure_run < kVoicedBackFrames) continue;
        }
        is_voice = !is_voice;
        run = 0;
        sure_run = 0;
        if (!is_voice) fallen = t + 1 - kQuietFrames;
    }
    return fallen;
}

// Where the voice's quiet end from `mark` falls into the noise before `end` (end_in_noise): by the
// level where the noise is steady (a frame at or under its reach is the noise's; one over the level
// it passes one frame in a hundred is the voice's), else by the voicing where that tells (a frame
// that reads voiced is the voice's, any other the noise's; one under the stricter crossing bar
// surely the voice's); 0 where neither tells.
std::size_t quiet_end(const FeatureTrack& track, std::size_t mark, std::size_t end, const PauseNoise& noise) {
    if (std::isfinite(noise.reach_db))
        return end_in_noise(
            mark, end, [&](std::size_t t) { return track.at(t, kEnergyDb) <= noise.reach_db; },
            [&](std::size_t t) { return track.at(t, kEnergyDb) > noise.rare_db; },
            [](std::size_t) { return false; });
    if (noise.voiced_crossings <= 0.0f) return 0;
    auto is_voiced = [&](std::size_t t) { return reads_voiced(track, t, noise, noise.voiced_crossings); };
    return end_in_noise(
        mark, end, [&](std::size_t t) { return !is_voiced(t); }, is_voiced,
        [&](std::size_t t) { return reads_voiced(track, t, noise, noise.voiced_back_crossings); });
}

// Whether the voicing reads a voice on up to `mark` (where only that tells): one of the kQuietFrames
// frames before it (at or after `first`) reads voiced, so that the voice has not fallen into the
// noise there. A span the cutter ran on into the noise holds none: there the voicing reads only
// noise on past the mark (bench/README.md Session 41 (phoneend4), the short kinds' p-fast-combo).
bool is_voiced_before(const FeatureTrack& track, std::size_t first, std::size_t mark,
                      const PauseNoise& noise) {
    for (std::size_t t = mark; t > first && t + kQuietFrames > mark; --t)
        if (reads_voiced(track, t - 1, noise, noise.voiced_crossings)) return true;
    return false;
}

// Where the walk back along the ringing's line drawn from `mark` cannot tell where the voice
// stopped in [loudest, mark) (a reflection stands over the line just before the mark, the level
// passes under it, or the walk reaches the last vowel's peak), the voice's own stop is looked for:
// a one-frame fall larger than twice the ripple (two frames of ringing, one over its line and one
// under it, differ by up to that) and than any of the ringing's own in [mark, fit_end): the direct
// sound stopping, where a fade falls less a frame. From there the level to fit_end lies on a
// falling line of its own, no frame more than the ripple over it, and the frame before the fall
// stands over that line drawn back by more than the ripple (the voice over its own ringing). The
// earliest such fall; the mark where there is none. (bench/README.md Session 38 (room5), the short
// kinds' rooms, tuning: the end within 5 frames of the voice's in 21 of 38 lines, 19 before; a fall
// of once the ripple took the quiet light-tone last syllables of three human passages for ringing.)
std::size_t ringing_after_fall(const FeatureTrack& track, std::size_t loudest, std::size_t mark,
                               std::size_t fit_end) {
    auto fall_db = [&](std::size_t t) { return track.at(t - 1, kEnergyDb) - track.at(t, kEnergyDb); };
    float ringing_fall_db = 2.0f * kRingingRippleDb;
    for (std::size_t t = mark + 1; t < fit_end; ++t) ringing_fall_db = std::max(ringing_fall_db, fall_db(t));
    for (std::size_t t = loudest + 1; t < mark; ++t) {
        if (fall_db(t) <= ringing_fall_db) continue;
        const LevelLine ringing = fit_level_line(track, kEnergyDb, t, fit_end);
        if (!(ringing.slope_db_per_frame < 0.0)) continue;
        if (track.at(t - 1, kEnergyDb) - ringing.at(-1.0) <= kRingingRippleDb) continue;
        bool on_line = true;
        for (std::size_t u = t; u < fit_end && on_line; ++u)
            on_line = track.at(u, kEnergyDb) - ringing.at(static_cast<double>(u - t)) <= kRingingRippleDb;
        if (on_line) return t;
    }
    return mark;
}

// The edge pauses of `chain` hold every searched frame outside its syllable_bound: the path may not
// lay an edge syllable there, nor stretch the vowels over it (set_search_spans scales them to the
// speech inside the bound). Set after the edges' own bounds (kCutEdgeFrames), which it overrides.
void keep_syllables_in_bound(SentenceChain& chain) {
    const FrameSpan& bound = chain.syllable_bound;
    const auto hold = [](PhoneState& edge, std::size_t frames) {
        if (frames == 0) return;
        edge.is_optional = false;
        edge.min_frames = frames;
        edge.max_frames = std::max(edge.max_frames, frames);
    };
    if (bound.first_frame > chain.searched.first_frame && bound.first_frame < chain.searched.end_frame)
        hold(chain.states.front(), bound.first_frame - chain.searched.first_frame);
    if (bound.end_frame < chain.searched.end_frame && bound.end_frame > chain.searched.first_frame)
        hold(chain.states.back(), chain.searched.end_frame - bound.end_frame);
}

// The frames from the first of `a` and `b` to the end of the later.
FrameSpan spanning(const FrameSpan& a, const FrameSpan& b) {
    return {std::min(a.first_frame, b.first_frame), std::max(a.end_frame, b.end_frame)};
}

// Sentence k's span of a cut's optional per-sentence spans (SentenceCut::limits, syllable_bounds):
// every frame where the cut sets none.
FrameSpan sentence_span_or_all(const std::vector<FrameSpan>& spans, std::size_t k) {
    return spans.empty() ? FrameSpan{0, std::numeric_limits<std::size_t>::max()} : spans[k];
}

}  // namespace

std::vector<SentenceChain> group_chains(const Timeline& transcript, const SentenceCut& cut,
                                        const std::vector<FrameSpan>& spans) {
    std::vector<SentenceChain> chains;
    bool continues_block = false;
    // One pass: the syllables come in sentence order (validate_transcript), and a sentence without
    // syllables has nothing to align.
    for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
        const std::size_t k = transcript.syllables[i].sentence;
        if (i == 0 || transcript.syllables[i - 1].sentence != k) {
            if (!continues_block) {
                chains.emplace_back();
                chains.back().first_sentence = k;
                chains.back().speech = spans[k];
                chains.back().limit = sentence_span_or_all(cut.limits, k);
                chains.back().syllable_bound = sentence_span_or_all(cut.syllable_bounds, k);
            }
            SentenceChain& block = chains.back();
            block.end_sentence = k + 1;
            block.speech = spanning(block.speech, spans[k]);
            block.limit = spanning(block.limit, sentence_span_or_all(cut.limits, k));
            block.syllable_bound =
                spanning(block.syllable_bound, sentence_span_or_all(cut.syllable_bounds, k));
            continues_block = cut.runs_on[k];
        }
        chains.back().syllables.push_back(&transcript.syllables[i]);
        chains.back().syllable_indices.push_back(i);
    }
    return chains;
}

void set_search_spans(const FeatureTrack& track, const LoudnessProfile& loudness, std::vector<SentenceChain>& chains) {
    // A fall past kTailFallDb is a room's tail only where the recording's sentences ring on in the
    // median (is_room); elsewhere it is a voice's own quiet end (a nasal coda whose murmur a
    // telephone band takes away, bench/README.md Session 36 (bound)): the last syllable keeps it
    // to where it falls into the noise.
    for (SentenceChain& chain : chains) {
        chain.tail_frames =
            chain.speech.end_frame - end_before_tail(track, chain.speech.first_frame, chain.speech.end_frame);
        chain.ends_in_tail = chain.tail_frames >= kRoomTailFrames;
    }
    const bool rings = is_room(chains);
    for (SentenceChain& chain : chains) chain.ends_before_tail = rings;
    const PauseNoise noise =
        rings ? PauseNoise{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()}
              : pauses_noise(track, loudness, chains);
    // Edges reach into the pauses around the sentence, at most halfway to its neighbours.
    for (std::size_t w = 0; w < chains.size(); ++w) {
        SentenceChain& chain = chains[w];
        const FrameSpan& speech = chain.speech;
        std::size_t lower = std::max(chain.limit.first_frame,
                                     w == 0 ? 0 : (chains[w - 1].speech.end_frame + speech.first_frame) / 2);
        std::size_t upper = std::min(chain.limit.end_frame, w + 1 == chains.size()
                                                                ? track.frame_count
                                                                : (speech.end_frame + chains[w + 1].speech.first_frame + 1) / 2);
        // Nor across a steady tone (a beep just before the speech is no syllable's).
        for (const FrameSpan& tone : loudness.tones) {
            if (tone.end_frame <= speech.first_frame) lower = std::max(lower, tone.end_frame);
            if (tone.first_frame >= speech.end_frame) upper = std::min(upper, tone.first_frame);
        }
        for (const FrameSpan& breath : loudness.unvoiced_edges) {
            if (breath.end_frame <= speech.first_frame) lower = std::max(lower, breath.end_frame);
            if (breath.first_frame >= speech.end_frame) upper = std::min(upper, breath.first_frame);
        }
        chain.searched.first_frame = std::max(lower, speech.first_frame > kEdgeFrames ? speech.first_frame - kEdgeFrames : 0);
        // A sentence that ends in a room's tail, or quietly, is searched only a little past the voice's
        // end, and its vowels are scaled to the voiced part: the tail is not speech to spread them
        // over, and a path given the quiet end to place slides the sentence's syllables into it
        // (bench/README.md Session 37 (phoneend): right sentences refused).
        const std::size_t voiced_end = speech.end_frame - chain.tail_frames;
        chain.searched.end_frame =
            std::min(upper, voiced_end < speech.end_frame ? voiced_end + kTailEdgeFrames : speech.end_frame + kEdgeFrames);
        const bool by_voicing = !std::isfinite(noise.reach_db) && noise.voiced_crossings > 0.0f;
        chain.quiet_end =
            voiced_end < speech.end_frame || by_voicing
                ? quiet_end(track, voiced_end, std::min(upper, speech.end_frame + kEdgeFrames), noise)
                : 0;
        chain.voiced_past_end = by_voicing && chain.quiet_end > voiced_end &&
                                is_voiced_before(track, speech.first_frame, voiced_end, noise);
        chain.searched_in_room = chain.searched;
        if (chain.ends_in_tail) {
            const std::size_t ringing_first =
                end_before_ringing(track, speech.first_frame, voiced_end, speech.end_frame);
            chain.searched_in_room.end_frame =
                std::min(chain.searched.end_frame, ringing_first + kTailEdgeFrames);
        }
        const std::size_t vowels_first = std::max(speech.first_frame, chain.syllable_bound.first_frame);
        const std::size_t vowels_end =
            std::max(vowels_first, std::min(voiced_end, chain.syllable_bound.end_frame));
        chain.states = build_phone_chain(chain.syllables, chain.searched.length(),
                                         speech_frames(loudness, {vowels_first, vowels_end}));
        // A recording cut to its sound has no silence at its edges for these states to take, but a
        // coder's ramp (measure_loudness): what reads as silence there is its weakest sound.
        if (loudness.is_cut_to_sound && speech.first_frame == 0)
            chain.states.front().max_frames = kCutEdgeFrames;
        if (loudness.is_cut_to_sound && speech.end_frame == track.frame_count)
            chain.states.back().max_frames = kCutEdgeFrames;
        keep_syllables_in_bound(chain);
    }
}

// In a reverberant room the last sound rings on for a few hundred ms after the voice stops, and the
// tail looks like the vowel: it lengthens the sentence the cutter finds (so every vowel is
// stretched to fill it) and the search gives it to the last vowel. Where the voice stops the level
// falls at once far below the vowel's, and the tail only decays from there: speech in [first, end)
// ends after its last frame less than kTailFallDb below the loudest frame of its last
// kTailReferenceFrames, unless what lies after it rises again (a quiet syllable, not a tail). In
// noise the floor stays above that mark and nothing moves.
std::size_t end_before_tail(const FeatureTrack& track, std::size_t first, std::size_t end) {
    if (end <= first + 1) return end;
    const std::size_t loudest = loudest_before(track, first, end);
    const float mark_db = track.at(loudest, kEnergyDb) - kTailFallDb;
    std::size_t trimmed = end;
    float later_loudest_db = -std::numeric_limits<float>::infinity();
    while (trimmed > loudest + 1 && track.at(trimmed - 1, kEnergyDb) < mark_db) {
        const float level_db = track.at(trimmed - 1, kEnergyDb);
        // A tail only decays: where the quiet part rises again after a dip, it holds a syllable of
        // its own (a weak last syllable after a stop's closure), and nothing is cut.
        if (level_db < later_loudest_db - kTailRiseDb) return end;
        later_loudest_db = std::max(later_loudest_db, level_db);
        --trimmed;
    }
    return trimmed;
}

std::size_t end_before_ringing(const FeatureTrack& track, std::size_t first, std::size_t mark,
                               std::size_t end) {
    const std::size_t fit_end = std::min(end, mark + kRingingFitFrames);
    if (fit_end < mark + kLeastRingingFitFrames) return mark;
    const LevelLine ringing = fit_level_line(track, kEnergyDb, mark, fit_end);
    if (!(ringing.slope_db_per_frame < 0.0)) return mark;
    auto off_line = [&](std::size_t t) {
        return track.at(t, kEnergyDb) - ringing.at(static_cast<double>(t) - static_cast<double>(mark));
    };
    const std::size_t loudest = loudest_before(track, first, end);
    // Only a voice that stops over the ringing ends where the line says; one whose fade passes under
    // the line drawn back ends somewhere in it, as likely at the mark as anywhere.
    std::size_t dip_frames = 0;
    for (std::size_t ringing_first = mark; ringing_first > loudest + 1; --ringing_first) {
        const double off = off_line(ringing_first - 1);
        if (off > kRingingRippleDb) {
            if (ringing_first < mark) return ringing_first;
            break;
        }
        dip_frames = off < -kRingingRippleDb ? dip_frames + 1 : 0;
        if (dip_frames > kRingingDipFrames) break;
    }
    return ringing_after_fall(track, loudest, mark, fit_end);
}

}  // namespace talkface::detail
