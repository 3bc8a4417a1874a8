// svg_animator.hpp's opening example, extracted from the header by extract_fragment.cmake, run on
// an animated face.
#include <string>

#include "aligned_hello.hpp"
#include "talkface/svg_animator.hpp"

int main() {
    const auto [face, timeline, animation] = animated_hello();
#include "svg_animator_hpp_example.inc"
    return svg.find("<animate ") == std::string::npos;
}
