// Dropouts concealed (issue 13, dropout_finder.hpp): the frames a dropout's zeros take are drawn
// straight from the frame before it to the frame after, as if the sound had gone on, which it did.
// Only inside speech: a run of zeros cut on both sides is also what a synthetic drum leaves
// between its hits (bench/ m-drums: 166 runs in its passages pass the finder's rule, and the
// levels either side tell them from dropouts no better), and filling those in filled the voice's
// pauses; 162 of them lie outside every sentence, in the pauses the loudness profile finds.
#ifndef TALKFACE_SPEECH_DROPOUT_CONCEALMENT_HPP
#define TALKFACE_SPEECH_DROPOUT_CONCEALMENT_HPP

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// A dropout takes the frames whose analysis window holds kTakenShare of its zeros.
constexpr double kTakenShare = 0.25;

// Conceals those of track.dropouts that cut the voice inside the speech measure_loudness finds in
// `track`: after its start and before its end, with speech either side, or on one side a
// syllable's (dropout_concealment.cpp); the others are left as they are. Returns the loudness of
// `track` as it leaves it: measured once, and again only where frames were drawn over, so that the
// aligner need not measure it again (it did for every track with a dropout, and for each pass of
// check mode warn).
LoudnessProfile conceal_dropouts(FeatureTrack& track);

}  // namespace talkface::detail

#endif
