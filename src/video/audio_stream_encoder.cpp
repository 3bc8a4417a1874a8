#include "video/audio_stream_encoder.hpp"

#include <algorithm>
#include <cstring>
#include <new>

extern "C" {
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
}

#include "common/internal_error.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Both codecs run at 48 kHz: Opus only takes 8/12/16/24/48 kHz, and 48 kHz is what every browser
// and phone decodes AAC at without a second resampling.
constexpr int kEncoderRateHz = 48000;
// Speech, mono: Opus is transparent for speech well below 48 kb/s; AAC-LC needs about twice that.
constexpr int kOpusSpeechBitrate = 48000;
constexpr int kAacSpeechBitrate = 96000;

}  // namespace

AudioStreamEncoder::AudioStreamEncoder(MuxerOutput& output, AudioCodec codec, int input_rate_hz, int bitrate_bps,
                                       bool low_rate_speech, const std::string& parameter)
    : output_(output), input_rate_hz_(input_rate_hz) {
    if (input_rate_hz <= 0) {
        throw InvalidArgument("sample_rate_hz", "expected > 0, found " + std::to_string(input_rate_hz));
    }
    const bool is_opus = codec == AudioCodec::opus;
    const AVCodec& encoder = find_encoder(is_opus ? "libopus" : "aac", is_opus ? "Opus audio" : "AAC audio", parameter);
    encoder_.reset(avcodec_alloc_context3(&encoder));
    if (!encoder_) throw std::bad_alloc();
    encoder_->sample_rate = kEncoderRateHz;
    encoder_->sample_fmt = is_opus ? AV_SAMPLE_FMT_FLT : AV_SAMPLE_FMT_FLTP;
    AVChannelLayout mono = AV_CHANNEL_LAYOUT_MONO;  // not const: swr_alloc_set_opts2 takes it so in 5.1
    check_ffmpeg(av_channel_layout_copy(&encoder_->ch_layout, &mono), "the mono channel layout");
    encoder_->bit_rate = bitrate_bps > 0 ? bitrate_bps : is_opus ? kOpusSpeechBitrate : kAacSpeechBitrate;
    encoder_->time_base = AVRational{1, kEncoderRateHz};
    if (output.context()->oformat->flags & AVFMT_GLOBALHEADER) encoder_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* settings = nullptr;
    if (is_opus && low_rate_speech) {
        // libopus's "voip" mode favours a voice's intelligibility over fidelity, and 60 ms packets
        // (three times the default) cut the container's share: a WebM block costs about 8 bytes,
        // 3 kb/s at 50 packets a second, a quarter of a 12 kb/s stream.
        av_dict_set(&settings, "application", "voip", 0);
        av_dict_set(&settings, "frame_duration", "60", 0);
    }
    // FFmpeg's AAC encoder searches its quantisers in two loops by default, a tenth of a whole
    // video's time (callgrind); its "fast" coder takes half of that at the same bit rate.
    if (!is_opus) av_dict_set(&settings, "aac_coder", "fast", 0);
    const int opened = avcodec_open2(encoder_.get(), &encoder, &settings);
    av_dict_free(&settings);
    check_ffmpeg(opened, encoder.name);

    stream_ = avformat_new_stream(output.context(), nullptr);
    if (stream_ == nullptr) throw std::bad_alloc();
    stream_->time_base = encoder_->time_base;
    check_ffmpeg(avcodec_parameters_from_context(stream_->codecpar, encoder_.get()), "the audio stream's parameters");

    SwrContext* resampler = nullptr;
    check_ffmpeg(swr_alloc_set_opts2(&resampler, &encoder_->ch_layout, encoder_->sample_fmt, kEncoderRateHz, &mono,
                                     AV_SAMPLE_FMT_FLT, input_rate_hz, 0, nullptr),
                 "the resampler's settings");
    resampler_.reset(resampler);
    check_ffmpeg(swr_init(resampler_.get()), "the resampler");
    fifo_.reset(av_audio_fifo_alloc(encoder_->sample_fmt, 1, std::max(encoder_->frame_size, 1) * 4));
    if (!fifo_) throw std::bad_alloc();
    frame_.reset(av_frame_alloc());
    if (!frame_) throw std::bad_alloc();
    packet_ = make_packet();
    // Matroska keeps the pre-skip as the track's CodecDelay, which players subtract from every
    // block's time: blocks must then start at 0, not at minus the pre-skip as the encoder stamps
    // them (FFmpeg 5.1's WebM muxer does not move them itself). MP4 and Ogg record the priming
    // their own way (an edit list, the Opus header) from negative times.
    if (std::strcmp(output.context()->oformat->name, "webm") == 0) priming_shift_ = encoder_->initial_padding;
}

