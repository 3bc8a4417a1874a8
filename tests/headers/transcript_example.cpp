// transcript.hpp's opening example, extracted from the header by extract_fragment.cmake, run.
#include <iostream>

#include "talkface/transcript.hpp"

int main() {
#include "transcript_hpp_example.inc"
}
