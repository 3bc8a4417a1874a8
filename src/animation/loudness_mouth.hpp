// The mouth over a stretch where the speech does not say the transcript's text (issue 13): the
// syllables there are the text's, not what is said, so their shapes would mouth the wrong words;
// instead the mouth opens with the audio's loudness (TextMismatch::loudness), closed in silence.
#ifndef TALKFACE_ANIMATION_LOUDNESS_MOUTH_HPP
#define TALKFACE_ANIMATION_LOUDNESS_MOUTH_HPP

#include <vector>

#include "talkface/lip_sync.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// The shape of a loudness in 0..1: louder, more open (m, z, n, a: each wider than the one before,
// all at the neutral mouth's width, so that only the opening changes).
MouthShape loudness_shape(double loudness);

// Key frames over `mismatch`'s stretch, one a frame of `fps` where its shape changes and where a
// run of one shape ends (so that a held opening is held, not slowly interpolated away); each
// names the syllable of the mismatch whose span holds it, or none. Empty without a loudness.
std::vector<MouthKeyFrame> loudness_key_frames(const Timeline& timeline, const TextMismatch& mismatch, double fps);

}  // namespace talkface::detail

#endif
