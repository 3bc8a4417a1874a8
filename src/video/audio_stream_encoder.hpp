// One compressed audio stream inside a container: mono float samples in, Opus or AAC packets out
// to the muxer. Shared by the audio files (audio_encoder.cpp) and the videos (video_writer.cpp), so
// a page's audio and a video's sound are encoded the same way.
#ifndef TALKFACE_VIDEO_AUDIO_STREAM_ENCODER_HPP
#define TALKFACE_VIDEO_AUDIO_STREAM_ENCODER_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "video/ffmpeg_support.hpp"
#include "video/muxer_output.hpp"

extern "C" {
#include <libavutil/audio_fifo.h>
}

namespace talkface::detail {

enum class AudioCodec {
    opus,  // libopus, 48 kHz: WebM and Ogg
    aac,   // FFmpeg's own AAC-LC encoder (LGPL), 48 kHz: MP4
};

struct AudioFifoDeleter {
    void operator()(AVAudioFifo* fifo) const { av_audio_fifo_free(fifo); }
};

class AudioStreamEncoder {
public:
    // Adds the stream to `output` (before its header is written). `bitrate_bps` 0 picks the
    // codec's default for speech. `low_rate_speech`: Opus tuned for a voice at a low bit rate
    // (audio_encoder.hpp). `parameter` names the output in errors (an encoder missing).
    AudioStreamEncoder(MuxerOutput& output, AudioCodec codec, int input_rate_hz, int bitrate_bps,
                       bool low_rate_speech, const std::string& parameter);

    // Encodes `count` mono samples at the input rate and hands the packets to the muxer.
    void encode(const float* mono, std::size_t count);
    // Encodes what is buffered and drains the encoder; call once, after the last encode().
    void finish();

    // Input samples taken so far, and their duration.
    std::uint64_t input_sample_count() const { return input_sample_count_; }
    int input_rate_hz() const { return input_rate_hz_; }

private:
    // Resamples `count` samples (nullptr: drains the resampler) into the FIFO.
    void resample(const float* mono, int count);
    // Encodes whole encoder frames from the FIFO; `is_last` also the short rest.
    void encode_buffered(bool is_last);
    void send(AVFrame* frame);

    MuxerOutput& output_;
    AVStream* stream_ = nullptr;
    CodecContextPtr encoder_;
    ResampleContextPtr resampler_;
    std::unique_ptr<AVAudioFifo, AudioFifoDeleter> fifo_;
    std::vector<float> resampled_;  // one plane: mono, float (FLT or FLTP alike)
    FramePtr frame_;
    PacketPtr packet_;
    int input_rate_hz_;
    std::uint64_t input_sample_count_ = 0;
    std::int64_t next_pts_ = 0;  // in samples at the encoder's rate
    std::int64_t priming_shift_ = 0;  // added to packet times, samples (WebM: the pre-skip)
};

}  // namespace talkface::detail

#endif
