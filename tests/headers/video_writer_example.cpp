// video_writer.hpp's opening example, extracted from the header by extract_fragment.cmake, run
// where speech.wav stands.
#include <cstdint>
#include <fstream>
#include <vector>

#include "talkface/video_writer.hpp"

int main() {
#include "video_writer_hpp_example.inc"
    return std::ifstream("talk.mp4") ? 0 : 1;
}
