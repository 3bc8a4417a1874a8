// A chain's best path turned into what the caller gets: each syllable's start (SPEC "Alignment":
// where its initial starts, a stop's closure after speech), its vowel's start, its end and its
// confidence; and the path's stretches and spans as the checks read them.
#ifndef TALKFACE_SPEECH_SYLLABLE_PLACEMENT_HPP
#define TALKFACE_SPEECH_SYLLABLE_PLACEMENT_HPP

#include <optional>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/alignment_confidence.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Writes the syllables of one aligned chain (the `chain_index`th) into `result` (times in seconds
// of the recording), and the evidence of their places into `evidence` (per syllable of the
// transcript), from which set_confidences gives their confidences once every chain is placed;
// `other_frames` (per other search of the same chain's syllables on the same frames, frames_on_path;
// may be none) weigh in by where they start each syllable (syllable_steadiness).
void place_syllables(const SentenceChain& chain, std::size_t chain_index, const std::vector<StateSegment>& path,
                     const std::vector<std::vector<SyllableFrames>>& other_frames, const EmissionScores& scores,
                     const FeatureTrack& track, Timeline& result, std::vector<SyllableEvidence>& evidence);

// A chain's last syllable whose voice the voicing reads across end_before_tail's mark on to its
// quiet end (chain.voiced_past_end), where the path ends it before the quiet end, so that
// place_syllables ends it on the path: where the cutter's span ends inside the voiced tail of a
// vowel in a coder's comfort noise, the path gives the tail to the pause (p-opus6's 著急, 爬山,
// bench/README.md Session 40 (opusend)). Its transcript index and the quiet end's time.
struct VoicedEnd {
    std::size_t syllable = 0;
    double end_s = 0.0;
};
std::optional<VoicedEnd> voiced_end_past_path(const SentenceChain& chain, const FeatureTrack& track,
                                              const Timeline& result);

// Where a voiced join starts (a syllable whose initial is m n l r or none, its first state
// `first` right after the vowel or nasal `before` of the syllable before, no pause between). The
// path puts the boundary where the two sounds fit alike, the middle of the transition, while the
// syllable starts (SPEC "Alignment") where the sound begins to turn towards it, when the mouth
// begins to move. Per frame, the rise is how much better `first_class` fits than `before_class`;
// it lies near one level (its median) over `before` and near another over `first`. Walking back
// from the path's boundary, the transition goes on while the rise is above the level before by a
// quarter of the step between the two; the join starts at the first frame that is not. Where `first_class` fits `first` no better than it fits
// `before` (two sounds alike), the path's boundary.
std::size_t voiced_join_start(const StateSegment& before, PhoneClass before_class, const StateSegment& first,
                              PhoneClass first_class, const EmissionScores& scores);

// Where a voiced join after an apical vowel (the rime of zi ci si zhi chi shi ri, its state `vowel_first`
// on) starts, the path having started it at `start`. The apical class, learned on the recording
// from a few syllables, fits the next syllable's i, ɛ and n about as well as their own classes do
// (是一, 十年), so the path may run the vowel on over them and start the next syllable a whole
// vowel late (100-250 ms). The rime is one steady vowel: past its onset its spectrum holds until it
// turns into the next sound. Where the spectrum holds at the path's start (the landmarks' bonus,
// spectral_landmarks.hpp, stays under kTurnRise within a frame of it), the syllable starts where
// the last turn between the vowel's onset and `start` begins to rise (the bonus rising kTurnRise or
// more from its trough); where the path's start is at a turn, or no turn lies before it, `start`:
// never later.
std::size_t apical_vowel_turn(const EmissionScores& scores, std::size_t vowel_first, std::size_t start);

// Where a syllable with no initial (y-, w-, a vowel) joined to the voiced sound before it starts:
// such a syllable has no sound of its own to begin with, only a turn of the vowel or nasal before
// towards its own, and the path puts its boundary late in that turn (in the middle of it, or, where
// the two vowels are alike, as i to yi, where the durations put it), while SPEC "Alignment" starts
// the syllable where the turn starts. Between two syllables' nuclei the level falls to a valley
// (the syllable boundary a phonetician takes between two voiced sounds, and where a join's
// cross-fade begins). `start` is where the syllable starts so far, `lowest` the first frame it may
// move to (after the syllable before's vowel begins), both counted from frame `offset` of `track`.
// Returns the lowest-level frame within kValleySearchFrames before `start` (or `start` itself)
// where it is a valley at least kValleyDepthDb deep (the last frame of its floor, where the level
// begins to rise); where there is none, the same within kFarValleySearchFrames and after the
// loudest frame from `lowest` to the foot of the level's rise into `start` (the syllable before's
// nucleus: the syllable's own onset, rising there, may be louder) where it is kFarValleyDepthDb
// deep (after a short syllable the path starts the next one late by more than a turn's width);
// else `start`: never later.
std::size_t syllable_valley_start(const FeatureTrack& track, std::size_t offset, std::size_t lowest, std::size_t start);

