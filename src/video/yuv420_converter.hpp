// The picture an H.264 or VP9 encoder is given, kept from frame to frame: each new RGBA frame is
// compared with the last one and only the rectangle that changed is converted (BT.709, limited
// range, 4:2:0, alpha kept for yuva420p). The face moves in a third of the frame and holds still
// in pauses; libswscale converts whole pictures only, and was a quarter of a video's time.
#ifndef TALKFACE_VIDEO_YUV420_CONVERTER_HPP
#define TALKFACE_VIDEO_YUV420_CONVERTER_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/rgba_pixels.hpp"

namespace talkface::detail {

// Planes as FFmpeg's AVFrame holds them: Y, U, V (and A) with their line sizes.
struct Yuv420Planes {
    std::uint8_t* data[4] = {nullptr, nullptr, nullptr, nullptr};
    int linesize[4] = {0, 0, 0, 0};
};

class Yuv420Converter {
public:
    // `width` and `height` even (4:2:0); `with_alpha`: the planes have an A plane (yuva420p).
    Yuv420Converter(int width, int height, bool with_alpha);

    // Converts what changed between the last frame and `rgba` (straight alpha, rows `stride_bytes`
    // apart) into `planes`, which must hold the last frame's conversion (all of the first frame is
    // converted). Returns the rectangle converted, on even coordinates; empty if nothing changed.
    PixelBox convert(const std::uint8_t* rgba, std::size_t stride_bytes, const Yuv420Planes& planes);

private:
    PixelBox find_change(const std::uint8_t* rgba, std::size_t stride_bytes) const;

    int width_;
    int height_;
    bool with_alpha_;
    bool has_last_ = false;
    std::vector<std::uint8_t> last_;  // the last frame, rows packed
};

}  // namespace talkface::detail

#endif
