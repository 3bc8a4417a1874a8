// talkface: the picture of an alignment, as thesis Figures 3.5 and 3.8 draw it: the waveform,
// the sentences in two alternating colours, each syllable's start marked and labelled.
//
//   const talkface::Timeline timeline = aligner.align_file("speech.wav", transcript);
//   talkface::write_alignment_plot_svg("speech.svg", "speech.wav", timeline);
//
// Lets a user see at a glance whether the aligner put each sentence and syllable where the voice
// is, before animating a face with it.
#ifndef TALKFACE_ALIGNMENT_PLOT_HPP
#define TALKFACE_ALIGNMENT_PLOT_HPP

#include <string>

#include "talkface/export.h"
#include "talkface/speech_aligner.hpp"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// A standalone SVG document of the audio's envelope (read in blocks, channels mixed down) and
/// `timeline`: 200 px per second of timeline.duration_s (600 to 20000 px wide), each sentence's
/// band tinted and titled with its text, a solid line at each syllable's start, a dotted one where
/// its final starts, its text and pinyin above, and a second scale below. A syllable whose
/// confidence is below kLowAlignmentConfidence is drawn in red over a red band titled with its
/// confidence: the places to check. Text is escaped.
/// \throws talkface::FileError / talkface::ParseError naming the file if it cannot be read as
///         audio, talkface::InvalidArgument if it has no frames.
TALKFACE_API std::string alignment_plot_svg(const std::string& audio_path, const Timeline& timeline);

/// The same for samples in memory (AudioView as SpeechAligner::align_samples takes them).
/// \throws talkface::InvalidArgument naming the malformed field of `audio`.
TALKFACE_API std::string alignment_plot_svg(const AudioView& audio, const Timeline& timeline);

/// Writes alignment_plot_svg(audio_path, timeline) to `svg_path` through a temporary file that is
/// renamed: a failure leaves no file behind.
/// \throws as alignment_plot_svg(), or talkface::FileError naming `svg_path`.
TALKFACE_API void write_alignment_plot_svg(const std::string& svg_path, const std::string& audio_path,
                                           const Timeline& timeline);

}  // namespace v0
}  // namespace talkface

#endif