void AudioStreamEncoder::encode(const float* mono, std::size_t count) {
    // Blocks of a second keep the resampler's output buffer small whatever `count` is.
    const auto block = static_cast<std::size_t>(input_rate_hz_);
    for (std::size_t done = 0; done < count; done += block) {
        resample(mono + done, static_cast<int>(std::min(block, count - done)));
        encode_buffered(false);
    }
    input_sample_count_ += count;
}

void AudioStreamEncoder::finish() {
    resample(nullptr, 0);  // what the resampler's filter still holds
    encode_buffered(true);
    send(nullptr);
}

void AudioStreamEncoder::resample(const float* mono, int count) {
    const int capacity = swr_get_out_samples(resampler_.get(), count);
    resampled_.resize(static_cast<std::size_t>(std::max(capacity, 1)));
    std::uint8_t* out_planes[1] = {reinterpret_cast<std::uint8_t*>(resampled_.data())};
    const std::uint8_t* in_planes[1] = {reinterpret_cast<const std::uint8_t*>(mono)};
    const int produced = swr_convert(resampler_.get(), out_planes, capacity, mono == nullptr ? nullptr : in_planes, count);
    check_ffmpeg(produced, "resampling");
    if (produced <= 0) return;
    void* planes[1] = {resampled_.data()};
    if (av_audio_fifo_write(fifo_.get(), planes, produced) < produced) throw std::bad_alloc();
}

void AudioStreamEncoder::encode_buffered(bool is_last) {
    const int frame_size = encoder_->frame_size > 0 ? encoder_->frame_size : 1024;
    while (av_audio_fifo_size(fifo_.get()) >= frame_size || (is_last && av_audio_fifo_size(fifo_.get()) > 0)) {
        const int count = std::min(frame_size, av_audio_fifo_size(fifo_.get()));
        av_frame_unref(frame_.get());
        frame_->nb_samples = count;
        frame_->format = encoder_->sample_fmt;
        frame_->sample_rate = encoder_->sample_rate;
        check_ffmpeg(av_channel_layout_copy(&frame_->ch_layout, &encoder_->ch_layout), "the frame's channel layout");
        check_ffmpeg(av_frame_get_buffer(frame_.get(), 0), "an audio frame's buffer");
        if (av_audio_fifo_read(fifo_.get(), reinterpret_cast<void**>(frame_->data), count) != count) {
            throw internal_error("the audio buffer ran short");
        }
        frame_->pts = next_pts_;
        next_pts_ += count;
        send(frame_.get());
    }
}

void AudioStreamEncoder::send(AVFrame* frame) {
    check_ffmpeg(avcodec_send_frame(encoder_.get(), frame), "an audio frame");
    for (;;) {
        const int received = avcodec_receive_packet(encoder_.get(), packet_.get());
        if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
        check_ffmpeg(received, "the audio encoder's output");
        if (packet_->pts != AV_NOPTS_VALUE) packet_->pts += priming_shift_;
        if (packet_->dts != AV_NOPTS_VALUE) packet_->dts += priming_shift_;
        av_packet_rescale_ts(packet_.get(), encoder_->time_base, stream_->time_base);
        packet_->stream_index = stream_->index;
        output_.write_packet(packet_.get());
    }
}

}  // namespace talkface::detail
