// The final pass's measures of a chain (SPEC "Alignment"): its syllables placed, and what the
// checks of alignment_checks.hpp judge of each of its sentences measured on its path.
#ifndef TALKFACE_SPEECH_CHAIN_MEASURES_HPP
#define TALKFACE_SPEECH_CHAIN_MEASURES_HPP

#include <cstddef>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/alignment_confidence.hpp"
#include "speech/alignment_passes.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Files of at most this many sentences get the leave-one-out check (held_out_fit_gaps).
inline constexpr std::size_t kMaxHeldOutCheckSentences = 2;

// How far the text fits of a recording of `spoken_sentences` forgive a stop's closure spoken
// through (text_fit_gap), as far as the recording's own closures are spoken through
// (learned.closure_run_on, the typical closure frame's run-on). At a fast pace a stop after a vowel
// is said with no silence before its burst, and the frame or two the path must give its closure
// sound like the vowel run on: scored as silence, each cost a right text 5-15 per frame (bench/
// espeak-ng fast, dev26's dialogue), and a line of six to nine syllables with three or four stops
// after speech (我就带了2块钱, 12点整开抢！) gapped 0.19-0.40 in its passage and was refused. Where
// the typical closure is spoken through (a run-on above 0: most closure frames sound more like the
// sound before them than silence) the speaker does not close, and every closure is forgiven
// wholly: forgiven only up to the typical run-on, a dense line's closures, which run on further,
// still refused 8 of the 12 such passages (bench/README.md, session 32 (dialog2)). In a room
// (`in_room`) the ringing, not the speaker, runs every closure on by about the room's own amount,
// the typical run-on, and only that is forgiven: a wrong text's closure forced onto a vowel runs on
// further (wholly forgiven there, the person's wrong passages in h-reverb were caught 43 -> 38).
// A speaker who keeps most closures silent (gcin-voice's speaker 3) has a typical run-on of 0 and
// keeps every closure's evidence. In a file of one or two sentences the models are learned from
// the sentence's own path and fit a wrong text's sounds as well as a right one's, all but the
// silence learned from the pauses around it: a closure where the speech has none is the evidence
// left (espeak-ng's 好啊 with the text 請進, tests/data/speech: a gap of 0.28, nearly all of it 進's
// closure after 請's ng), and its paths are too few to tell how the speaker speaks. There it stays
// silent.
double forgiven_closure_run_on(const Reestimation& learned, std::size_t spoken_sentences, bool in_room);

// Whether a chain's sentences are judged by their order margin and held-out halves
// (check_held_out_fit) as well as by their text fit: in a file of one or two sentences, where the
// models re-estimated on the recording fit any text, but not where the chain ends in a room's tail
// (there a right text's halves gap as a wrong one's do, bench/ reverb); and on the models a music
// bed's recording learns from its sentences clear of the bed alone (`is_on_bed_free_models`,
// bed_free_models.hpp, outside a room). Those are three or four sentences of a passage, and a
// wrong text among them shapes them as it shapes a file of one or two's: a replaced sentence fits
// them -0.13-0.26 per frame worse than free sounds (median 0.08, 12 of 49 over kMaxTextFitGap),
// where its typical syllable on held-out models gaps more than its order margin in 39 of the 49
// and a right sentence's in 1 of 206 (bench/README.md, session 36 (bed3): a person's, a voice's
// and espeak-ng's passages under a bed).
bool is_judged_by_order_margin(const SentenceChain& chain, std::size_t spoken_sentences,
                               bool is_on_bed_free_models);

// What the final pass measures a chain on: the chain (the `chain_index`th), its path on the
// re-estimated models and its observations, where other searches of it place its syllables (they
// weigh in on their confidences), the re-estimation, the recording's count of spoken sentences and
// how far a closure spoken through is forgiven (forgiven_closure_run_on), the recording's features,
// its loudness and the transcript, whether its path is checked (check_path), whether it is
// judged on the models learned from the sentences clear of a music bed (bed_free_models.hpp),
// outside a room, and whether the recording is placed as a room's.
struct ChainMeasureInputs {
    const SentenceChain& chain;
    std::size_t chain_index;
    const std::vector<StateSegment>& path;
    const std::vector<float>& observations;
    const std::vector<std::vector<SyllableFrames>>& other_frames;
    const Reestimation& learned;
    std::size_t spoken_sentences;
    double forgiven_run_on;
    const FeatureTrack& track;
    const LoudnessProfile& loudness;
    const Timeline& transcript;
    bool is_checked;
    bool is_on_bed_free_models;
    bool is_in_room;
};

// The final pass over one chain, on the re-estimated models, whose scores of it `scores` holds: its
// syllables placed in `result` and their evidence in `evidence`, what the checks judge of each of its
// sentences measured into `metrics` (a block's sentences' spans into `spans`), and its path checked
// when the inputs ask. `scores` is left holding held-out models' scores; `workspace` is scratch.
void measure_chain(const ChainMeasureInputs& in, EmissionScores& scores, ViterbiWorkspace& workspace,
                   Timeline& result, std::vector<SyllableEvidence>& evidence, std::vector<FrameSpan>& spans,
                   std::vector<SentenceMetrics>& metrics);

}  // namespace talkface::detail

#endif
