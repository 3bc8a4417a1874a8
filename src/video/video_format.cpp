// The kinds of video file, told by their extension, and the limits of their options.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"
#include "talkface/video_writer.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// 8K UHD: the largest size H.264 level 6.2 and VP9 level 6.2 carry, and a frame (130 MB of RGBA at
// most) that fits the memory any caller would budget for one frame.
constexpr int kMaxLongSidePx = 7680;
constexpr int kMaxShortSidePx = 4320;
constexpr double kMinFps = 1.0;
constexpr double kMaxFps = 120.0;
// GIF's frame delays are whole hundredths of a second, and browsers show a delay under 0.02 s as
// 0.1 s: faster than 50 fps a GIF would play slower than asked.
constexpr double kMaxGifFps = 50.0;

std::string lower_extension(std::string_view path) {
    const std::size_t slash = path.find_last_of('/');
    const std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
    const std::size_t dot = name.find_last_of('.');
    if (dot == std::string_view::npos || dot == 0) return {};
    std::string extension(name.substr(dot));
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

const char* codec_words(VideoFormat format) {
    return format == VideoFormat::mp4 ? "H.264 in .mp4" : "VP9 in .webm";
}

}  // namespace

const char* video_format_name(VideoFormat format) {
    switch (format) {
        case VideoFormat::mp4: return "mp4";
        case VideoFormat::webm: return "webm";
        case VideoFormat::webp: return "webp";
        case VideoFormat::png_sequence: return "png";
        case VideoFormat::gif: return "gif";
    }
    throw InvalidArgument("format", "expected mp4, webm, webp, png or gif, found " +
                                        std::to_string(static_cast<int>(format)));
}

VideoFormat video_format_from_path(std::string_view path) {
    const std::string extension = lower_extension(path);
    if (extension == ".mp4") return VideoFormat::mp4;
    if (extension == ".webm") return VideoFormat::webm;
    if (extension == ".webp") return VideoFormat::webp;
    if (extension == ".png") return VideoFormat::png_sequence;
    if (extension == ".gif") return VideoFormat::gif;
    throw InvalidArgument(std::string(path), (extension.empty() ? std::string("no extension")
                                                                : "unknown extension \"" + extension + "\"") +
                                                 "; expected .mp4 (H.264 + AAC), .webm (VP9 + Opus), .webp "
                                                 "or .gif (animated) or .png (a numbered sequence)");
}

void check_video_options(std::string_view path, const VideoOptions& options) {
    const VideoFormat format = video_format_from_path(path);
    const int long_side = std::max(options.width_px, options.height_px);
    const int short_side = std::min(options.width_px, options.height_px);
    const std::string size = std::to_string(options.width_px) + "x" + std::to_string(options.height_px);
    if (short_side < 2) {
        throw InvalidArgument(options.width_px < 2 ? "width_px" : "height_px",
                              "a size of " + size + ": expected at least 2x2 pixels");
    }
    if (long_side > kMaxLongSidePx || short_side > kMaxShortSidePx) {
        throw InvalidArgument(options.width_px == long_side ? "width_px" : "height_px",
                              "a size of " + size + " is over the largest, 7680x4320 (or 4320x7680)");
    }
    if ((format == VideoFormat::mp4 || format == VideoFormat::webm) &&
        (options.width_px % 2 != 0 || options.height_px % 2 != 0)) {
        // 4:2:0 video keeps one colour sample per 2x2 pixels; encoders refuse odd sides, and
        // rounding silently would give a file of another size than asked.
        const int even_width = options.width_px + options.width_px % 2;
        const int even_height = options.height_px + options.height_px % 2;
        throw InvalidArgument(options.width_px % 2 != 0 ? "width_px" : "height_px",
                              "a size of " + size + ": " + codec_words(format) +
                                  " needs an even width and height (4:2:0 colour); try " +
                                  std::to_string(even_width) + "x" + std::to_string(even_height) +
                                  ", or .webp / .gif / .png, which take any size");
    }
    if (!std::isfinite(options.fps) || options.fps < kMinFps || options.fps > kMaxFps) {
        throw InvalidArgument("fps", "expected 1..120 frames per second, found " +
                                         detail::format_shortest(options.fps));
    }
    if (format == VideoFormat::gif && options.fps > kMaxGifFps) {
        throw InvalidArgument("fps", "expected 1..50 frames per second for .gif (its frames last whole "
                                     "hundredths of a second, and players show shorter than 0.02 s as 0.1 s), found " +
                                         detail::format_shortest(options.fps));
    }
    const int max_crf = format == VideoFormat::webm ? 63 : 51;
    if (options.crf != -1 && (options.crf < 0 || options.crf > max_crf)) {
        throw InvalidArgument("crf", std::string("expected 0..") + std::to_string(max_crf) + " for " +
                                         video_format_name(format) + " (or -1, the default), found " +
                                         std::to_string(options.crf));
    }
    if (options.transparent && format == VideoFormat::mp4) {
        throw InvalidArgument("transparent", "H.264 in .mp4 has no alpha channel; write .webm, .webp, .gif or .png");
    }
}

}  // namespace v0
}  // namespace talkface
