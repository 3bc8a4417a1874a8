// web_page.hpp's opening example, extracted from the header by extract_fragment.cmake, run on an
// animated face where speech.wav stands.
#include <fstream>

#include "aligned_hello.hpp"
#include "talkface/web_page.hpp"

int main() {
    const auto [face, timeline, animation] = animated_hello();
#include "web_page_hpp_example.inc"
    return std::ifstream("book.html") ? 0 : 1;
}
