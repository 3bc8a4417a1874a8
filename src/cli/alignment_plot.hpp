// The picture of an alignment (thesis Figures 3.5 and 3.8): the waveform's envelope, sentences in
// two alternating colours, each syllable's start marked and labelled with its pinyin.
#ifndef TALKFACE_CLI_ALIGNMENT_PLOT_HPP
#define TALKFACE_CLI_ALIGNMENT_PLOT_HPP

#include <string>

#include <talkface/timeline.hpp>

namespace talkface_cli {

// An SVG document of `audio_path` (read again, in blocks, for its envelope) and `timeline`.
// \throws talkface::FileError / talkface::ParseError if the audio cannot be read.
std::string alignment_plot_svg(const std::string& audio_path, const talkface::Timeline& timeline);

}  // namespace talkface_cli

#endif