// The level the noise's own `column` reaches (the high band, 2.5-8 kHz, frication's; the whole
// band): steady_noise_reach (noise_reach.hpp) of its levels over the frames of `path`'s pauses (edge
// silences and pauses between syllables of `chain`).
float pause_noise_reach(const FeatureTrack& track, const SentenceChain& chain,
                        const std::vector<StateSegment>& path, FeatureColumn column);

// Where a sibilant (s sh x) right after the sound before starts, the path having started it at
// `first` (its state's frames [first, end), counted from frame `offset` of `track`). A sibilant is
// heard as frication in the high band. In noise its weak onset, and the tail of the sound before
// as it decays, sound like the noise alone; the path may not put a pause that short before a
// fricative (a weak fricative's start would go to it: phone_chain.cpp) and gives those frames to
// the sibilant, which then starts 50-100 ms early where a vowel's tail decays under the noise
// (bench/ Session 22). Where the high band on the path's first frames stays within
// `noise_reach_db` (pause_noise_reach of the high band), the frication is first heard where the high band
// rises above it and stays there (kHeardFrames running: the noise alone passes its reach on one frame in ten,
// bench/ Session 23); which of the frames heard as noise before it were the sound before's and which the
// sibilant's the recording does not tell, so the sibilant starts halfway between, off by at most half that
// stretch either way. Never earlier than `first`; where no such run starts before `end`, `first`. Not f or h:
// their frication is weak and low for the high band, which in noise they seldom lift above its reach before
// their vowel (bench/ Session 22: moved late).
std::size_t sibilant_onset(const FeatureTrack& track, std::size_t offset, std::size_t first, std::size_t end,
                           float noise_reach_db);

// Where the closure of a stop or affricate right after the sound before (z zh j c ch q b d g p t k
// after speech, SPEC) starts, the path having started it at `first` and its burst at `burst`
// (frames counted from frame `offset` of `track`). The closure's silence class is learned on the
// recording's pauses, noise and all, and in noise (15-20 dB) the vowel's decaying tail, a few dB
// over the noise, fits it as well: the path starts the closure where the vowel falls towards the
// noise, 50-150 ms before its sound ends (bench/ Session 23, the early closures). The vowel is
// still heard while the whole band's level is over `noise_reach_db` (pause_noise_reach of the whole
// band, the level the noise alone passes one frame in ten): the closure starts at the first frame at
// or under it. Where none lies before `burst` (a voiced closure; a noise too unsteady to have a
// reach), or where the pauses are digital silence (an editor's: the silence class fits the closure
// from its first silent frame), `first`. Never earlier than `first`.
std::size_t closure_after_tail(const FeatureTrack& track, std::size_t offset, std::size_t first,
                               std::size_t burst, float noise_reach_db);

// Where a syllable after a pause (a sentence's first, or a phrase's after a comma) starts, its
// initial `initial` held by `segment` on the path (frames counted from frame `offset` of `track`).
// The silence class is learned on the recording's pauses and closures, and the sound just before a
// sentence may fit the initial's class better: a room's tail of the sentence before (a nasal), a
// note (a liquid), a drum (a sibilant). The path then gives the initial that sound too, up to its
// longest, and the sentence starts 150-200 ms early (bench/ espeak-ng reverb, music20, song15).
// Where the initial holds more frames than its duration prior's median times
// exp(kOverlongInitialSpreads spreads), the syllable starts at the last frame of the level's lowest
// stretch within them (within kValleyFloorDb of its lowest frame), where the sound rises into the
// initial: the sound before decays or holds there. Where the lowest frame is the first (a sound
// held from its onset on), or the initial is no longer than that, the path's start. place_syllables
// asks it only of an initial that sounds from its first frame on, not of a burst's (b d g p t k,
// and after a pause z zh j c ch q, whose frication after the burst may start weaker: a wrong text's
// 这 started in the dip after its burst, 80 ms late, and a missing sentence went unnoticed).
std::size_t onset_after_pause(const FeatureTrack& track, std::size_t offset, const PhoneState& initial,
                              const StateSegment& segment);

// The path's syllables and pauses, in frames of the whole recording.
std::vector<AlignedStretch> stretches_of(const SentenceChain& chain, const std::vector<StateSegment>& path);

// Frames from the first syllable's start to the last one's end of sentence `k` of `chain` as
// aligned in `result`.
FrameSpan aligned_span(const Timeline& result, const SentenceChain& chain, std::size_t k);

// Each syllable of `chain`'s start sureness and far start share on `path` (alignment_confidence.hpp),
// from the path search's `marginals`, into its `evidence`.
void set_start_evidence(const SentenceChain& chain, const std::vector<StateSegment>& path,
                        const EntryMaxMarginals& marginals, std::vector<SyllableEvidence>& evidence);

}  // namespace talkface::detail

#endif
