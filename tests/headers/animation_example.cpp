// animation.hpp's opening example, extracted from the header by extract_fragment.cmake, run on the
// aligned timeline it starts from: 你好。 with its syllables' times set as an aligner sets them.
#include <cstddef>
#include <string>

#include "talkface/animation.hpp"
#include "talkface/transcript.hpp"

int main() {
    talkface::Timeline timeline = talkface::read_transcript("你好。");
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        timeline.syllables[k].start_s = 0.5 + 0.25 * static_cast<double>(k);
        timeline.syllables[k].end_s = timeline.syllables[k].start_s + 0.25;
    }
    timeline.sentences.front().start_s = 0.5;
    timeline.sentences.front().end_s = timeline.syllables.back().end_s;
    timeline.duration_s = 1.5;
#include "animation_hpp_example.inc"
    return json.find("\"mouth\"") == std::string::npos;
}
