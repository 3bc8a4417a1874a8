// A still picture read through FFmpeg's decoders (PNG, JPEG, WebP, BMP, GIF, TIFF, SVG through
// librsvg ...) as straight-alpha RGBA: the background image of a video.
#ifndef TALKFACE_VIDEO_IMAGE_DECODER_HPP
#define TALKFACE_VIDEO_IMAGE_DECODER_HPP

#include <cstdint>
#include <string>
#include <vector>

namespace talkface::detail {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // rows of width * 4 bytes, R, G, B, A
};

// The first frame of the image at `path`. At most 100 megapixels, as photos are.
// \throws talkface::FileError naming the path if it cannot be opened, is not a picture FFmpeg
//         reads, or is larger.
RgbaImage decode_image_file(const std::string& path);

}  // namespace talkface::detail

#endif
