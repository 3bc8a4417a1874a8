#include "video/audio_encoder.hpp"

#include <vector>

#include "talkface/errors.hpp"
#include "video/audio_stream_encoder.hpp"
#include "video/muxer_output.hpp"

namespace talkface::detail {

namespace {

constexpr std::size_t kBlockFrames = 16384;

const char* muxer_name(AudioContainer container) {
    switch (container) {
        case AudioContainer::ogg_opus: return "ogg";
        case AudioContainer::webm_opus: return "webm";
        case AudioContainer::mp4_aac: return "mp4";
    }
    throw InvalidArgument("container", "expected ogg_opus, webm_opus or mp4_aac");
}

AudioCodec codec_of(AudioContainer container) {
    return container == AudioContainer::mp4_aac ? AudioCodec::aac : AudioCodec::opus;
}

void encode_into(MuxerOutput& output, AudioSource& audio, const AudioEncodeOptions& options,
                 const std::string& parameter) {
    AudioStreamEncoder stream(output, codec_of(options.container), audio.sample_rate_hz(), options.bitrate_bps,
                              options.low_rate_speech, parameter);
    AVDictionary* muxer_options = nullptr;
    if (output.is_file() && options.container == AudioContainer::mp4_aac) {
        av_dict_set(&muxer_options, "movflags", "+faststart", 0);
    }
    output.write_header(&muxer_options);
    av_dict_free(&muxer_options);
    std::vector<float> block(kBlockFrames);
    for (;;) {
        const std::size_t count = audio.read(block.data(), block.size());
        if (count == 0) break;
        stream.encode(block.data(), count);
    }
    stream.finish();
    output.finish();
}

}  // namespace

const char* audio_container_mime_type(AudioContainer container) {
    switch (container) {
        case AudioContainer::ogg_opus: return "audio/ogg; codecs=opus";
        case AudioContainer::webm_opus: return "audio/webm; codecs=opus";
        case AudioContainer::mp4_aac: return "audio/mp4; codecs=mp4a.40.2";
    }
    throw InvalidArgument("container", "expected ogg_opus, webm_opus or mp4_aac");
}

const char* audio_container_extension(AudioContainer container) {
    switch (container) {
        case AudioContainer::ogg_opus: return ".ogg";
        case AudioContainer::webm_opus: return ".webm";
        case AudioContainer::mp4_aac: return ".m4a";
    }
    throw InvalidArgument("container", "expected ogg_opus, webm_opus or mp4_aac");
}

std::string encode_audio(AudioSource& audio, const AudioEncodeOptions& options) {
    MuxerOutput output = MuxerOutput::to_memory(muxer_name(options.container));
    encode_into(output, audio, options, audio.name());
    return output.take_bytes();
}

std::string encode_audio(const AudioView& audio, const AudioEncodeOptions& options) {
    const std::unique_ptr<AudioSource> source = open_audio_view(audio);
    return encode_audio(*source, options);
}

std::string encode_audio_file(const std::string& audio_path, const AudioEncodeOptions& options) {
    const std::unique_ptr<AudioSource> source = open_audio_file(audio_path);
    return encode_audio(*source, options);
}

void write_encoded_audio(const std::string& path, AudioSource& audio, const AudioEncodeOptions& options) {
    MuxerOutput output = MuxerOutput::to_file(path, muxer_name(options.container));
    encode_into(output, audio, options, path);
}

}  // namespace talkface::detail
