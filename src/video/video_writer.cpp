// VideoWriter: frames and a speech into one container (or a PNG sequence). Sound is encoded as the
// frames arrive, up to the time of the last frame, so the muxer interleaves the two streams
// without holding either whole.
#include "talkface/video_writer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "talkface/errors.hpp"
#include "video/audio_stream_encoder.hpp"
#include "video/muxer_output.hpp"
#include "video/png_sequence.hpp"
#include "video/video_stream_encoder.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr std::size_t kAudioBlockFrames = 4096;

const char* muxer_name(VideoFormat format) {
    switch (format) {
        case VideoFormat::mp4: return "mp4";
        case VideoFormat::webm: return "webm";
        case VideoFormat::webp: return "webp";
        case VideoFormat::gif: return "gif";
        case VideoFormat::png_sequence: return nullptr;
    }
    return nullptr;
}

bool has_sound(VideoFormat format) { return format == VideoFormat::mp4 || format == VideoFormat::webm; }

}  // namespace

struct VideoWriter::Impl {
    std::string path;
    VideoOptions options;
    VideoFormat format;
    std::optional<detail::MuxerOutput> muxer;
    std::optional<detail::PngSequenceOutput> png_sequence;
    std::optional<detail::VideoStreamEncoder> video;
    AVStream* video_stream = nullptr;
    std::unique_ptr<detail::AudioSource> audio_source;
    std::optional<detail::AudioStreamEncoder> audio;
    std::vector<float> audio_block;
    bool is_started = false;
    bool is_finished = false;

    Impl(std::string output_path, VideoOptions video_options)
        : path(std::move(output_path)), options(video_options), format(video_format_from_path(path)) {
        check_video_options(path, options);
        if (format == VideoFormat::png_sequence) {
            // The encoder is looked up first: a missing one must leave nothing behind.
            video.emplace(format, options, false, path);
            png_sequence.emplace(path);
        } else {
            muxer.emplace(detail::MuxerOutput::to_file(path, muxer_name(format)));
            const bool global_header = (muxer->context()->oformat->flags & AVFMT_GLOBALHEADER) != 0;
            video.emplace(format, options, global_header, path);
            video_stream = avformat_new_stream(muxer->context(), nullptr);
            if (video_stream == nullptr) throw std::bad_alloc();
            video_stream->time_base = video->context()->time_base;
            video_stream->avg_frame_rate = video->context()->framerate;
            detail::check_ffmpeg(avcodec_parameters_from_context(video_stream->codecpar, video->context()),
                                 "the video stream's parameters");
        }
    }

    void set_audio(std::unique_ptr<detail::AudioSource> source) {
        if (is_started) throw InvalidArgument("audio", "must be added before the first frame");
        if (audio_source) throw InvalidArgument("audio", "was added already; a video has one sound");
        if (!has_sound(format)) return;
        audio_source = std::move(source);
        const detail::AudioCodec codec = format == VideoFormat::mp4 ? detail::AudioCodec::aac : detail::AudioCodec::opus;
        audio.emplace(*muxer, codec, audio_source->sample_rate_hz(), 0, false, path);
    }

    void start() {
        if (is_started) return;
        is_started = true;
        if (!muxer) return;
        AVDictionary* muxer_options = nullptr;
        if (format == VideoFormat::mp4) av_dict_set(&muxer_options, "movflags", "+faststart", 0);
        // Loop forever, as chats show animated images.
        if (format == VideoFormat::webp || format == VideoFormat::gif) av_dict_set(&muxer_options, "loop", "0", 0);
        muxer->write_header(&muxer_options);
        av_dict_free(&muxer_options);
    }

    void write_video_packet(AVPacket* packet, AVRational time_base) {
        if (png_sequence) {
            png_sequence->write_frame(packet->data, static_cast<std::size_t>(packet->size));
            return;
        }
        av_packet_rescale_ts(packet, time_base, video_stream->time_base);
        packet->stream_index = video_stream->index;
        muxer->write_packet(packet);
    }

    // Encodes sound up to `until_s` seconds (all of it for infinity).
    void encode_audio_until(double until_s) {
        if (!audio) return;
        const double rate = audio->input_rate_hz();
        audio_block.resize(kAudioBlockFrames);
        for (;;) {
            const double wanted = std::isinf(until_s) ? static_cast<double>(kAudioBlockFrames)
                                                      : std::ceil(until_s * rate) - double(audio->input_sample_count());
            if (wanted <= 0.0) return;
            const std::size_t count =
                audio_source->read(audio_block.data(), std::min<std::size_t>(kAudioBlockFrames, std::size_t(wanted)));
            if (count == 0) return;
            audio->encode(audio_block.data(), count);
        }
    }
};

VideoWriter::VideoWriter(std::string path, VideoOptions options)
    : impl_(std::make_unique<Impl>(std::move(path), options)) {}

VideoWriter::~VideoWriter() = default;
VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&&) noexcept = default;

VideoFormat VideoWriter::format() const { return impl_->format; }
const VideoOptions& VideoWriter::options() const { return impl_->options; }
std::size_t VideoWriter::frame_count() const { return static_cast<std::size_t>(impl_->video->frame_count()); }

void VideoWriter::add_audio(const AudioView& audio) { impl_->set_audio(detail::open_audio_view(audio)); }

void VideoWriter::add_audio_file(const std::string& audio_path) {
    impl_->set_audio(detail::open_audio_file(audio_path));
}

void VideoWriter::write_frame(const std::uint8_t* rgba, std::size_t stride_bytes) {
    Impl& impl = *impl_;
    if (impl.is_finished) throw InvalidArgument("write_frame", "the video was finished already");
    if (rgba == nullptr) throw InvalidArgument("rgba", "must not be null");
    if (stride_bytes < 4 * static_cast<std::size_t>(impl.options.width_px)) {
        throw InvalidArgument("stride_bytes", "expected at least 4 * width_px = " +
                                                  std::to_string(4 * impl.options.width_px) + ", found " +
                                                  std::to_string(stride_bytes));
    }
    impl.start();
    impl.video->encode(rgba, stride_bytes,
                       [&impl](AVPacket* packet, AVRational time_base) { impl.write_video_packet(packet, time_base); });
    // The sound that plays while the frames so far are shown.
    impl.encode_audio_until(static_cast<double>(impl.video->frame_count()) / impl.options.fps);
}

void VideoWriter::finish() {
    Impl& impl = *impl_;
    if (impl.is_finished) throw InvalidArgument("finish", "the video was finished already");
    if (impl.video->frame_count() == 0) throw InvalidArgument("frames", "no frame was written; a video needs one");
    impl.is_finished = true;
    impl.video->finish([&impl](AVPacket* packet, AVRational time_base) { impl.write_video_packet(packet, time_base); });
    impl.encode_audio_until(std::numeric_limits<double>::infinity());
    if (impl.audio) impl.audio->finish();
    if (impl.png_sequence) {
        impl.png_sequence->finish();
    } else {
        impl.muxer->finish();
    }
}

}  // namespace v0
}  // namespace talkface
