#include "video/gif_frames.hpp"

#include <algorithm>
#include <cstring>
#include <new>
#include <string>
#include <type_traits>

#include <dlfcn.h>
#include <zlib.h>

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/macros.h>
#include <libavutil/pixfmt.h>
}

#include "talkface/errors.hpp"
#include "video/ffmpeg_support.hpp"

namespace talkface::detail {

namespace {

// palettegen counts the colours of what changed from the frame before (the first frame whole):
// the moving mouth and eyes get their colours although the still background covers most pixels.
// One entry is kept for the transparent colour, which the GIF encoder also uses for the pixels
// that did not change. paletteuse maps without dithering: the face's colours are flat and its
// edges antialiased, which 255 colours hold, and dither noise would differ from frame to frame
// where nothing moved.
constexpr const char* kPaletteGen = "stats_mode=diff:reserve_transparent=1";
constexpr const char* kPaletteUse = "dither=none:diff_mode=rectangle:alpha_threshold=128";
// The frames the palette is made from, deflated: at 1280x720 and 30 fps the demo's take 42 KB
// each (the head turns, so more than the mouth changes), so 32 MB is the first 25 s, in which a
// speech shows its colours: skin, lips, the mouth's inside, teeth, tongue and the blinks' lids.
// A 65 s GIF made so differs from one with the palette of all its frames by 57.5 dB PSNR (the
// least 57.2). A chat's GIF of a few seconds is made from all its frames, as before.
constexpr std::size_t kSampleBytes = 32u << 20;

// libavfilter is opened when the first GIF is made, not linked: with what it links in turn
// (libplacebo, Vulkan, libepoxy, flite, pocketsphinx, rubberband, LAPACK...: 31 shared libraries
// that nothing else in talkface needs) it cost every program that loads libtalkface about 80 M
// instructions of dynamic linking at start, a third of what `talkface syllables` spent
// (bench/README.md, "Session 13"), and only a GIF's palette uses it. The name carries the major
// version the headers describe, so the calls below have the types they were compiled against.
constexpr const char* kAvFilterLibrary = "libavfilter.so." AV_STRINGIFY(LIBAVFILTER_VERSION_MAJOR);

}  // namespace

// The libavfilter calls GifFrames makes, looked up once per process; the library stays loaded.
struct AvFilterCalls {
    decltype(&avfilter_graph_alloc) graph_alloc = nullptr;
    decltype(&avfilter_graph_free) graph_free = nullptr;
    decltype(&avfilter_get_by_name) get_by_name = nullptr;
    decltype(&avfilter_graph_create_filter) graph_create_filter = nullptr;
    decltype(&avfilter_link) link = nullptr;
    decltype(&avfilter_graph_config) graph_config = nullptr;
    decltype(&av_buffersrc_add_frame_flags) buffersrc_add_frame_flags = nullptr;
    decltype(&av_buffersink_get_frame) buffersink_get_frame = nullptr;
    std::string failure;  // why the library or a call could not be found; empty when all were
};

namespace {

AvFilterCalls load_avfilter() {
    AvFilterCalls calls;
    void* library = dlopen(kAvFilterLibrary, RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
        const char* reason = dlerror();
        calls.failure = reason != nullptr ? reason : std::string(kAvFilterLibrary) + " not found";
        return calls;
    }
    const auto find = [&](auto& call, const char* name) {
        call = reinterpret_cast<std::remove_reference_t<decltype(call)>>(dlsym(library, name));
        if (call == nullptr && calls.failure.empty()) calls.failure = std::string(kAvFilterLibrary) + " has no " + name;
    };
    find(calls.graph_alloc, "avfilter_graph_alloc");
    find(calls.graph_free, "avfilter_graph_free");
    find(calls.get_by_name, "avfilter_get_by_name");
    find(calls.graph_create_filter, "avfilter_graph_create_filter");
    find(calls.link, "avfilter_link");
    find(calls.graph_config, "avfilter_graph_config");
    find(calls.buffersrc_add_frame_flags, "av_buffersrc_add_frame_flags");
    find(calls.buffersink_get_frame, "av_buffersink_get_frame");
    return calls;
}

// libavfilter's calls. \throws talkface::InvalidArgument naming `parameter` (the output file) if
// they cannot be loaded.
const AvFilterCalls& avfilter_calls(const std::string& parameter) {
    static const AvFilterCalls calls = load_avfilter();  // thread-safe, once
    if (!calls.failure.empty())
        throw InvalidArgument(parameter, "an animated GIF (.gif) needs FFmpeg's " + std::string(kAvFilterLibrary) +
                                             " (its palettegen and paletteuse filters), which could not be loaded: " +
                                             calls.failure + "; install it (Debian: libavfilter" +
                                             AV_STRINGIFY(LIBAVFILTER_VERSION_MAJOR) + ") or choose another format");
    return calls;
}

}  // namespace

struct GifFrames::Graph {
    const AvFilterCalls& avfilter;
    AVFilterGraph* graph;
    std::vector<AVFilterContext*> sources;
    AVFilterContext* sink = nullptr;

