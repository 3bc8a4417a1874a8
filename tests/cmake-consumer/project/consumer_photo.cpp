// Reads a face from a photo given in pixels through the installed talkface::photo: a blank photo has
// no face, and the error says so.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <talkface/errors.hpp>
#include <talkface/face_from_photo.hpp>

int main() {
    const std::vector<std::uint8_t> grey(64 * 64, 128);
    try {
        talkface::face_from_photo(talkface::ImageView{grey.data(), 64, 64, 64, talkface::PixelFormat::gray8});
    } catch (const talkface::InvalidArgument& error) {
        std::printf("C++ photo: %s\n", error.what());
        return std::string(error.what()).find("no face") != std::string::npos ? 0 : 1;
    }
    return 1;
}
