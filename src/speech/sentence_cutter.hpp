// Sentence utterances: where each sentence of the transcript is spoken (thesis 3.2). Three ways:
// Algorithm 3.1 from a pause the caller selects, an automatic one that learns the noise level
// and the pauses from the audio and lets the transcript's sentences choose among them (SPEC
// "Alignment": noise-adjusted loudness per band, a duration prior from each sentence's syllables),
// and spans the caller gives (subtitle cues, issue #15), which the search never leaves.
#ifndef TALKFACE_SPEECH_SENTENCE_CUTTER_HPP
#define TALKFACE_SPEECH_SENTENCE_CUTTER_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "speech/frame_features.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// A pause: shorter quiet runs are stop closures and the gaps of a phrase, never a sentence's end.
constexpr double kMinPauseS = 0.12;
constexpr auto kMinPauseFrames = static_cast<std::size_t>(kMinPauseS / kFrameStepS + 0.5);
// The speech's loud level (LoudnessProfile::speech_level_db): this percentile of its frames' activity.
constexpr double kSpeechPercentile = 0.95;
// Read speech runs at 3-8 syllables per second: at fewer frames a syllable than this (14 a second)
// a stretch cannot hold its text. check_sentence_lengths refuses such a sentence, and the cutter
// never chooses one.
constexpr double kFastestFramesPerSyllable = 7.0;
// Speech the transcript lacks is spoken as loud as the rest: sound this far below a recording's
// speech level is not taken for speech the text lacks (check_path), nor for the start or end of
// its speech (measure_loudness). Music 15-20 dB under the voice rises above the noise floor at each
// note but stays further below (bench/ music15, music20: two in three passages were refused as
// missing a sentence).
constexpr float kUnspokenSpeechBelowDb = 12.0f;

// Frames [first_frame, end_frame) of one sentence utterance.
struct FrameSpan {
    std::size_t first_frame = 0;
    std::size_t end_frame = 0;
    std::size_t length() const { return end_frame - first_frame; }
};

// What the whole recording says about its noise: per-band floors and a speech/pause decision per
// frame. Computed once, shared by the cutter, the aligner and the checks.
struct LoudnessProfile {
    float energy_floor_db = 0.0f;
    float low_floor_db = 0.0f;
    float mid_floor_db = 0.0f;
    float high_floor_db = 0.0f;
    // The same floors over the frames that hold any sound, for the acoustic observations: exact
    // digital zeros (a recording padded with silence, a muted stretch) all read one level, far
    // below any noise, and a floor there puts every sound near the loudest (measure_loudness).
    float energy_sound_floor_db = 0.0f;
    float low_sound_floor_db = 0.0f;
    float high_sound_floor_db = 0.0f;
    float activity_threshold_db = 0.0f;     // a frame is speech when its activity is above this
    float speech_level_db = 0.0f;           // the activity of loud speech: its 95th percentile
    std::vector<float> activity_db;         // per frame: the loudest band above its floor, smoothed
    std::vector<FrameSpan> pauses;          // runs of non-speech, at least kMinPauseS, in order
    std::vector<FrameSpan> tones;           // runs of a steady tone as loud as speech (steady_tone.hpp), in order
    // Sound before the first words or after the last, set apart by a pause, never voiced or with no
    // fundamental, beside a voice that is and has one (a breath, breath_edge.hpp): no syllable's, and
    // no sentence is searched into it; so is a click closer to the first words than a pause, with
    // the quiet after it, and the noise a gain lifted before the first words, in
    // loudness_after_lifted_lead_in's profile. In order.
    std::vector<FrameSpan> unvoiced_edges;
    // Music that plays on under the first words (music_bed.hpp): alone over `music_before_voice`,
    // then under the voice, fading or not, up to the end of `voice_under_music`. Both empty where
    // there is none.
    FrameSpan music_before_voice;
    FrameSpan voice_under_music;
    std::size_t speech_first_frame = 0;     // first and one past the last speech frame
    std::size_t speech_end_frame = 0;
    // No pause anywhere, not even at its edges (a line cut to its sound): its speech runs from its
    // first frame to its last, and its floors are its own weakest sound, not noise.
    bool is_cut_to_sound = false;
};

LoudnessProfile measure_loudness(const FeatureTrack& track);

// The profile with the noise a gain lifted before the first words read as that noise
// (lifted_lead_in.hpp), no sentence searched into it; nothing where `loudness` (measure_loudness's)
// finds a pause before its speech or the recording starts with no such noise. For the syllables'
// placement only: the checks judge a text on `loudness` (judged after the lifted noise, 8 of the
// 10 wrong texts of short_kinds_bench's p-agc tuning lines they catch there passed: bench/README.md,
// session 30).
std::optional<LoudnessProfile> loudness_after_lifted_lead_in(const FeatureTrack& track,
                                                             const LoudnessProfile& loudness);

// Whether frame t of `loudness` is speech (activity at or above its threshold).
inline bool is_speech_frame(const LoudnessProfile& loudness, std::size_t t) {
    return loudness.activity_db[t] >= loudness.activity_threshold_db;
}

// Where the sentences of a transcript are spoken, as far as the pauses tell.
struct SentenceCut {
    std::vector<FrameSpan> spans;  // per sentence of the transcript, in order, its speech only
    // Per sentence: its end has no pause the cutter can be sure of (run_together.hpp), so it is
    // aligned together with the next sentence, which then places the end; its span is a guess.
    std::vector<bool> runs_on;
    // The pauses do not single the sentence ends out (run_together.hpp): a cut that the syllables
    // refuse may be a comma's pause taken for a sentence's end.
    bool is_in_doubt = false;
    // Per sentence: the frames its search may not leave (given spans); empty: no bound.
    std::vector<FrameSpan> limits;
    // Per sentence: the frames its syllables may not leave, while its search and the pauses at its
    // edges do (a line's own voice on a cut that holds noise around it, own_reading_bound.hpp);
    // empty: no bound.
    std::vector<FrameSpan> syllable_bounds;
};

// How many syllables each sentence of `transcript` holds, in the sentences' order (0 for a
// sentence without syllables: a line of punctuation or of words with no reading).
std::vector<std::size_t> syllables_per_sentence(const Timeline& transcript);

// The sentences of `transcript` cut from the audio.
// \throws talkface::AlignmentError when the pauses cannot be matched to the sentences (in
//         first_pause mode, a different number of speaking parts), naming the times.
// \throws talkface::InvalidArgument if the first pause lies outside the audio.
SentenceCut cut_sentences(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                          const AlignOptions& options);

// A sentence's time span as the caller gives it (a subtitle cue's), seconds.
struct GivenSpan {
    double start_s = 0.0;
    double end_s = 0.0;
};

// The sentences of `transcript` where `spans_s` (one per sentence; those of sentences without
// syllables are not read) says they are spoken: each sentence's speech is what is louder than the
// noise inside its span (the whole span where nothing is), its search stays inside the span, and
// neighbours whose spans overlap (one cue for both) are aligned as one chain.
// \throws talkface::InvalidArgument naming the sentence whose span is not 0 <= start < end inside
//         the audio, or if `spans_s` does not hold one span per sentence.
SentenceCut given_sentence_cut(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                               const std::vector<GivenSpan>& spans_s);

}  // namespace talkface::detail

#endif
