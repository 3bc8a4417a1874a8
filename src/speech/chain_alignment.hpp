// A cut's sentences aligned chain by chain (SPEC "Alignment"): their chains, the models re-estimated
// on them, and the final pass, which places the syllables and measures what the checks judge.
#ifndef TALKFACE_SPEECH_CHAIN_ALIGNMENT_HPP
#define TALKFACE_SPEECH_CHAIN_ALIGNMENT_HPP

#include <optional>
#include <vector>

#include "speech/alignment_checks.hpp"
#include "speech/alignment_progress.hpp"
#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"
#include "speech/syllable_placement.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// One alignment of a cut's sentences, before the checks judge it.
struct CutAlignment {
    Timeline result;
    // In a room (room_closures.hpp), the syllables placed again with the closures ringing, on the
    // features without the room's ringing (late_reverb.hpp): given out in the end, while every
    // check reads `result`, the silent closures' placement on the recorded features (and
    // check_missing_text this one as well, placed_missing_text.hpp).
    std::optional<Timeline> room_result;
    std::vector<FrameSpan> spans;
    std::vector<SentenceMetrics> metrics;
    // A final path gave a pause the text does not mark more than kMaxUnmarkedPauseFrames, in a
    // chain whose text marks pauses (keep_pauses_to_marks).
    bool has_long_unmarked_pause = false;
    // Last syllables the voicing reads on past their path's end (voiced_end_past_path): the checks
    // read `result`'s ends on the path, and align_cut gives these ends out after them. A typical
    // sentence's rate and voiced peaks read with such an end 0.3 s on let a sentence stretched over
    // a missing one pass (bench/README.md Session 41 (phoneend4)).
    std::vector<VoicedEnd> voiced_ends;
};

// The syllables of every sentence of `cut`, aligned sentence by sentence (neighbours that run on,
// together), and, when `is_checked`, check_path on each path; when `is_lenient`, the final pass on
// lenient chains (lenient_chain.hpp). With `is_kept_to_marks`, keep_pauses_to_marks on every chain;
// with `is_nasal_release_allowed`, let_closures_after_nasals_be_skipped on every chain. In a room
// (is_room), each chain is also placed with its closures ringing (let_closures_ring) into
// `room_result`, on the features without the room's ringing (late_reverb.hpp) and models
// re-estimated on them.
CutAlignment align_chains(const FeatureTrack& track, const LoudnessProfile& loudness,
                          const Timeline& transcript, const SentenceCut& cut, ProgressReporter& progress,
                          bool is_checked, bool is_lenient, bool is_kept_to_marks,
                          bool is_nasal_release_allowed);

}  // namespace talkface::detail

#endif
