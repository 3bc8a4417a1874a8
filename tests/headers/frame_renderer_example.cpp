// frame_renderer.hpp's opening example, extracted from the header by extract_fragment.cmake, run
// on an animated face.
#include <cstdint>
#include <vector>

#include "aligned_hello.hpp"
#include "talkface/frame_renderer.hpp"

int main() {
    const auto [face, timeline, animation] = animated_hello();
#include "frame_renderer_hpp_example.inc"
    return pixels[3] == 0xff ? 0 : 1;
}