    explicit Graph(const AvFilterCalls& calls) : avfilter(calls), graph(calls.graph_alloc()) {
        if (graph == nullptr) throw std::bad_alloc();
    }
    ~Graph() { avfilter.graph_free(&graph); }
    Graph(const Graph&) = delete;
    Graph& operator=(const Graph&) = delete;

    AVFilterContext* add(const char* filter_name, const std::string& arguments) {
        AVFilterContext* context = nullptr;
        check_ffmpeg(avfilter.graph_create_filter(&context, avfilter.get_by_name(filter_name), filter_name,
                                                  arguments.c_str(), nullptr, graph),
                     filter_name);
        return context;
    }
    AVFilterContext* add_source(int width, int height, AVPixelFormat format) {
        AVFilterContext* source = add("buffer", "video_size=" + std::to_string(width) + "x" + std::to_string(height) +
                                                    ":pix_fmt=" + std::to_string(format) +
                                                    ":time_base=1/1:pixel_aspect=1/1");
        sources.push_back(source);
        return source;
    }
    void link(AVFilterContext* from, AVFilterContext* to, unsigned to_pad = 0) {
        check_ffmpeg(avfilter.link(from, 0, to, to_pad), "a filter link");
    }
    void configure() { check_ffmpeg(avfilter.graph_config(graph, nullptr), "the GIF palette's filters"); }

    void push(std::size_t source, AVFrame* frame) {
        check_ffmpeg(avfilter.buffersrc_add_frame_flags(sources[source], frame, AV_BUFFERSRC_FLAG_PUSH), "a GIF frame");
    }
    // The frames the sink has ready, to `each`; false once it has given its last.
    bool drain(AVFrame* frame, const std::function<void(AVFrame*)>& each) {
        for (;;) {
            const int got = avfilter.buffersink_get_frame(sink, frame);
            if (got == AVERROR(EAGAIN)) return true;
            if (got == AVERROR_EOF) return false;
            check_ffmpeg(got, "a GIF frame");
            each(frame);
            av_frame_unref(frame);
        }
    }
};

GifFrames::GifFrames(int width, int height, bool transparent, const std::string& parameter)
    : width_(width), height_(height), transparent_(transparent), avfilter_(&avfilter_calls(parameter)),
      palette_graph_(std::make_unique<Graph>(*avfilter_)),
      mapped_(av_frame_alloc()), last_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0) {
    if (!mapped_) throw std::bad_alloc();
    Graph& graph = *palette_graph_;
    AVFilterContext* source = graph.add_source(width, height, transparent ? AV_PIX_FMT_RGBA : AV_PIX_FMT_RGB0);
    AVFilterContext* palettegen = graph.add("palettegen", kPaletteGen);
    graph.sink = graph.add("buffersink", "");
    graph.link(source, palettegen);
    graph.link(palettegen, graph.sink);
    graph.configure();
}

GifFrames::~GifFrames() = default;

void GifFrames::add(const std::uint8_t* rgba, std::size_t stride_bytes, const FrameSink& each) {
    if (mapping_graph_) {
        map(rgba, stride_bytes, each);
        return;
    }
    keep(rgba, stride_bytes);
    if (kept_bytes_ > kSampleBytes) start_mapping(each);
}

