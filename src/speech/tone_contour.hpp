// A syllable's tone heard in its pitch (lenient alignment, issue 13). The broad phone classes hear
// 场大 chang3 da4 and 沙发 sha1 fa1 alike, and a text with one in place of the other fits nearly as
// well as the right one; their tones differ. Each syllable's pitch shape over its final is set
// against the shapes the recording's other syllables give each tone, as the speaker says them.
#ifndef TALKFACE_SPEECH_TONE_CONTOUR_HPP
#define TALKFACE_SPEECH_TONE_CONTOUR_HPP

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "speech/frame_features.hpp"

namespace talkface::detail {

// A final's pitch: the median of the voiced frames of its first, middle and last third, in
// semitones from the recording's median pitch.
struct ToneShape {
    std::array<double, 3> semitones{};
    bool is_measured = false;  // with too few voiced frames: not
};

// The median pitch (Hz) of the voiced frames among `frames` (track frames); 0 if none.
double median_voiced_hz(const FeatureTrack& track, const std::vector<std::size_t>& frames);

// The shape of frames [first, end) of `track` against `reference_hz` (median_voiced_hz).
ToneShape tone_shape(const FeatureTrack& track, std::size_t first, std::size_t end, double reference_hz);

// Per syllable (`pinyin`, in order; `sentences`: the sentence of each), how much better, in
// log-likelihood, a tone it cannot have fits its shape than the best tone it can, on Gaussians of
// each tone's shapes learned from the other syllables (a variance shared by the tones): above 0,
// the pitch says another syllable. NaN: not judged (a light tone, too few voiced frames, too few
// syllables of a tone to learn it from).
std::vector<double> tone_gaps(const std::vector<ToneShape>& shapes, const std::vector<std::string>& pinyin,
                              const std::vector<std::size_t>& sentences);

}  // namespace talkface::detail

#endif
