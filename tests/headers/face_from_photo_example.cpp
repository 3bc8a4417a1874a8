// face_from_photo.hpp's opening example, extracted from the header by extract_fragment.cmake, run
// where me.jpg stands (Grace Hopper's portrait, matplotlib's sample).
#include <fstream>
#include <iostream>

#include "talkface/face_from_photo.hpp"

int main() {
#include "face_from_photo_hpp_example.inc"
    return std::ifstream("me-points.png") ? 0 : 1;
}