void GifFrames::keep(const std::uint8_t* rgba, std::size_t stride_bytes) {
    const std::size_t row_bytes = 4 * static_cast<std::size_t>(width_);
    difference_.resize(last_.size());
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* row = rgba + y * stride_bytes;
        std::uint8_t* last = last_.data() + y * row_bytes;
        std::uint8_t* out = difference_.data() + y * row_bytes;
        for (std::size_t x = 0; x < row_bytes; ++x) out[x] = static_cast<std::uint8_t>(row[x] - last[x]);
        std::memcpy(last, row, row_bytes);
    }
    uLongf packed_size = compressBound(static_cast<uLong>(difference_.size()));
    deflating_.resize(packed_size);
    if (compress2(deflating_.data(), &packed_size, difference_.data(), static_cast<uLong>(difference_.size()), 1) != Z_OK) {
        throw std::bad_alloc();
    }
    kept_.emplace_back(deflating_.begin(), deflating_.begin() + static_cast<std::ptrdiff_t>(packed_size));
    kept_bytes_ += packed_size;

    FramePtr frame(av_frame_alloc());
    if (!frame) throw std::bad_alloc();
    frame->format = transparent_ ? AV_PIX_FMT_RGBA : AV_PIX_FMT_RGB0;
    frame->width = width_;
    frame->height = height_;
    frame->data[0] = last_.data();
    frame->linesize[0] = static_cast<int>(row_bytes);
    frame->pts = static_cast<std::int64_t>(kept_.size()) - 1;
    // Not reference counted: the filter copies the picture.
    palette_graph_->push(0, frame.get());
}

void GifFrames::start_mapping(const FrameSink& each) {
    FramePtr palette(av_frame_alloc());
    if (!palette) throw std::bad_alloc();
    palette_graph_->push(0, nullptr);
    palette_graph_->drain(mapped_.get(), [&](AVFrame* made) { av_frame_move_ref(palette.get(), made); });
    palette_graph_.reset();
    if (palette->width != 16 || palette->height != 16) check_ffmpeg(AVERROR_BUG, "the GIF palette");
    palette->pts = 0;

    mapping_graph_ = std::make_unique<Graph>(*avfilter_);
    Graph& graph = *mapping_graph_;
    AVFilterContext* pictures = graph.add_source(width_, height_, transparent_ ? AV_PIX_FMT_RGBA : AV_PIX_FMT_RGB0);
    AVFilterContext* colours = graph.add_source(16, 16, static_cast<AVPixelFormat>(palette->format));
    AVFilterContext* paletteuse = graph.add("paletteuse", kPaletteUse);
    graph.sink = graph.add("buffersink", "");
    graph.link(pictures, paletteuse, 0);
    graph.link(colours, paletteuse, 1);
    graph.link(paletteuse, graph.sink);
    graph.configure();
    graph.push(1, palette.get());
    graph.push(1, nullptr);

    // The kept frames, undone difference by difference into the last frame's buffer.
    std::vector<std::uint8_t>& picture = last_;
    std::fill(picture.begin(), picture.end(), 0);
    std::vector<std::uint8_t>& difference = difference_;
    for (std::vector<std::uint8_t>& kept : kept_) {
        uLongf size = static_cast<uLongf>(difference.size());
        if (uncompress(difference.data(), &size, kept.data(), static_cast<uLong>(kept.size())) != Z_OK ||
            size != difference.size()) {
            check_ffmpeg(AVERROR_BUG, "a kept GIF frame");
        }
        std::vector<std::uint8_t>().swap(kept);
        for (std::size_t i = 0; i < picture.size(); ++i) picture[i] = static_cast<std::uint8_t>(picture[i] + difference[i]);
        map(picture.data(), 4 * static_cast<std::size_t>(width_), each);
    }
    kept_ = {};
    kept_bytes_ = 0;
    last_ = {};
    difference_ = {};
    deflating_ = {};
}

void GifFrames::map(const std::uint8_t* rgba, std::size_t stride_bytes, const FrameSink& each) {
    FramePtr frame(av_frame_alloc());
    if (!frame) throw std::bad_alloc();
    frame->format = transparent_ ? AV_PIX_FMT_RGBA : AV_PIX_FMT_RGB0;
    frame->width = width_;
    frame->height = height_;
    // Not reference counted: the filter copies the picture, and never writes to it.
    frame->data[0] = const_cast<std::uint8_t*>(rgba);
    frame->linesize[0] = static_cast<int>(stride_bytes);
    frame->pts = next_pts_++;
    mapping_graph_->push(0, frame.get());
    mapping_graph_->drain(mapped_.get(), each);
}

void GifFrames::finish(const FrameSink& each) {
    if (!mapping_graph_) start_mapping(each);
    mapping_graph_->push(0, nullptr);
    if (mapping_graph_->drain(mapped_.get(), each)) check_ffmpeg(AVERROR_BUG, "the end of the GIF's frames");
    mapping_graph_.reset();
}

}  // namespace talkface::detail
