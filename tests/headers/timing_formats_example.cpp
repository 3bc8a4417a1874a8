// timing_formats.hpp's opening example, extracted from the header by extract_fragment.cmake, run
// on an animated face, with the TextGrid it reads back written first (the timeline's own).
#include "aligned_hello.hpp"
#include "talkface/timing_formats.hpp"

int main() {
    const auto [face, timeline, animation] = animated_hello();
    const talkface::Timeline transcript = talkface::read_transcript("你好。");
    const double duration_s = timeline.duration_s;
    talkface::ExportInput aligned;
    aligned.timeline = timeline;
    talkface::export_to_file("mfa.TextGrid", aligned);
#include "timing_formats_hpp_example.inc"
    return mine.syllables.size() == timeline.syllables.size() ? 0 : 1;
}
