// face_video.hpp's opening example, extracted from the header by extract_fragment.cmake, run on
// an animated face where speech.wav stands.
#include <fstream>

#include "aligned_hello.hpp"
#include "talkface/face_video.hpp"

int main() {
    const auto [face, timeline, animation] = animated_hello();
    const talkface::ProgressCallback progress;
#include "face_video_hpp_example.inc"
    return std::ifstream("talk.mp4") ? 0 : 1;
}
