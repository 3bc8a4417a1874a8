// animation.hpp's opening example, extracted from the header by extract_fragment.cmake, run on the
// aligned timeline it starts from.
#include <string>

#include "aligned_hello.hpp"

int main() {
    const talkface::Timeline timeline = aligned_hello();
#include "animation_hpp_example.inc"
    return json.find("\"mouth\"") == std::string::npos;
}
