// Reads back what the video stage wrote, through libavformat/libavcodec: the streams, their codecs
// and durations, and decoded video frames as RGBA. Test-only.
#ifndef TALKFACE_TESTS_VIDEO_MEDIA_PROBE_HPP
#define TALKFACE_TESTS_VIDEO_MEDIA_PROBE_HPP

#include <cstdint>
#include <string>
#include <vector>

namespace talkface_test {

struct StreamInfo {
    std::string codec;         // "h264", "opus", "aac", "vp9" ...
    bool is_video = false;
    double start_s = 0.0;      // the first packet's time
    double priming_s = 0.0;    // audio: the decoder's delay that players skip (Opus pre-skip in WebM)
    double duration_s = 0.0;   // from the stream, or from its packets
    int width = 0, height = 0;
    std::string pixel_format;  // "yuv420p" ...
    int sample_rate_hz = 0;
    long frame_count = 0;      // packets counted
};

struct MediaInfo {
    std::string container;     // libavformat's demuxer name
    double duration_s = 0.0;   // the container's
    std::vector<StreamInfo> streams;
    const StreamInfo* video() const;
    const StreamInfo* audio() const;
};

// \throws std::runtime_error if libavformat cannot open the file.
MediaInfo probe_media(const std::string& path);

// Decoded video frame `index` (0-based, in presentation order) as RGBA rows, width*4 bytes each.
std::vector<std::uint8_t> decode_video_frame_rgba(const std::string& path, long index, int* width, int* height);

// Writes bytes to a file (for probing memory output).
void write_bytes(const std::string& path, const std::string& bytes);

}  // namespace talkface_test

#endif
