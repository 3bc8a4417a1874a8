// A cut's alignment (SPEC "Alignment"): its sentences aligned (chain_alignment.hpp), again where the
// text's pauses or a stop after a nasal ask for it, and judged by the checks (alignment_checks.hpp).
#ifndef TALKFACE_SPEECH_CUT_ALIGNMENT_HPP
#define TALKFACE_SPEECH_CUT_ALIGNMENT_HPP

#include <optional>
#include <vector>

#include "speech/alignment_progress.hpp"
#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// An alignment's syllables as the checks read them, on the silent closures' paths (`checked`), and,
// in a room, as they are given out, placed with the closures ringing (`in_room`, room_closures.hpp):
// the room's paths fit a wrong text as well as the right one, so that the confirmation of a cut
// (align_confirmed) and the block retry (align_track) read only the silent closures' placement.
// `is_vouched_by_order`: checked, and the sentences' order margins vouch for the text
// (is_vouched_by_order, alignment_checks.hpp).
struct AlignedTimelines {
    Timeline checked;
    std::optional<Timeline> in_room;
    bool is_vouched_by_order = false;
};

// The syllables of every sentence of `cut` (align_chains), and, when `is_checked`, the checks
// that audio and transcript belong together.
//
// A second pass keeps the text's pauses where it marks them: a sentence that slides a syllable or
// a phrase on gives the audio's pauses to the wrong places, a comma's to the pause between two
// sentences and that one to a pause inside a word (bench/ Session 12: 牛奶，吃 and 開車 of one
// passage, each placement scoring nearly alike, and re-estimation keeping the first pass's). Where
// an alignment gives a pause the text does not mark more than kMaxUnmarkedPauseFrames, it is made
// again with such pauses kept short, and whichever fits the audio better is kept (their sentences'
// text fit gaps): a speaker who did stop where the text marks nothing keeps that pause. Where the
// kept one wins in a room, check_missing_text reads the first one's placements too
// (placed_missing_text.hpp).
//
// A third pass lets a stop after a nasal release from the nasal's closure: a sentence whose text
// fits so poorly that check_text_fit would refuse it may be a right one whose path slipped a
// syllable where the speaker made no silence before a stop (天都, n + d: the tongue already closed
// for the n), and kept every later syllable on its successor's closure (bench/ Session 14; every
// such refusal of a person's right text since session 11). It is aligned again with the closure
// after a nasal skippable in every chain (the models learned on those paths too), and the new
// alignment kept if the poorly fitting sentences then fit their texts as well as free sounds do
// and, in a file of one or two sentences (whose models its own path shaped), within a right text's
// gap on models learned from the rest of the recording (fits_as_well_as_free_sounds,
// alignment_checks.hpp). Skippable everywhere and always, such closures lost held-out passages
// that are one slip from another place (sessions 11-13); here only an alignment the check would
// refuse is made again, and no other passage of any corpus moves.
//
// `heard` is the recording as heard, where `track` is what the syllables are placed and judged on:
// under a music bed (bed_removal.hpp) the two differ, and the voiced peaks the length checks count
// (count_nuclei) are read on `heard`, as they are on every other recording: the bed taken out by
// the least each band holds nearby leaves the low band peakier than any voice's (bench/README.md,
// sessions 33 and 34).
AlignedTimelines align_cut(const FeatureTrack& track, const FeatureTrack& heard,
                           const LoudnessProfile& loudness, const Timeline& transcript,
                           const SentenceCut& cut, ProgressReporter& progress, bool is_checked,
                           bool is_lenient);

// align_cut, where a sentence end that ran on keeps its chain only if the chain's syllables move
// it out of the pause the cutter chose and put that pause where the text has one (a comma's): a
// sentence end they leave in its pause confirms the cut, and one they move off a pause the text
// does not account for is a wrong text's doing. Then the sentences are aligned apart again, as
// the checks know them best.
AlignedTimelines align_confirmed(const FeatureTrack& track, const FeatureTrack& heard,
                                 const LoudnessProfile& loudness, const Timeline& transcript,
                                 const SentenceCut& cut, const std::vector<bool>& is_spoken,
                                 ProgressReporter& progress, bool is_checked, bool is_lenient);

}  // namespace talkface::detail

#endif
