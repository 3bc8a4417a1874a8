// An animated GIF's frames, kept until the last one so that one palette, made for all of them,
// serves every frame (FFmpeg's palettegen and paletteuse filters). One palette lets the GIF encoder
// write each frame as the rectangle that changed, with unchanged pixels transparent: a GIF a third
// the size of one with a palette per frame (measured on the demo, bench/README.md "Video"). The
// frames are kept as their difference from the frame before, deflated (zlib): a talking face
// changes in a small part of the picture, so a 720p frame takes kilobytes, not megabytes.
#ifndef TALKFACE_VIDEO_GIF_FRAMES_HPP
#define TALKFACE_VIDEO_GIF_FRAMES_HPP

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

extern "C" {
#include <libavutil/frame.h>
}

struct AVFilterGraph;
struct AVFilterContext;

namespace talkface::detail {

class GifFrames {
public:
    // `transparent`: pixels with alpha under half become GIF's transparent colour; otherwise alpha
    // is ignored.
    GifFrames(int width, int height, bool transparent);
    ~GifFrames();
    GifFrames(const GifFrames&) = delete;
    GifFrames& operator=(const GifFrames&) = delete;

    // Keeps the next RGBA frame (straight alpha, rows `stride_bytes` apart) and counts its colours.
    void add(const std::uint8_t* rgba, std::size_t stride_bytes);
    // Makes the palette, then hands each kept frame, in order, mapped to it (AV_PIX_FMT_PAL8, the
    // palette in data[1], pts its index) to `each`.
    void finish(const std::function<void(AVFrame* frame)>& each);

private:
    struct Graph;
    int width_;
    int height_;
    bool transparent_;
    std::unique_ptr<Graph> palette_graph_;
    std::vector<std::uint8_t> last_;  // the last frame added, rows packed
    std::vector<std::vector<std::uint8_t>> kept_;  // each frame minus the one before, deflated
    std::vector<std::uint8_t> difference_;          // scratch for add(): one frame's difference and
    std::vector<std::uint8_t> deflating_;           // its deflated bytes, reused frame after frame
};

}  // namespace talkface::detail

#endif
