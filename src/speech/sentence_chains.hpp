// What the aligner searches: the transcript's sentences grouped into chains (one sentence, or
// neighbours the speaker ran together, run_together.hpp), each with the stretch of audio it is
// searched over and its chain of phone states (SPEC "Alignment").
#ifndef TALKFACE_SPEECH_SENTENCE_CHAINS_HPP
#define TALKFACE_SPEECH_SENTENCE_CHAINS_HPP

#include <cstddef>
#include <limits>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/phone_chain.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// One sentence, or neighbouring sentences the speaker ran together, aligned as one chain.
struct SentenceChain {
    std::size_t first_sentence = 0;  // the transcript's sentences [first_sentence, end_sentence)
    std::size_t end_sentence = 0;
    FrameSpan speech;   // from the cutter
    FrameSpan searched; // with the edges
    FrameSpan limit;    // what the search may not leave: its sentences' SentenceCut::limits, or the audio
    // What its syllables may not leave (SentenceCut::syllable_bounds), or the audio: the edge pauses
    // hold the rest of `searched`.
    FrameSpan syllable_bound{0, std::numeric_limits<std::size_t>::max()};
    std::vector<const Syllable*> syllables;
    std::vector<std::size_t> syllable_indices;
    std::vector<PhoneState> states;
    std::size_t tail_frames = 0;  // how far end_before_tail moved its end (a room's tail, a fade)
    bool ends_in_tail = false;    // its last sound rings on in a room (end_before_tail cut a tail off)
    // The recording is a room (is_room): the last syllable ends before the tail (end_before_tail).
    bool ends_before_tail = true;
    // Where its voice has stopped, outside a room: where its quiet end past end_before_tail's mark
    // falls into the recording's noise, which the search may not reach; 0 in a room, where the noise
    // is too unsteady for its level to tell and its voicing does not tell either, or where the
    // sentence has no quiet end. Where only the voicing tells (a coder's comfort noise), read from the
    // voice's end whether end_before_tail moved it or not: where the cutter's span ends in a voiced tail.
    std::size_t quiet_end = 0;
    // Only the voicing tells, and it reads the voice across end_before_tail's mark on to quiet_end:
    // the last syllable runs on to it even where the path ends it before the mark (a tail in the
    // comfort noise the path gave to the pause; voiced_end_past_path).
    bool voiced_past_end = false;
    // Where the syllables given out in a room are searched (room_placement.hpp): `searched`, ending
    // a little past where the voice stopped before the ringing (end_before_ringing) where it ends in a
    // tail. The models learn on `searched`, whose tail teaches the pause what the room leaves.
    FrameSpan searched_in_room;

    bool is_block() const { return end_sentence > first_sentence + 1; }
};

// The transcript's spoken sentences (those with syllables) grouped into chains: a sentence whose
// end runs on (`cut.runs_on`) is chained to the next. Each chain's speech spans its sentences'
// `spans`, its limit their `cut.limits` (none: every frame); searched spans and states are left to
// set_search_spans.
std::vector<SentenceChain> group_chains(const Timeline& transcript, const SentenceCut& cut,
                                        const std::vector<FrameSpan>& spans);

// Each chain's searched span (its speech with the pauses around it, at most halfway to its
// neighbours, only a little of a room's tail or a quiet end, never past its limit) and its phone states,
// vowels scaled to the speech they fill; whether their last syllables end before the tail (the recording is
// a room, is_room), and where a quiet end falls into the noise outside a room.
// \throws talkface::InvalidArgument naming a syllable whose pinyin is not Mandarin.
void set_search_spans(const FeatureTrack& track, const LoudnessProfile& loudness, std::vector<SentenceChain>& chains);

// SPEC: a sentence ends with its last sound. Where speech in [first, end) ends before a room's
// tail: after its last frame less than a fixed fall below the loudest frame of its end.
std::size_t end_before_tail(const FeatureTrack& track, std::size_t first, std::size_t end);

// Where the voice in [first, end) stopped before a room's tail, `mark` its end_before_tail: past the
// mark the tail surely rings, on a straight line at the room's own decay; followed back from the mark,
// the ringing starts where the level stands over that line drawn back by more than the ringing's
// ripple. The mark where the tail is too short to draw the line, or the level passes under it for
// longer than the ringing's own dips between its reflections.
std::size_t end_before_ringing(const FeatureTrack& track, std::size_t first, std::size_t mark,
                               std::size_t end);

}  // namespace talkface::detail

#endif
