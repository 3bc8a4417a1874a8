// alignment_plot.hpp's opening example, extracted from the header by extract_fragment.cmake, run
// where speech.wav and speech.txt stand (tests/data/speech/two_sentences).
#include <fstream>

#include "talkface/alignment_plot.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

int main() {
    const talkface::SpeechAligner aligner;
    const talkface::Timeline transcript = talkface::load_transcript("speech.txt");
#include "alignment_plot_hpp_example.inc"
    return std::ifstream("speech.svg") ? 0 : 1;
}
