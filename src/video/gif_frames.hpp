// An animated GIF's frames mapped to one palette (FFmpeg's palettegen and paletteuse filters). One
// palette lets the GIF encoder write each frame as the rectangle that changed, with unchanged
// pixels transparent: a GIF a third the size of one with a palette per frame (measured on the
// demo, bench/README.md "Video").
//
// The palette is made from the first frames, up to kSampleBytes of them kept (as their difference
// from the frame before, deflated: a talking face changes in a small part of the picture), or from
// all of a GIF shorter than that; the frames after it are mapped as they come. So memory is bounded
// whatever the GIF's length: a whole GIF held until its end took 156 MB for 13 s at 720p and grew
// with every second (1.3 MB a second more).
#ifndef TALKFACE_VIDEO_GIF_FRAMES_HPP
#define TALKFACE_VIDEO_GIF_FRAMES_HPP

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

extern "C" {
#include <libavutil/frame.h>
}

#include "video/ffmpeg_support.hpp"

struct AVFilterGraph;
struct AVFilterContext;

namespace talkface::detail {

struct AvFilterCalls;  // gif_frames.cpp

class GifFrames {
public:
    using FrameSink = std::function<void(AVFrame* frame)>;

    // `transparent`: pixels with alpha under half become GIF's transparent colour; otherwise alpha
    // is ignored.
    // \throws talkface::InvalidArgument naming `parameter` (the output file) if libavfilter, opened
    //         here and not linked (gif_frames.cpp says why), cannot be loaded.
    GifFrames(int width, int height, bool transparent, const std::string& parameter);
    ~GifFrames();
    GifFrames(const GifFrames&) = delete;
    GifFrames& operator=(const GifFrames&) = delete;

    // Takes the next RGBA frame (straight alpha, rows `stride_bytes` apart): kept and its colours
    // counted while the palette is being made, else mapped. Mapped frames (AV_PIX_FMT_PAL8, the
    // palette in data[1], pts the frame's index) go to `each`, in order.
    void add(const std::uint8_t* rgba, std::size_t stride_bytes, const FrameSink& each);
    // Maps what is left (making the palette first if no frame has made it) to `each`.
    void finish(const FrameSink& each);

private:
    struct Graph;
    void keep(const std::uint8_t* rgba, std::size_t stride_bytes);
    // Makes the palette from the frames kept, then maps them and lets them go.
    void start_mapping(const FrameSink& each);
    void map(const std::uint8_t* rgba, std::size_t stride_bytes, const FrameSink& each);

    int width_;
    int height_;
    bool transparent_;
    const AvFilterCalls* avfilter_;  // libavfilter's calls (gif_frames.cpp), loaded for the process
    std::unique_ptr<Graph> palette_graph_;  // until the palette is made
    std::unique_ptr<Graph> mapping_graph_;  // from then on
    FramePtr mapped_;
    std::int64_t next_pts_ = 0;
    std::vector<std::uint8_t> last_;  // the last frame kept, rows packed
    std::vector<std::vector<std::uint8_t>> kept_;  // each frame minus the one before, deflated
    std::size_t kept_bytes_ = 0;
    std::vector<std::uint8_t> difference_;  // scratch for keep(): one frame's difference and
    std::vector<std::uint8_t> deflating_;   // its deflated bytes, reused frame after frame
};

}  // namespace talkface::detail

#endif
