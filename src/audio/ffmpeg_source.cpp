#include "audio/ffmpeg_source.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libswresample/swresample.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "audio/chained_stream.hpp"
#include "audio/ffmpeg_messages.hpp"
#include "audio/mp3_toc.hpp"
#include "audio/mp4_index.hpp"
#include "audio/voiced_share.hpp"
#include "common/number_format.hpp"
#include "common/string_ends.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// An AAC-LC encoder's delay, at the least: the first frame it writes overlaps 1024 samples before
// the sound (the codec's frame overlap; FFmpeg's encoder delays by exactly this, Apple's by 1088
// more). An MP4's edit list states the delay and FFmpeg drops it (or, where the sound starts
// after the picture, times it before the sound's start); a raw AAC file (ADTS: an Android
// recorder's and many call recorders' .aac), a Matroska or an AVI file cannot state it, and
// every syllable came 64 ms late at 16 kHz.
constexpr std::size_t kAacFrameOverlapFrames = 1024;

// The same for MPEG Layer II (a TV recording's, a DVD's or an old camera's MP2) and AC-3 (a
// camcorder's AVCHD, a film's track), whose transport streams, program streams and bare files
// state no delay at all: MP2's analysis and synthesis filter banks delay it by 481 samples
// (FFmpeg's encoder and twolame, sox's, alike: 10 ms at 48 kHz), AC-3's by its block overlap,
// 256 (FFmpeg's three encoders alike).
constexpr std::size_t kMp2FilterBankDelayFrames = 481;
constexpr std::size_t kAc3BlockOverlapFrames = 256;

// Whether the file at `path` opens with Matroska's EBML header (WebM's too: its ID 1A 45 DF A3, then
// its size as an EBML variable-length number, RFC 8794 4) and ends inside it: a download cut to its
// first bytes, which FFmpeg called "Invalid data", as if it were no audio.
bool ends_inside_ebml_header(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) return false;
    unsigned char head[12] = {};
    const std::size_t got = std::fread(head, 1, sizeof head, file);
    std::fclose(file);
    constexpr unsigned char kEbmlId[4] = {0x1A, 0x45, 0xDF, 0xA3};
    if (got < 5 || std::memcmp(head, kEbmlId, sizeof kEbmlId) != 0 || head[4] == 0) return false;
    // The size's length: 1 + the leading zero bits of its first byte; its value: the bits after the marker.
    std::size_t length = 1;
    while ((head[4] & (0x80U >> (length - 1))) == 0) ++length;
    if (got < 4 + length) return true;
    std::uint64_t size = head[4] & (0xFFU >> length);
    for (std::size_t i = 1; i < length; ++i) size = size << 8U | head[4 + i];
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    return !error && 4 + length + size > bytes;
}

// Whether the file at `path` opens as an MP3 does (an ID3v2 tag or none, then an MPEG Layer III
// frame's header) and ends within its first few frames: FFmpeg's MP3 reader wants more of them to
// tell MP3 from other bytes, and said "Invalid argument", as of a text file.
bool ends_within_first_mp3_frames(const std::string& path) {
    std::error_code error;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path, error);
    std::FILE* file = error ? nullptr : std::fopen(path.c_str(), "rb");
    if (file == nullptr) return false;
    std::string head(10, '\0');
    head.resize(std::fread(head.data(), 1, head.size(), file));
    const std::size_t frame_start = after_id3(head);
    std::string frame_head(4, '\0');
    const bool seeked =
        frame_start < file_bytes && std::fseek(file, static_cast<long>(frame_start), SEEK_SET) == 0;
    frame_head.resize(seeked ? std::fread(frame_head.data(), 1, frame_head.size(), file) : 0);
    std::fclose(file);
    constexpr std::size_t kFewFrames = 4;
    const auto frame = frame_head.size() == 4 ? read_mp3_frame_header(frame_head) : std::nullopt;
    return frame && frame->bytes > 0 && file_bytes - frame_start < kFewFrames * frame->bytes;
}

// Demuxers for recordings people have: MP3, raw AAC, MP4/M4A/MOV (one demuxer), Matroska/WebM,
// Ogg (Opus), FLAC, WAV, MPEG transport and program streams (a camcorder's AVCHD .mts and .m2ts, a
// TV recording's .ts, a DVD's .vob and an old camera's .mpg, with MP2 or AC-3 sound), raw AC-3 and
// a few more. Whitelisted because FFmpeg also has demuxers (playlists, concat lists, image
// sequences) that open other files named inside the input.
constexpr const char* kFormats =
    "mp3,aac,mov,matroska,webm,ogg,flac,wav,w64,aiff,caf,avi,asf,amr,au,mpegts,mpeg,ac3,eac3";

// How far short of its stated length a sound track may end and still be whole: the larger of
// these (encoder padding and priming are tens of milliseconds; a file cut off loses far more).
constexpr double kLengthSlackS = 0.25;
constexpr double kLengthSlackShare = 0.05;

// How much later than the samples before it a frame's timestamp may lie before the difference is
// taken for lost packets: Matroska stores milliseconds, and a lost packet shorter than this moves
// no syllable out of the aligner's 50 ms.
constexpr double kTimestampSlackS = 0.025;
// A damaged file's lost end (fill_lost_end) is at most this many times the sound read before it:
// damage loses the sound of the bytes it hits, and a lost end longer than this says the length
// stated is damaged.
constexpr double kMostLostEndShare = 10.0;

// Packets after the first that show an MP3 stream's rate constant (each the size its bit rate
// gives a frame, give or take the padding byte) before its bytes are counted as time.
constexpr int kMp3PacketsToJudgeRate = 4;

// The largest frame an MP3 stream can hold: 320 kb/s at 32 kHz, padded (MPEG-1 Layer III, 144 x
// 320000 / 32000 + 1 bytes). A packet larger than this holds bytes that are no frame.
constexpr int kLargestMp3FrameBytes = 1441;

// The packets (of a variable-rate MP3) whose bytes a sample estimate the time of bytes no frame
// holds: about a second.
constexpr double kMp3RecentPackets = 32.0;

// How far a variable-rate MP3's table of contents may place a byte from where the packets before
// it reach, as a share of that, and still be the stream's own.
constexpr double kMp3TocSlackShare = 0.1;

// A file with several sound tracks (a screen recorder's: OBS writes the desktop's sound and the
// microphone's as two, the first often empty; a film's languages) is heard for up to this much of
// each before one is read.
constexpr double kTrackHearingS = 60.0;

// A track is heard as the loudness of its kLoudnessFrameS frames (averaged down to about 8 kHz, as
// voiced_share hears it) against the mean of the kLowEnergyWindowS around each: speech, a syllable
// or a phrase at a time, leaves many frames under half the mean (the "low-energy frames" of Scheirer
// and Slaney's speech/music discriminator, 1997). Over the first 60 s of every passage of the
// corpora, tuning and held out alike (bench/README.md, Session 26): the person's 0.17-0.59 of frames
// (the least with long silences), espeak-ng's 0.26-0.56, v-'s and w-'s 0.33-0.56. make_music_kinds's
// music alone: piano 0.07-0.17, chord pad 0.01-0.02, sung line 0.06-0.12; a drum kit alone
// 0.39-0.55, as speech (which kLeastSpeechVoicedShare tells apart). At 8 kHz white noise no longer
// fills speech's pauses: at the full rate espeak-ng under white noise at 10 dB read 0.17-0.28 (now
// 0.27-0.39); every other passage moved by 0.04 at the most.
constexpr double kLoudnessFrameS = 0.02;
constexpr double kLowEnergyWindowS = 1.0;

// How many times the share of low-energy frames of the track FFmpeg would take (its default one)
// another must have to be read instead: the person's speech against the music nearest to it above
// (0.24 against 0.15 in the conditions it was set on; a passage with long silences reads 0.17, as much as
// the most of a piano's), while a film's languages, speech each, keep the default.
constexpr double kSpeechOverDefaultRatio = 1.5;

// A track voiced (voiced_share.hpp) in fewer of its frames than this is no speech, however many
// low-energy frames it has: make_music_kinds's drum kit alone is voiced in 0.10-0.16 of its frames,
// the sweep's (a 190 Hz snare under its noise) in 0.23, speech in 0.33 at the least over the
// tuning passages of every corpus, noisy or not (held out 0.30; bench/README.md, Session 25,
// several sound tracks).
constexpr double kLeastSpeechVoicedShare = 0.27;

// A track whose loudest frame is under this RMS (-60 dBFS) is silent: an empty track is zeros.
constexpr double kSilentTrackRms = 1e-3;

// How far before the frame it seeks to skip_to() has the demuxer seek, for the decoder to
// settle there on what precedes it: an MP3 frame's bit reservoir reaches 511 bytes back (7 frames,
// 0.5 s, at 8 kb/s), AAC and Vorbis overlap one frame, Opus asks 80 ms of preroll (RFC 7845, 4.6).
constexpr double kSeekPrerollS = 1.0;

// The samples every frame of a codec starts on a multiple of, from a stream's second frame on (the
// first may have lost its start to the encoder's delay): a frame's fixed length or the unit its
// lengths come in. MP2's are 1152, MP3's 1152 or (MPEG-2 and 2.5) 576; AAC-LC's 1024 (HE-AAC's
// 2048, its core's at twice the rate); Opus's 2.5 to 60 ms, each a whole number of 2.5 ms (RFC
// 6716, 2.1.4). 0 for a codec whose frames may end on any sample (Vorbis's and FLAC's blocks,
// AAC-LD's 480), and for AC-3 and E-AC-3, whose frames are 1536 samples (six blocks of 256) but
// whose decoder fills the mantissas the encoder left out with dither from one random sequence
// along the whole stream: decoded from a seek, every sample after differs from the whole
// reading's (by up to 0.0024 on a voice at 0.95).
std::int64_t frame_step_frames(const AVCodecParameters& codec, int rate_hz) {
    constexpr std::int64_t kMp2Frame = 1152;
    constexpr std::int64_t kMp3HalfFrame = 576;
    constexpr std::int64_t kAacFrame = 1024;
    constexpr int kOpusStepsPerSecond = 400;  // 2.5 ms
    switch (codec.codec_id) {
        case AV_CODEC_ID_MP2:
            return kMp2Frame;
        case AV_CODEC_ID_MP3:
            return kMp3HalfFrame;
        case AV_CODEC_ID_AAC:
            return codec.profile == FF_PROFILE_AAC_LOW || codec.profile == FF_PROFILE_AAC_HE ||
                           codec.profile == FF_PROFILE_AAC_HE_V2
                       ? kAacFrame
                       : 0;
        case AV_CODEC_ID_OPUS:
            return rate_hz % kOpusStepsPerSecond == 0 ? rate_hz / kOpusStepsPerSecond : 0;
        default:
            return 0;
    }
}

std::string seconds_text(double seconds) { return format_fixed(seconds, 3) + " s"; }

std::string ordinal_text(std::size_t n) {
    static const char* const kOrdinals[] = {"first", "second",  "third",  "fourth", "fifth",
                                            "sixth", "seventh", "eighth", "ninth",  "tenth"};
    return n < 10 ? kOrdinals[n] : "no. " + std::to_string(n + 1);
}

struct FormatCloser {
    void operator()(AVFormatContext* context) const { avformat_close_input(&context); }
};
struct CodecFreer {
    void operator()(AVCodecContext* context) const { avcodec_free_context(&context); }
};
struct PacketFreer {
    void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};
struct FrameFreer {
    void operator()(AVFrame* frame) const { av_frame_free(&frame); }
};
struct ResamplerFreer {
    void operator()(SwrContext* context) const { swr_free(&context); }
};

// A decoded frame's samples as float with its channels averaged (ChannelMixer), as the libsndfile
// reader gives them, so that a file gives the same samples whichever library reads it. Sample
// format conversion only (same rate, same channels): the speech stage resamples.
class FrameMixer {
public:
    FrameMixer() = default;
    ~FrameMixer() { av_channel_layout_uninit(&layout_); }
    FrameMixer(const FrameMixer&) = delete;
    FrameMixer& operator=(const FrameMixer&) = delete;

    // Whether `frame`'s sample format and channels can be converted (a converter made for them).
    bool takes(const AVFrame& frame) {
        if (converter_ && frame.format == format_ &&
            av_channel_layout_compare(&frame.ch_layout, &layout_) == 0)
            return true;
        av_channel_layout_uninit(&layout_);
        if (av_channel_layout_copy(&layout_, &frame.ch_layout) < 0) throw std::bad_alloc();
        SwrContext* raw = nullptr;
        // FFmpeg 5.1 takes the layouts by non-const pointer; the copy stands for both.
        const int made =
            swr_alloc_set_opts2(&raw, &layout_, AV_SAMPLE_FMT_FLT, frame.sample_rate, &layout_,
                                static_cast<AVSampleFormat>(frame.format), frame.sample_rate, 0, nullptr);
        converter_.reset(raw);
        format_ = frame.format;
        if (made < 0 || swr_init(converter_.get()) < 0) converter_.reset();
        return converter_ != nullptr;
    }

    // Converts `frame` (which takes() accepted) and puts the mix of its samples after the first
    // `skip` in `mono`; returns how many it converted, skipped ones included, or FFmpeg's error.
    int mix(const AVFrame& frame, std::size_t skip, std::vector<float>& mono) {
        const auto channels = static_cast<std::size_t>(frame.ch_layout.nb_channels);
        interleaved_.resize(static_cast<std::size_t>(frame.nb_samples) * channels);
        auto* out = reinterpret_cast<std::uint8_t*>(interleaved_.data());
        const int converted =
            swr_convert(converter_.get(), &out, frame.nb_samples,
                        const_cast<const std::uint8_t**>(frame.extended_data), frame.nb_samples);
        if (converted < 0) return converted;
        const auto count = static_cast<std::size_t>(converted);
        skip = std::min(skip, count);
        mono.resize(count - skip);
        mixer_.mix(interleaved_.data() + skip * channels, count - skip, channels, mono.data());
        return converted;
    }

private:
    std::unique_ptr<SwrContext, ResamplerFreer> converter_;
    AVChannelLayout layout_{};
    int format_ = -1;
    std::vector<float> interleaved_;
    ChannelMixer mixer_;
};

// A decoder opened for a stream's `parameters`; where that fails, `context` is null and `failure`
// says at which step, with FFmpeg's error.
struct OpenedDecoder {
    enum class Failure { none, no_decoder, parameters, opening };
    const AVCodec* codec = nullptr;
    std::unique_ptr<AVCodecContext, CodecFreer> context;
    Failure failure = Failure::none;
    int error = 0;
};

OpenedDecoder open_decoder(const AVCodecParameters& parameters) {
    OpenedDecoder opened;
    opened.codec = avcodec_find_decoder(parameters.codec_id);
    if (opened.codec == nullptr) {
        opened.failure = OpenedDecoder::Failure::no_decoder;
        return opened;
    }
    opened.context.reset(avcodec_alloc_context3(opened.codec));
    if (!opened.context) throw std::bad_alloc();
    if (const int copied = avcodec_parameters_to_context(opened.context.get(), &parameters); copied < 0) {
        opened.failure = OpenedDecoder::Failure::parameters;
        opened.error = copied;
    } else if (const int ready = avcodec_open2(opened.context.get(), opened.codec, nullptr); ready < 0) {
        opened.failure = OpenedDecoder::Failure::opening;
        opened.error = ready;
    }
    if (opened.failure != OpenedDecoder::Failure::none) opened.context.reset();
    return opened;
}

// What hearing a sound track found: the figures a track is chosen by.
struct TrackSummary {
    bool is_silent = true;  // no kLoudnessFrameS frame reaches kSilentTrackRms, or it does not decode
    // The share of its frames under half the mean loudness of the kLowEnergyWindowS around them.
    double low_energy_share = 0.0;
    double voiced_share = 0.0;  // voiced_share.hpp

    // Its share of low-energy frames if it is voiced as speech is, else 0: how much it sounds like
    // speech.
    double speech_share() const {
        return is_silent || voiced_share < kLeastSpeechVoicedShare ? 0.0 : low_energy_share;
    }
};

// The samples of a kLoudnessFrameS frame at `rate_hz`, at least one.
std::size_t loudness_frame_samples(double rate_hz) {
    return static_cast<std::size_t>(std::max(1, static_cast<int>(kLoudnessFrameS * rate_hz)));
}

// The RMS of each whole frame of `frame_samples` of `signal`.
std::vector<double> loudness_frames(const std::vector<double>& signal, std::size_t frame_samples) {
    std::vector<double> frames(signal.size() / frame_samples);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        double energy = 0.0;
        for (std::size_t j = i * frame_samples; j < (i + 1) * frame_samples; ++j)
            energy += signal[j] * signal[j];
        frames[i] = std::sqrt(energy / static_cast<double>(frame_samples));
    }
    return frames;
}

double low_energy_share(const std::vector<double>& frames) {
    std::vector<double> sums(frames.size() + 1, 0.0);
    for (std::size_t i = 0; i < frames.size(); ++i) sums[i + 1] = sums[i] + frames[i];
    const auto window = static_cast<std::size_t>(kLowEnergyWindowS / kLoudnessFrameS);
    const std::size_t span = std::min(window, frames.size());
    std::size_t low = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const std::size_t begin = std::min(i - std::min(i, window / 2), frames.size() - span);
        const std::size_t end = begin + span;
        const double mean = (sums[end] - sums[begin]) / static_cast<double>(end - begin);
        if (frames[i] < 0.5 * mean) ++low;
    }
    return static_cast<double>(low) / static_cast<double>(frames.size());
}

// One sound track heard from its packets as they come: its samples, averaged down to the rate a
// pitch is looked for at (PitchRateSignal), from which its loudness is read once it has been heard.
class TrackHearing {
public:
    explicit TrackHearing(const AVStream& stream) : time_base_(stream.time_base) {
        OpenedDecoder opened = open_decoder(*stream.codecpar);
        if (!opened.context || opened.context->sample_rate <= 0) return;
        codec_ = std::move(opened.context);
        frame_.reset(av_frame_alloc());
        if (!frame_) throw std::bad_alloc();
        frame_samples_ = loudness_frame_samples(codec_->sample_rate);
        heard_.emplace(codec_->sample_rate);
    }
    TrackHearing(const TrackHearing&) = delete;
    TrackHearing& operator=(const TrackHearing&) = delete;

    // Whether it still wants packets: it decodes, and neither its sound (in whole kLoudnessFrameS
    // frames) nor its packets' times (a track whose packets do not decode) have reached
    // kTrackHearingS.
    bool listening() const {
        return codec_ && !past_hearing_ &&
               static_cast<double>(samples_heard_ / frame_samples_) * kLoudnessFrameS < kTrackHearingS;
    }

    void hear(const AVPacket& packet) {
        if (packet.pts != AV_NOPTS_VALUE &&
            static_cast<double>(packet.pts) * av_q2d(time_base_) > kTrackHearingS)
            past_hearing_ = true;
        if (!listening() || avcodec_send_packet(codec_.get(), &packet) < 0) return;
        while (avcodec_receive_frame(codec_.get(), frame_.get()) == 0) {
            add(*frame_);
            av_frame_unref(frame_.get());
        }
    }

    // What was heard; a track that does not decode is silent.
    TrackSummary summary() const {
        TrackSummary found;
        if (!heard_) return found;
        const std::vector<double> frames =
            loudness_frames(heard_->samples(), loudness_frame_samples(heard_->rate_hz()));
        found.is_silent =
            std::all_of(frames.begin(), frames.end(), [](double rms) { return rms < kSilentTrackRms; });
        if (found.is_silent) return found;
        found.low_energy_share = low_energy_share(frames);
        found.voiced_share = voiced_share(*heard_);
        return found;
    }

private:
    void add(const AVFrame& frame) {
        const int channels = frame.ch_layout.nb_channels;
        if (frame.nb_samples <= 0 || channels <= 0 || channels > kMaxChannels) return;
        if (!mixer_.takes(frame) || mixer_.mix(frame, 0, mono_) <= 0) return;
        heard_->add(mono_.data(), mono_.size());
        samples_heard_ += mono_.size();
    }

    AVRational time_base_;
    bool past_hearing_ = false;
    std::unique_ptr<AVCodecContext, CodecFreer> codec_;
    std::unique_ptr<AVFrame, FrameFreer> frame_;
    FrameMixer mixer_;
    std::vector<float> mono_;
    std::optional<PitchRateSignal> heard_;
    std::size_t frame_samples_ = 1;  // a kLoudnessFrameS frame at the track's own rate
    std::size_t samples_heard_ = 0;
};

// A file read through FFmpeg with the 4 bytes at `hidden_byte` read as zeros: the capture pattern
// ("OggS") of an Ogg page whose header claims more bytes than the file holds, so that FFmpeg's Ogg
// reader looks for the next page instead of waiting for this one to the end of the file.
class HidingReader {
public:
    HidingReader(const std::string& path, std::int64_t hidden_byte) : hidden_byte_(hidden_byte) {
        file_ = std::fopen(path.c_str(), "rb");
        if (file_ == nullptr) return;
        constexpr int kBufferBytes = 1 << 16;
        auto* buffer = static_cast<unsigned char*>(av_malloc(kBufferBytes));
        if (buffer != nullptr) context_ = avio_alloc_context(buffer, kBufferBytes, 0, this, &read, nullptr, &seek);
        if (context_ == nullptr) {
            av_free(buffer);
            throw std::bad_alloc();
        }
    }
    ~HidingReader() {
        if (context_ != nullptr) av_freep(&context_->buffer);
        avio_context_free(&context_);
        if (file_ != nullptr) std::fclose(file_);
    }
    HidingReader(const HidingReader&) = delete;
    HidingReader& operator=(const HidingReader&) = delete;
    // Null if the file could not be opened (FFmpeg then opens it by its path and says why not).
    AVIOContext* context() const { return context_; }

private:
    static int read(void* opaque, std::uint8_t* buffer, int size) {
        auto* reader = static_cast<HidingReader*>(opaque);
        const std::int64_t at = ftello(reader->file_);
        const std::size_t got = std::fread(buffer, 1, static_cast<std::size_t>(size), reader->file_);
        if (got == 0) return AVERROR_EOF;
        for (std::int64_t byte = reader->hidden_byte_; byte < reader->hidden_byte_ + 4; ++byte)
            if (byte >= at && byte < at + static_cast<std::int64_t>(got)) buffer[byte - at] = 0;
        return static_cast<int>(got);
    }
    static std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
        auto* reader = static_cast<HidingReader*>(opaque);
        if (whence & AVSEEK_SIZE) {
            const std::int64_t at = ftello(reader->file_);
            if (fseeko(reader->file_, 0, SEEK_END) != 0) return -1;
            const std::int64_t size = ftello(reader->file_);
            return fseeko(reader->file_, at, SEEK_SET) == 0 ? size : -1;
        }
        if (fseeko(reader->file_, offset, whence & ~AVSEEK_FORCE) != 0) return -1;
        return ftello(reader->file_);
    }

    std::FILE* file_ = nullptr;
    AVIOContext* context_ = nullptr;
    std::int64_t hidden_byte_;
};

class FfmpegSource final : public AudioSource {
public:
    FfmpegSource(std::string path, const FfmpegReading& reading) : path_(std::move(path)), reading_(reading) {
        quiet_ffmpeg_log();
        open_format();
        int stream = av_find_best_stream(format_.get(), AVMEDIA_TYPE_AUDIO, -1, -1, nullptr, 0);
        if (stream >= 0 && sound_tracks().size() > 1) {
            stream = choose_sound_track(stream);
            // Hearing the tracks read past their start: the file is opened again to be read from it.
            format_.reset();
            hiding_reader_.reset();
            open_format();
        }
        if (stream < 0) {
            bool has_video = false;
            bool has_subtitles = false;
            for (unsigned i = 0; i < format_->nb_streams; ++i) {
                has_video |= format_->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_VIDEO;
                has_subtitles |= format_->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_SUBTITLE;
            }
            if (const std::string damage = broken_index(); !damage.empty())
                throw ParseError(path_, 0, 0, "", damage + ", and no sound track can be found in what is left of it");
            if (has_video) throw ParseError(path_, 0, 0, "", "a video without a sound track: nothing to align");
            // A subtitle file muxed alone (an MKV or MP4 of subtitles, as a subtitle editor or a
            // track extractor writes it) was called no audio stream, which said nothing of what it is.
            if (has_subtitles)
                throw ParseError(
                    path_, 0, 0, "",
                    "subtitles without a sound track: nothing to align (the audio is in another file)");
            throw not_audio("no audio stream in the " + std::string(format_->iformat->name) + " file");
        }
        stream_ = format_->streams[stream];
        const AVCodecParameters* parameters = stream_->codecpar;
        OpenedDecoder opened = open_decoder(*parameters);
        if (opened.failure == OpenedDecoder::Failure::no_decoder)
            throw ParseError(path_, 0, 0, "", std::string("its sound track is ") + avcodec_get_name(parameters->codec_id) +
                                                   ", which this FFmpeg cannot decode");
        if (opened.failure == OpenedDecoder::Failure::parameters)
            throw not_audio(ffmpeg_error_text(opened.error));
        if (opened.failure == OpenedDecoder::Failure::opening) {
            if (const std::string damage = broken_index(); !damage.empty())
                throw ParseError(path_, 0, 0, "",
                                 damage + " (cannot decode its " + opened.codec->name +
                                     " sound track: " + ffmpeg_error_text(opened.error) + ")");
            throw ParseError(path_, 0, 0, "",
                             std::string("cannot decode its ") + opened.codec->name +
                                 " sound track: " + ffmpeg_error_text(opened.error));
        }
        codec_ = std::move(opened.context);
        sample_rate_hz_ = codec_->sample_rate;
        if (parameters->codec_id == AV_CODEC_ID_MP3) {
            mp3_toc_ = read_mp3_toc_file(path_);
            if (mp3_toc_ && mp3_toc_->is_variable_rate) mp3_rate_is_constant_ = false;
        }
        if (!is_readable_format(sample_rate_hz_, codec_->ch_layout.nb_channels))
            throw ParseError(
                path_, 0, 0, "",
                unsupported_format_text("sound track", sample_rate_hz_, codec_->ch_layout.nb_channels));
        estimated_frames_ = estimate_frames();
        stated_seconds_ = stated_seconds();
        // FFmpeg's MP3 reader moves the stream's start past the delay a LAME tag gives; no start, no tag.
        if (parameters->codec_id == AV_CODEC_ID_MP3 && (stream_->start_time == AV_NOPTS_VALUE || stream_->start_time == 0))
            frames_to_skip_ = kUntaggedMp3DelayFrames;
        packet_.reset(av_packet_alloc());
        frame_.reset(av_frame_alloc());
        if (!packet_ || !frame_) throw std::bad_alloc();
        // Decode up to the first samples now: a file that holds none is refused on opening.
        if (!decode_next_frame()) {
            if (const std::string damage = broken_index(); !damage.empty())
                throw ParseError(path_, 0, 0, "", damage + ", and its sound track decodes to no samples from what is left of it");
            // A header that states a length, and packets up to the file's end (or placed past it by
            // an index) that decode to nothing: the file was cut inside its first packets, as a
            // download that stopped after the header leaves it (FFmpeg called the last one "Invalid
            // data", or nothing was left to decode).
            if (stated_seconds_ > 0.0 && packets_reach_file_end()) throw cut_short();
            if (last_refusal_ != 0) throw decode_error(last_refusal_);
            throw InvalidArgument(path_, "empty audio: the sound track decodes to no samples");
        }
        keep_picture_lead();
    }

    FfmpegSource(const FfmpegSource&) = delete;
    FfmpegSource& operator=(const FfmpegSource&) = delete;

    std::size_t read_frames(float* mono, std::size_t max_frames) override {
        std::size_t written = 0;
        while (written < max_frames) {
            if (silence_ahead_ > 0) {
                const std::size_t take = std::min(max_frames - written, silence_ahead_);
                std::fill_n(mono + written, take, 0.0f);
                silence_ahead_ -= take;
                written += take;
                frames_given_ += take;
                continue;
            }
            if (pending_position_ == pending_.size()) {
                if (!decode_next_frame()) {
                    if (fill_lost_end()) continue;
                    check_whole();
                    note_length_at_end();
                    break;
                }
                continue;
            }
            const std::size_t take = std::min(max_frames - written, pending_.size() - pending_position_);
            std::copy_n(pending_.data() + pending_position_, take, mono + written);
            pending_position_ += take;
            written += take;
            frames_given_ += take;
        }
        return written;
    }
    int sample_rate_hz() const override { return sample_rate_hz_; }
    std::size_t frame_count() const override { return estimated_frames_; }
    const std::string& name() const override { return path_; }

private:
    // skip_to()'s move: a seek of the file's one opening to kSeekPrerollS before `frame`, and a
    // decode by a decoder of its own from there to the frame that holds `frame`, placed by its
    // timestamp (frame_start). Only once it stands there does that decoder take the reading's
    // place; a seek that cannot land there opens the file again at the packet the reading had
    // reached (return_to_packets_read), so the reading is as it was; past the first frames, it is
    // then decoded on to `frame` (as the reading would have read it, at its cost). The frames keep
    // their grid: a sample is where the first reading's counting puts it, for the timestamps count
    // as that counting does wherever the file is whole. What the seek passes is not read: the file
    // was read up to its first sound once already, and found silent there, and that reading names
    // what it lost there (take_first_reading).
    bool seek_frames(std::size_t frame) override {
        if (!can_seek()) return false;
        if (pass_over_to(frame, false)) return true;
        if (timed_frames_ >= 2 && can_seek() && land_at(frame)) return true;
        return pass_over_to(frame, true);
    }

    // Whether skip_to() may seek: in a file FFmpeg can seek in, read whole so far (no packet
    // refused, no gap, no codec pause), whose sound track's timestamps resolve one sample (MP3's,
    // FLAC's, MP4's, Ogg's) or, where they do not (Matroska's milliseconds, MPEG-TS's 90 kHz
    // clock), place a frame on its codec's grid (frame_start: Opus, MP2, MP3, AAC; not Vorbis,
    // FLAC or AC-3). A file read in a way of its own (a damaged Ogg file's, a WAV read
    // past its stated size) is read on.
    bool can_seek() const {
        if (hiding_reader_ || reading_.keeps_stated_length || reading_.reads_past_stated_size) return false;
        if (flushed_ || skipped_frames_ > 0 || timed_frames_ < 1 || has_lost_audio_read() ||
            !codec_pauses().empty())
            return false;
        if (format_->pb == nullptr || (format_->pb->seekable & AVIO_SEEKABLE_NORMAL) == 0) return false;
        const AVRational base = stream_->time_base;
        if (base.num <= 0 || base.den <= 0) return false;
        return resolves_sample() ||
               frame_step_frames(*stream_->codecpar, sample_rate_hz_) > 2 * tick_frames();
    }

    // Whether the sound track's time base resolves one sample (MP3's, FLAC's, MP4's, Ogg's).
    bool resolves_sample() const {
        const AVRational base = stream_->time_base;
        return base.den % (static_cast<std::int64_t>(base.num) * sample_rate_hz_) == 0;
    }

    // One tick of the sound track's time base in samples, rounded up: 48 for Matroska's
    // milliseconds at 48 kHz, 1 for MPEG-TS's 90 kHz clock.
    std::int64_t tick_frames() const {
        const AVRational base = stream_->time_base;
        return (static_cast<std::int64_t>(base.num) * sample_rate_hz_ + base.den - 1) / base.den;
    }

    // Where a frame whose timestamp is `timestamp` starts, in the reading's counting. Where the time
    // base resolves one sample, the timestamp's own; else the point of the codec's grid
    // (frame_step_frames, from the second frame, which placed time 0) nearest it: the timestamp and
    // time 0 are each rounded to a tick, and the grid's step is over two ticks, so one point is
    // nearest. None where that point lies further from it than a tick: the frames were not of the
    // codec's steps, and the reading reads on.
    std::optional<std::int64_t> frame_start(std::int64_t timestamp) const {
        const std::int64_t at =
            av_rescale_q(timestamp, stream_->time_base, AVRational{1, sample_rate_hz_}) - time_zero_frames_;
        if (resolves_sample()) return at;
        const std::int64_t step = frame_step_frames(*stream_->codecpar, sample_rate_hz_);
        const std::int64_t from_grid = at - second_frame_at_;
        const std::int64_t steps = (from_grid >= 0 ? from_grid + step / 2 : from_grid - step / 2) / step;
        const std::int64_t placed = second_frame_at_ + steps * step;
        if (std::llabs(placed - at) > tick_frames()) return std::nullopt;
        return placed;
    }

    // Passes over the samples decoded up to `frame`, decoding on while time 0 is not placed (the
    // second frame with a timestamp places it, skip_to_timestamp) or, with `to_frame`, until
    // `frame` is reached. True once the reading stands at `frame`; false where time 0 was placed
    // first or the sound track ended.
    bool pass_over_to(std::size_t frame, bool to_frame) {
        while (true) {
            const std::size_t silence = std::min(silence_ahead_, frame - frames_given_);
            silence_ahead_ -= silence;
            frames_given_ += silence;
            const std::size_t step = std::min(pending_.size() - pending_position_, frame - frames_given_);
            pending_position_ += step;
            frames_given_ += step;
            if (frames_given_ == frame) return true;
            if (!to_frame && timed_frames_ >= 2) return false;
            if (silence_ahead_ == 0 && !decode_next_frame()) return false;
        }
    }

    // What a decode from a seek read up to the frame it landed on: where that frame's first sample
    // lies in the reading's counting and how many it converted, and the packets' bytes and last
    // length, which the reading takes over with the opening.
    struct SeekLanding {
        std::int64_t start = 0;
        std::int64_t frames = 0;
        std::int64_t packets_read = 0;  // of every stream, since the seek
        std::int64_t packets_end_byte = -1;
        std::int64_t next_packet_byte = -1;
        std::int64_t last_packet_duration = 0;
    };

    // The seek of seek_frames, the samples at hand passed over: true where it landed on `frame`.
    bool land_at(std::size_t frame) {
        const std::int64_t target = timestamp_target(frame);
        const std::int64_t seek_at = av_rescale_q(target + time_zero_frames_ - preroll_frames(),
                                                  AVRational{1, sample_rate_hz_}, stream_->time_base);
        if (seek_at <= 0) return false;
        OpenedDecoder opened = open_decoder(*stream_->codecpar);
        if (!opened.context || opened.context->sample_rate != sample_rate_hz_) return false;
        std::optional<SeekLanding> landing;
        if (seek_demuxer(seek_at)) landing = decode_to_landing(*format_, *stream_, *opened.context, target);
        if (!landing || !mix_landing_frame(*landing, target)) {
            return_to_packets_read();
            return false;
        }
        codec_ = std::move(opened.context);
        opening_seek_at_ = seek_at;
        packets_read_ = landing->packets_read;
        take_landing(*landing, frame);
        return true;
    }

    // Seeks the opening's demuxer to the sound track's timestamp `seek_at`, or the packet before.
    bool seek_demuxer(std::int64_t seek_at) {
        return avformat_seek_file(format_.get(), stream_->index, std::numeric_limits<std::int64_t>::min(),
                                  seek_at, seek_at, 0) >= 0;
    }

    // Where a seek moved the demuxer and could not land: the file opened again and its packets read
    // (not decoded) up to the one the reading had reached, from the seek that placed the opening
    // before, if any, so that the reading goes on from there as it was. Only this one opening is
    // held: a second one, which sought while the first waited, held an MP4's index twice (10 h of
    // AAC peaked 9.5 MB higher).
    void return_to_packets_read() {
        const int index = stream_->index;
        format_.reset();
        open_format();
        if (static_cast<unsigned>(index) >= format_->nb_streams)
            throw ParseError(path_, 0, 0, "", "the file changed while it was read: its sound track is gone");
        stream_ = format_->streams[index];
        if (opening_seek_at_ && !seek_demuxer(*opening_seek_at_))
            throw ParseError(path_, 0, 0, "", "the file changed while it was read: it no longer seeks");
        for (std::int64_t packet = 0; packet < packets_read_; ++packet) {
            if (const int got = av_read_frame(format_.get(), packet_.get()); got < 0)
                throw ParseError(path_, 0, 0, "",
                                 "the file changed while it was read: it ends before " +
                                     seconds_text(seconds_read()) + ": " + ffmpeg_error_text(got));
            av_packet_unref(packet_.get());
        }
    }

    // `frame` as a timestamp counts it: the samples decoded run ahead of those given out by what
    // was cut from the start (an encoder's delay).
    std::int64_t timestamp_target(std::size_t frame) const {
        return static_cast<std::int64_t>(frame) + static_cast<std::int64_t>(frames_decoded_ - frames_given_);
    }

    std::int64_t preroll_frames() const { return static_cast<std::int64_t>(kSeekPrerollS * sample_rate_hz_); }

    // Decodes `stream` of `format`, just seeked, with `codec` until a frame holds the sample
    // `target` (left in frame_); none where a frame has no timestamp, another rate, starts past
    // `target`, or the sound track ends first.
    std::optional<SeekLanding> decode_to_landing(AVFormatContext& format, const AVStream& stream,
                                                 AVCodecContext& codec, std::int64_t target) {
        SeekLanding landing;
        landing.packets_end_byte = packets_end_byte_;
        while (true) {
            const int received = avcodec_receive_frame(&codec, frame_.get());
            if (received == 0) {
                const std::int64_t timestamp = frame_->best_effort_timestamp;
                if (timestamp == AV_NOPTS_VALUE || frame_->sample_rate != sample_rate_hz_) break;
                const std::optional<std::int64_t> start = frame_start(timestamp);
                if (!start) break;
                landing.start = *start;
                if (landing.start > target) break;
                if (landing.start + frame_->nb_samples > target) return landing;
                av_frame_unref(frame_.get());
                continue;
            }
            if (received == AVERROR(ENOMEM)) throw std::bad_alloc();
            if (received == AVERROR_EOF || !send_landing_packet(format, stream, codec, landing))
                return std::nullopt;
        }
        av_frame_unref(frame_.get());
        return std::nullopt;
    }

    // Sends `codec` the next packet of `stream`, noting its bytes and length in `landing`; false at
    // the end or where the demuxer fails. Packets the decoder refuses in its first frames after the
    // seek (an MP3 frame whose bit reservoir lies before it) fall in the preroll: what it holds
    // settles the decoder.
    bool send_landing_packet(AVFormatContext& format, const AVStream& stream, AVCodecContext& codec,
                             SeekLanding& landing) {
        int got = 0;
        while ((got = av_read_frame(&format, packet_.get())) >= 0) {
            ++landing.packets_read;
            if (packet_->pos >= 0)
                landing.packets_end_byte = std::max(landing.packets_end_byte, packet_->pos + packet_->size);
            if (packet_->stream_index == stream.index) break;
            av_packet_unref(packet_.get());
        }
        if (got < 0) return false;
        landing.next_packet_byte = packet_->pos >= 0 ? packet_->pos + packet_->size : -1;
        landing.last_packet_duration = packet_->duration;
        const int sent = avcodec_send_packet(&codec, packet_.get());
        av_packet_unref(packet_.get());
        if (sent == AVERROR(ENOMEM)) throw std::bad_alloc();
        return true;
    }

    // Puts the samples of the frame a seek landed on (frame_) from `target` on in pending_, through
    // the reading's mixer; false where they cannot be converted, the reading as it was.
    bool mix_landing_frame(SeekLanding& landing, std::int64_t target) {
        if (!mixer_.takes(*frame_)) {
            av_frame_unref(frame_.get());
            return false;
        }
        std::vector<float> landed;
        const int converted = mixer_.mix(*frame_, static_cast<std::size_t>(target - landing.start), landed);
        av_frame_unref(frame_.get());
        if (converted < 0) return false;
        pending_ = std::move(landed);
        pending_position_ = 0;
        landing.frames = converted;
        return true;
    }

    // The reading's counts once it stands at `frame`, on the frame `landing` found.
    void take_landing(const SeekLanding& landing, std::size_t frame) {
        const std::int64_t decoded_before = static_cast<std::int64_t>(frames_decoded_);
        const std::int64_t decoded = landing.start + landing.frames;
        frames_decoded_ = static_cast<std::size_t>(decoded);
        frames_to_skip_ = 0;
        frames_given_ = frame;
        first_packet_sent_ = true;
        packets_end_byte_ = landing.packets_end_byte;
        next_packet_byte_ = landing.next_packet_byte;
        last_packet_frames_ = packet_frames(landing.last_packet_duration);
        last_packet_is_pause_ = false;
        last_packet_is_mp3_tag_ = false;
        short_mp3_frame_.reset();
        // A variable-rate MP3's samples up to the last packet, as its table of contents counts them.
        mp3_frames_before_ += static_cast<double>(decoded - decoded_before);
    }

    // Opens the file into format_ and reads its streams' parameters.
    void open_format() {
        if (reading_.overlong_ogg_page_byte >= 0)
            hiding_reader_ = std::make_unique<HidingReader>(path_, reading_.overlong_ogg_page_byte);
        format_ = opened_format(hiding_reader_ ? hiding_reader_->context() : nullptr);
    }

    // The file opened by FFmpeg, its streams' parameters read; through `reader` where it is not null.
    std::unique_ptr<AVFormatContext, FormatCloser> opened_format(AVIOContext* reader) const {
        AVDictionary* options = nullptr;
        av_dict_set(&options, "format_whitelist", kFormats, 0);
        av_dict_set(&options, "protocol_whitelist", "file", 0);
        if (reading_.reads_past_stated_size) av_dict_set(&options, "ignore_length", "1", 0);
        AVFormatContext* raw = nullptr;
        if (reader != nullptr) {
            raw = avformat_alloc_context();
            if (raw == nullptr) throw std::bad_alloc();
            raw->pb = reader;
            raw->flags |= AVFMT_FLAG_CUSTOM_IO;
        }
        const int opened = avformat_open_input(&raw, path_.c_str(), nullptr, &options);
        av_dict_free(&options);
        if (opened < 0) {
            if (opened == AVERROR(ENOENT) || opened == AVERROR(EACCES) || opened == AVERROR(EISDIR))
                throw FileError(path_, ffmpeg_error_text(opened));
            if (is_mp4_without_index(path_))
                throw FileError(path_,
                                "truncated: an MP4/M4A/MOV file without its index (the moov box), which "
                                "recorders and encoders write last; the file was cut while it was copied "
                                "or recorded, or is still being written");
            // A damaged Ogg page's file fails here too ("Invalid data" where the page held a header):
            // throw_header_ends names the page.
            if (opened == AVERROR(EIO) || opened == AVERROR_EOF || reading_.damaged_ogg_page_byte >= 0 ||
                ends_inside_ebml_header(path_) || ends_within_first_mp3_frames(path_))
                throw_header_ends();
            throw unreadable_index_or_not_audio(ffmpeg_error_text(opened));
        }
        std::unique_ptr<AVFormatContext, FormatCloser> format(raw);
        if (const int found = avformat_find_stream_info(format.get(), nullptr); found < 0) {
            if (found == AVERROR(EIO) || found == AVERROR_EOF) throw_header_ends();
            throw unreadable_index_or_not_audio(ffmpeg_error_text(found));
        }
        return format;
    }

    // The streams that are sound tracks (a cover picture is no stream of sound), in the file's order.
    std::vector<int> sound_tracks() const {
        std::vector<int> tracks;
        for (unsigned i = 0; i < format_->nb_streams; ++i)
            if (format_->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_AUDIO)
                tracks.push_back(static_cast<int>(i));
        return tracks;
    }

    // Of several sound tracks, the one that sounds most like speech (TrackHearing), heard up to
    // kTrackHearingS into each: FFmpeg's choice, `best` (the default track), unless it is silent
    // or another has kSpeechOverDefaultRatio times its share of low-energy frames (a track voiced
    // too seldom to be speech, a drum kit's, counting none). The user is told which was read, that
    // there are others, and how to align another.
    int choose_sound_track(int best) {
        const std::vector<int> tracks = sound_tracks();
        std::vector<std::unique_ptr<TrackHearing>> hearings;
        for (const int track : tracks)
            hearings.push_back(std::make_unique<TrackHearing>(*format_->streams[track]));
        std::unique_ptr<AVPacket, PacketFreer> packet(av_packet_alloc());
        if (!packet) throw std::bad_alloc();
        const auto listening = [&] {
            return std::any_of(hearings.begin(), hearings.end(),
                               [](const auto& hearing) { return hearing->listening(); });
        };
        while (listening() && av_read_frame(format_.get(), packet.get()) >= 0) {
            const auto at = std::find(tracks.begin(), tracks.end(), packet->stream_index);
            if (at != tracks.end()) hearings[static_cast<std::size_t>(at - tracks.begin())]->hear(*packet);
            av_packet_unref(packet.get());
        }
        const auto best_at =
            static_cast<std::size_t>(std::find(tracks.begin(), tracks.end(), best) - tracks.begin());
        std::vector<TrackSummary> heard;
        for (const auto& hearing : hearings) heard.push_back(hearing->summary());
        std::size_t chosen = best_at;
        for (std::size_t i = 0; i < tracks.size(); ++i) {
            if (heard[i].is_silent) continue;
            const double share = heard[i].speech_share();
            if (heard[chosen].is_silent ||
                (share > heard[chosen].speech_share() &&
                 (heard[best_at].is_silent ||
                  share > kSpeechOverDefaultRatio * heard[best_at].speech_share())))
                chosen = i;
        }
        std::string reason;
        if (chosen != best_at)
            reason = heard[best_at].is_silent
                         ? ", for the " + ordinal_text(best_at) + " is silent"
                         : ", for it sounds more like speech than the " + ordinal_text(best_at);
        std::string others;
        std::size_t other_count = 0;
        for (std::size_t i = 0; i < tracks.size(); ++i) {
            if (i == chosen || (i == best_at && !reason.empty())) continue;
            others += (others.empty() ? "the " : ", the ") + ordinal_text(i) +
                      (heard[i].is_silent ? " (silent)" : "");
            ++other_count;
        }
        if (other_count > 0) others = (other_count == 1 ? "; the other: " : "; the others: ") + others;
        add_note("it has " + std::to_string(tracks.size()) + " sound tracks: the " + ordinal_text(chosen) +
                 " was read" + reason + others +
                 "; to align another, take it out first: ffmpeg -i FILE -map 0:a:N track.wav (N: 0 for the "
                 "first)");
        return tracks[chosen];
    }

    // Also says of a file that is an ID3 tag and nothing after it, or whose tag states more bytes
    // than the file holds (a damaged tag hides the sound after it), where FFmpeg said only
    // "Invalid argument".
    ParseError not_audio(const std::string& reason) const {
        std::error_code size_error;
        const auto file_bytes = std::filesystem::file_size(path_, size_error);
        std::string head(10, '\0');
        if (std::FILE* file = size_error ? nullptr : std::fopen(path_.c_str(), "rb")) {
            head.resize(std::fread(head.data(), 1, head.size(), file));
            std::fclose(file);
        }
        if (const std::size_t tag_end = after_id3(head); tag_end > 0 && tag_end >= file_bytes)
            return ParseError(
                path_, 0, 0, "",
                "an MP3's ID3 tag (the title, artist and picture at its start) states " +
                    std::to_string(tag_end) + " bytes" +
                    (tag_end > file_bytes ? ", more than the file's " + std::to_string(file_bytes)
                                          : std::string()) +
                    ", and no sound follows it: the tag is damaged or the file holds only the tag");
        return ParseError(
            path_, 0, 0, "",
            "not audio talkface can read (WAV, FLAC, Ogg, MP3, AAC/M4A, Opus, AMR, or the sound track of an "
            "MP4, MOV, MKV, WebM, MPEG-TS or MPEG video): " +
                reason);
    }

    // What is wrong with an MP4-family file (MP4, M4A, MOV, 3GP) whose index (the moov box, at its
    // start in a file written for streaming, "faststart") breaks inside its box structure, as a
    // scratch or a bad sector there leaves it: "the file is damaged: its index (...) breaks at byte
    // N". FFmpeg then finds no sound track ("a video without a sound track" was said of a damaged
    // one), finds "Invalid data", or indexes less sound than the file states. Empty for any other
    // file. Only asked once something has failed.
    std::string broken_index() const {
        const std::optional<Mp4Index> index = find_mp4_index(path_);
        if (!index || !index->broken_at_byte) return {};
        return "the file is damaged: its index (the moov box, bytes " + std::to_string(index->start_byte) + "-" +
               std::to_string(index->end_byte) + ", which says where its sound and picture lie) breaks at byte " +
               std::to_string(*index->broken_at_byte);
    }

    // FFmpeg cannot open a file: an MP4-family file with an index whose boxes hold together but
    // whose tables FFmpeg refuses ("Invalid data": a scratch inside the table of sample sizes) is
    // damaged there, as one whose boxes break is; anything else is no audio talkface reads.
    ParseError unreadable_index_or_not_audio(const std::string& reason) const {
        if (const std::string damage = broken_index(); !damage.empty())
            return ParseError(path_, 0, 0, "", damage + " (" + reason + ")");
        if (const std::optional<Mp4Index> index = find_mp4_index(path_))
            return ParseError(path_, 0, 0, "",
                              "its index (the moov box, bytes " + std::to_string(index->start_byte) + "-" +
                                  std::to_string(index->end_byte) + ", which says where its sound and picture lie) "
                                  "cannot be read: " + reason + "; the file is damaged there, or was written by a "
                                  "program FFmpeg does not read");
        return not_audio(reason);
    }

    // A reader that runs out of bytes inside the container's header (Matroska says "Input/output
    // error", others "End of file"): a file cut to its first bytes, as a copy or a download that
    // stopped leaves it. Said so, with the file's size, rather than as FFmpeg's bare words; but an
    // Ogg file whose header pages fail their check ends there too, and is damaged, not cut.
    [[noreturn]] void throw_header_ends() const {
        if (reading_.damaged_ogg_page_byte >= 0)
            throw ParseError(path_, 0, 0, "",
                             "the file is damaged: its Ogg pages break at byte " +
                                 std::to_string(reading_.damaged_ogg_page_byte) +
                                 " (a page that fails its check, or one missing: a scratch, or bytes lost), "
                                 "and no sound can be read without the stream's header held there");
        std::error_code size_error;
        const auto bytes = std::filesystem::file_size(path_, size_error);
        const std::string size = size_error ? std::string() : " after " + std::to_string(bytes) + " bytes";
        throw FileError(path_, "truncated: the file ends" + size +
                                   ", inside its header, before any sound; it "
                                   "was cut while it was copied or recorded");
    }

    // The container's length (the stream's, else the whole file's); at least 1, since progress
    // divides by it. Only an estimate: reading goes on to the real end.
    std::size_t estimate_frames() const {
        double seconds = 0.0;
        if (stream_->duration != AV_NOPTS_VALUE && stream_->duration > 0)
            seconds = static_cast<double>(stream_->duration) * av_q2d(stream_->time_base);
        else if (format_->duration != AV_NOPTS_VALUE && format_->duration > 0)
            seconds = static_cast<double>(format_->duration) / AV_TIME_BASE;
        const double frames = std::min(seconds * sample_rate_hz_, 1e12);
        return std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(frames)));
    }

    // The length the container states exactly for the sound track, seconds; 0 where it only
    // guesses (an MP3 without a LAME tag: from its bit rate) or says nothing. A whole file's length
    // counts only where the sound is all it holds: a video's sound track may end before its picture.
    double stated_seconds() const {
        if (format_->duration_estimation_method == AVFMT_DURATION_FROM_BITRATE) return 0.0;
        if (stream_->duration != AV_NOPTS_VALUE && stream_->duration > 0)
            return static_cast<double>(stream_->duration) * av_q2d(stream_->time_base);
        if (const double tagged_s = matroska_track_seconds(*stream_); tagged_s > 0.0) return tagged_s;
        if (format_->nb_streams == 1 && format_->duration != AV_NOPTS_VALUE && format_->duration > 0)
            return static_cast<double>(format_->duration) / AV_TIME_BASE;
        return 0.0;
    }

    // A Matroska track's length as its DURATION tag states it ("00:00:03.098000000"), which
    // FFmpeg's muxer and mkvmerge write for every track (Matroska has no per-track duration field);
    // 0 where there is none (a browser's MediaRecorder writes no length at all).
    double matroska_track_seconds(const AVStream& stream) const {
        if (std::strncmp(format_->iformat->name, "matroska", 8) != 0) return 0.0;
        const AVDictionaryEntry* tag = av_dict_get(stream.metadata, "DURATION", nullptr, 0);
        if (tag == nullptr) return 0.0;
        unsigned hours = 0, minutes = 0;
        double seconds = 0.0;
        if (std::sscanf(tag->value, "%u:%u:%lf", &hours, &minutes, &seconds) != 3 || minutes >= 60 || seconds < 0.0 ||
            seconds >= 60.0)
            return 0.0;
        return hours * 3600.0 + minutes * 60.0 + seconds;
    }

    // Whether a Matroska demuxer stopped short of its sound's end because the file is damaged
    // there, not cut: a scratch inside a cluster makes it skip the rest of that cluster, and a file
    // of one cluster (FFmpeg's default clusters are 5 s: a short clip, a voice message) or a scratch
    // in the last one loses the rest of its sound with nothing after it to say where it belonged.
    // Told from a cut file by the bytes left after the last packet read: a cut file ends where its
    // packets do, a damaged one still holds the bytes of what is missing (at least half of what the
    // missing time takes at the file's own rate). Its end is the track's stated length, else the
    // file's (only an upper bound where a video's sound ends before its picture).
    double damaged_matroska_end_seconds() const {
        if (std::strncmp(format_->iformat->name, "matroska", 8) != 0 || packets_end_byte_ < 0) return 0.0;
        const double file_s = format_->duration != AV_NOPTS_VALUE && format_->duration > 0
                                  ? static_cast<double>(format_->duration) / AV_TIME_BASE
                                  : 0.0;
        const double end_s = stated_seconds_ > 0.0 ? stated_seconds_ : file_s;
        const std::int64_t file_bytes = avio_size(format_->pb);
        const double missing_s = end_s - seconds_read();
        if (file_s <= 0.0 || file_bytes <= 0 || missing_s <= std::max(kLengthSlackS, kLengthSlackShare * end_s))
            return 0.0;
        const double unread_bytes = static_cast<double>(file_bytes - packets_end_byte_);
        const double missing_bytes = missing_s * static_cast<double>(file_bytes) / file_s;
        return unread_bytes >= 0.5 * missing_bytes ? end_s : 0.0;
    }

    // At the end of the data: a sound track well short of the length its container states was cut
    // off (a download or a copy that stopped), as a WAV whose data ends early is (audio_source.cpp).
    // Said, not aligned: half a recording would fail against its whole transcript with a message
    // about the text. Codecs pad or trim a few frames at each end, far inside the allowance.
    void check_whole() const {
        if (stated_seconds_ <= 0.0) return;
        const double decoded_s = seconds_read();
        if (decoded_s >= stated_seconds_ - std::max(kLengthSlackS, kLengthSlackShare * stated_seconds_)) return;
        if (const std::string damage = broken_index(); !damage.empty())
            throw ParseError(path_, 0, 0, "", damage + ", and the sound it indexes ends at " + seconds_text(decoded_s) +
                                                   " of the " + seconds_text(stated_seconds_) + " it states");
        throw cut_short();
    }

    FileError cut_short() const {
        return FileError(path_, "truncated: its header says the sound lasts " +
                                    seconds_text(stated_seconds_) + " but the data ends at " +
                                    seconds_text(seconds_read()));
    }

    // Whether the packets read reach the end of the file, or none was read.
    bool packets_reach_file_end() const {
        const std::int64_t file_bytes = avio_size(format_->pb);
        return packets_end_byte_ < 0 || (file_bytes > 0 && packets_end_byte_ >= file_bytes);
    }

    // At the end of the data, once: what the user should know of a file read whole that its header
    // or its last frame belies. An MP3 whose last packet is shorter than its frame's header states,
    // ending where the file does, was cut in the middle of that frame (a download or a copy that
    // stopped): nothing else says so where no LAME tag states the length, and a transcript of the
    // whole recording was aligned into the part left, silently. A sound track that lasts longer
    // than its header states (a LAME tag or an MP4's track header written before the recording
    // ended), or a file of one track whose header states longer than that track's own index holds
    // (an MP4's movie header left from before an edit), is read whole and said.
    void note_length_at_end() {
        if (end_noted_) return;
        end_noted_ = true;
        // The sound track's length as given out: seconds_read() counts an encoder's delay cut from its
        // start; the silence before a late sound track (keep_picture_lead) is the picture's, not the track's.
        const double decoded_s = static_cast<double>(frames_given_ - picture_lead_frames_) / sample_rate_hz_;
        if (short_mp3_frame_ && short_mp3_frame_->end_byte >= avio_size(format_->pb))
            add_note(
                "its last MP3 frame is cut short: its header states " +
                std::to_string(short_mp3_frame_->stated_bytes) + " bytes, the file ends after " +
                std::to_string(short_mp3_frame_->held_bytes) + " of them, at " + seconds_text(decoded_s) +
                ": the file was cut while it was copied, downloaded or recorded, and the sound after that "
                "time is missing; a transcript that goes on past it was aligned into what is left");
        const auto slack_s = [](double stated_s) {
            return std::max(kLengthSlackS, kLengthSlackShare * stated_s);
        };
        // A WAV read past its stated size is said so by its opener (describe_stale_size); an Ogg or
        // Matroska file's second recording, whose first's length was stated, by the join's warning
        // (describe_second_stream).
        if (stated_seconds_ > 0.0 && !reading_.reads_past_stated_size &&
            decoded_s > stated_seconds_ + slack_s(stated_seconds_) && !chained_stream(path_))
            add_note("its header states " + seconds_text(stated_seconds_) + " of sound, the file holds " +
                     seconds_text(decoded_s) + "; read to the end of the file");
        const double file_s = format_->nb_streams == 1 && format_->duration != AV_NOPTS_VALUE &&
                                      format_->duration > 0 &&
                                      format_->duration_estimation_method != AVFMT_DURATION_FROM_BITRATE
                                  ? static_cast<double>(format_->duration) / AV_TIME_BASE
                                  : 0.0;
        if (file_s > decoded_s + slack_s(file_s) && decoded_s >= stated_seconds_ - slack_s(stated_seconds_))
            add_note("its header states " + seconds_text(file_s) +
                     " for the file, but its sound track's own index holds " + seconds_text(decoded_s) +
                     ", all of which was read");
        const double longest_track_s = longest_track_seconds();
        const double stated_file_s = static_cast<double>(format_->duration) / AV_TIME_BASE;
        if (longest_track_s > 0.0 && format_->duration != AV_NOPTS_VALUE &&
            stated_file_s > longest_track_s + slack_s(stated_file_s))
            add_note("its header states " + seconds_text(stated_file_s) + " for the file, but its " +
                     std::to_string(format_->nb_streams) + " tracks' own lengths reach only " +
                     seconds_text(longest_track_s) + " (its sound track " + seconds_text(decoded_s) +
                     ", all of which was read): the header's length is damaged");
        note_second_file(decoded_s);
    }

    // The longest of a file's several tracks (a video's picture and sound), each by its own index or
    // its Matroska DURATION tag: a video's picture may outlast its sound, but no track lasts longer
    // than this, so a file's stated length well past it was damaged (a movie header or a Segment's
    // Duration overwritten), which a file of one track is told by above. 0 where the file holds one
    // track, or a track states no length of its own (a cover picture, a browser's recording).
    double longest_track_seconds() const {
        if (format_->nb_streams < 2) return 0.0;
        double longest_s = 0.0;
        for (unsigned i = 0; i < format_->nb_streams; ++i) {
            const AVStream& stream = *format_->streams[i];
            double seconds = matroska_track_seconds(stream);
            if (stream.duration != AV_NOPTS_VALUE && stream.duration > 0)
                seconds = static_cast<double>(stream.duration) * av_q2d(stream.time_base);
            if (seconds <= 0.0) return 0.0;
            longest_s = std::max(longest_s, seconds);
        }
        return longest_s;
    }

    // An MP4-family file followed by a second one (second_file_byte): what was not read, said.
    void note_second_file(double decoded_s) {
        if (!starts_with(format_->iformat->name, "mov")) return;
        const std::optional<std::uint64_t> second_byte = second_file_byte(path_);
        const std::int64_t file_bytes = avio_size(format_->pb);
        if (!second_byte || file_bytes <= static_cast<std::int64_t>(*second_byte)) return;
        const std::uint64_t unread_bytes = static_cast<std::uint64_t>(file_bytes) - *second_byte;
        add_note(
            "the file goes on past its end: a second MP4 file (its own ftyp box) begins at byte " +
            std::to_string(*second_byte) + ", as when two recordings or two copies of one are joined; its " +
            std::to_string(unread_bytes) + " bytes (about " +
            seconds_text(decoded_s * static_cast<double>(unread_bytes) / static_cast<double>(*second_byte)) +
            " of sound, if it holds sound as the first does) were not read; only the first was aligned");
    }

    // Follows whether an MP3 packet holds fewer bytes than its frame's header states (short_mp3_frame_).
    void follow_mp3_frame_size(const AVPacket& packet) {
        short_mp3_frame_.reset();
        if (stream_->codecpar->codec_id != AV_CODEC_ID_MP3 || packet.data == nullptr || packet.size <= 0 ||
            packet.pos < 0)
            return;
        const std::optional<Mp3FrameHeader> header = read_mp3_frame_header(std::string_view(
            reinterpret_cast<const char*>(packet.data), static_cast<std::size_t>(packet.size)));
        const auto held = static_cast<std::size_t>(packet.size);
        if (header && header->bytes > held)
            short_mp3_frame_ = ShortFrame{header->bytes, held, packet.pos + packet.size};
    }

    // At the end of a file known to be damaged inside: the sound short of the length its container
    // states was lost with the damaged pages (the container's last page is whole: a cut file is
    // refused before it gets here), and is kept as silence. True if there was such sound to fill.
    bool fill_lost_end() {
        if (end_filled_) return false;
        end_filled_ = true;
        const double end_s = reading_.keeps_stated_length ? stated_seconds_ : damaged_matroska_end_seconds();
        if (end_s <= 0.0) return false;
        const double missing_frames = end_s * sample_rate_hz_ - static_cast<double>(frames_decoded_);
        if (missing_frames <= kTimestampSlackS * sample_rate_hz_) return false;
        // The lost pages are bytes of the file, as the pages read are: a header stating far more than
        // they could hold is damaged too (an Ogg stream's last granule scratched with a page before
        // it stated 2^40 samples, whose silence was one allocation of 4 TB).
        if (missing_frames > kMostLostEndShare * static_cast<double>(frames_decoded_))
            throw ParseError(path_, 0, 0, "",
                             "the file is damaged: its header states " + seconds_text(end_s) +
                                 " of sound, but the pages that can be read hold " +
                                 seconds_text(seconds_read()) + ", and no damage loses " +
                                 std::to_string(static_cast<int>(kMostLostEndShare)) +
                                 " times the sound it leaves: the stated length is damaged too");
        pending_.clear();
        pending_position_ = 0;
        skipped_frames_ += static_cast<std::size_t>(std::llround(missing_frames));
        skipped_is_damage_ = true;
        fill_skipped_time();
        return true;
    }

    // Decodes the next frame of the sound track into pending_ (mono); false at the end.
    bool decode_next_frame() {
        while (true) {
            const int received = avcodec_receive_frame(codec_.get(), frame_.get());
            if (received == 0) {
                skip_to_timestamp(*frame_);
                mix_down(*frame_);
                const std::size_t frame_samples = pending_.size();
                av_frame_unref(frame_.get());
                fill_skipped_time();
                // AMR-WB's decoder writes an empty pause frame's silence itself (a frame a packet;
                // the pause frames it refuses, and AMR-NB's, are refuse_packet's): a pause too.
                if (last_packet_is_pause_ && frame_samples > 0)
                    note_codec_pause(frames_given_ + silence_ahead_, frame_samples);
                if (!pending_.empty() || silence_ahead_ > 0) return true;
                continue;
            }
            if (received == AVERROR_EOF) {
                // A recording that ends in undecodable packets still lasts to its end, once any
                // sound came before; one that holds nothing else decodes to no samples.
                if (frames_decoded_ == 0) return false;
                pending_.clear();
                pending_position_ = 0;
                fill_skipped_time();
                return silence_ahead_ > 0;
            }
            if (received == AVERROR(ENOMEM)) throw std::bad_alloc();
            // Some decoders refuse a damaged packet here rather than when it is sent.
            if (received != AVERROR(EAGAIN)) refuse_packet(received, last_packet_frames_);
            if (!send_next_packet()) return false;
        }
    }

    // Feeds the decoder the next packet of the sound track, or the end; false once the end was sent.
    bool send_next_packet() {
        if (flushed_) return false;
        while (true) {
            const int got = av_read_frame(format_.get(), packet_.get());
            if (got >= 0) ++packets_read_;
            if (got == AVERROR_EOF) {
                avcodec_send_packet(codec_.get(), nullptr);
                flushed_ = true;
                return true;
            }
            if (got < 0) throw ParseError(path_, 0, 0, "", "cannot read past " + seconds_text(seconds_read()) + ": " +
                                                                ffmpeg_error_text(got));
            if (packet_->pos >= 0) packets_end_byte_ = std::max(packets_end_byte_, packet_->pos + packet_->size);
            if (packet_->stream_index != stream_->index) {
                av_packet_unref(packet_.get());
                continue;
            }
            if (!first_packet_sent_) cut_unstated_delay(*packet_);
            first_packet_sent_ = true;
            follow_mp3_frame_size(*packet_);
            last_packet_is_mp3_tag_ = is_mp3_tag_packet(*packet_);
            const std::size_t lost_frames = mp3_bytes_lost(*packet_);
            const int sent = avcodec_send_packet(codec_.get(), packet_.get());
            last_packet_frames_ = packet_frames(packet_->duration);
            if (lost_frames > 0) {
                // The timestamps after it do not count this time: time 0 moves with it.
                skipped_frames_ += lost_frames;
                skipped_is_damage_ = true;
                time_zero_frames_ -= static_cast<std::int64_t>(lost_frames);
            }
            last_packet_is_pause_ = is_amr_pause(*packet_);
            av_packet_unref(packet_.get());
            if (sent == AVERROR(ENOMEM)) throw std::bad_alloc();
            if (sent < 0) {
                refuse_packet(sent, last_packet_frames_);
                continue;
            }
            return true;
        }
    }

    // The sound track's first packet: a stream in a container that cannot state the encoder's
    // delay starts with the delay, which is cut (unstated_delay_frames), unless FFmpeg marks
    // samples to skip on it.
    void cut_unstated_delay(const AVPacket& packet) {
        if (av_packet_get_side_data(&packet, AV_PKT_DATA_SKIP_SAMPLES, nullptr) != nullptr) return;
        if (const std::size_t delay = unstated_delay_frames(); delay > 0) frames_to_skip_ = delay;
    }

    // Every container but the MP4 family's states no delay (raw AAC, Matroska, AVI, MPEG
    // transport and program streams, bare MP2 and AC-3); an MP4's edit list states it (or, where
    // the sound starts after the picture, times it before the sound's start), and one whose whole
    // index holds none (a fragmented MP4, a browser's MediaRecorder's as FFmpeg writes it) does not.
    std::size_t unstated_delay_frames() const {
        if (starts_with(format_->iformat->name, "mov")) {
            const std::optional<Mp4Index> index = find_mp4_index(path_);
            if (!index || index->broken_at_byte || index->has_edit_list) return 0;
        }
        const AVCodecParameters* parameters = stream_->codecpar;
        switch (parameters->codec_id) {
            case AV_CODEC_ID_AAC:
                return parameters->profile == FF_PROFILE_AAC_LOW ? kAacFrameOverlapFrames : 0;
            case AV_CODEC_ID_MP2:
                return kMp2FilterBankDelayFrames;
            case AV_CODEC_ID_AC3:
            case AV_CODEC_ID_EAC3:
                return kAc3BlockOverlapFrames;
            default:
                return 0;
        }
    }

    ParseError decode_error(int code) const {
        return ParseError(path_, 0, 0, "", "the sound track cannot be decoded at " + seconds_text(seconds_read()) + ": " +
                                                ffmpeg_error_text(code));
    }

    double seconds_read() const { return static_cast<double>(frames_decoded_) / sample_rate_hz_; }

    // A packet the decoder refuses is skipped, as players do (a scratch in an MP3 is a click, not
    // the end): damaged (decoders say so in many words: "invalid data", or AAC's bare -1, which
    // reads "operation not permitted"), or of a kind this FFmpeg does not decode (AMR's
    // comfort-noise frames, which phones send in pauses, are "not yet implemented"). Its time is
    // kept as silence, or every syllable after it would be timed early.
    void refuse_packet(int error, std::size_t frames) {
        skipped_frames_ += frames;
        last_refusal_ = error;
        // What this FFmpeg does not decode (AMR's comfort noise, "not yet implemented"), AMR's
        // empty pause frames (which it calls invalid) and a second MP3 recording's header frame are
        // no damage: the file is whole.
        if (error != AVERROR_PATCHWELCOME && !last_packet_is_pause_ && !last_packet_is_mp3_tag_ && frames > 0)
            skipped_is_damage_ = true;
        if (frames > 0) skipped_is_pause_ = skipped_is_pause_ && last_packet_is_pause_;
    }

    // An AMR frame a phone sends in a pause instead of speech (discontinuous transmission): a
    // comfort-noise description (SID: frame type 8 in AMR-NB, 9 in AMR-WB) or nothing at all
    // (NO_DATA, type 15). The type is bits 3-6 of the frame's first byte (RFC 4867, 5.3).
    bool is_amr_pause(const AVPacket& packet) const {
        if (packet.size < 1 || packet.data == nullptr) return false;
        const int type = (packet.data[0] >> 3) & 0x0F;
        if (stream_->codecpar->codec_id == AV_CODEC_ID_AMR_NB) return type == 8 || type == 15;
        if (stream_->codecpar->codec_id == AV_CODEC_ID_AMR_WB) return type == 9 || type == 15;
        return false;
    }

    // An MP3 packet that is a recording's header frame (is_mp3_tag_frame), its ID3 tag before it
    // (FFmpeg's parser joins the tag to the frame): the first recording's own is read as its header,
    // and one later is a second recording's (`cat` of two files FFmpeg's LAME wrote), which the
    // decoder refuses, having no sound in it. The join is named apart (describe_second_stream); the
    // frame was called damaged, "0.036 s of its sound could not be decoded", beside it.
    bool is_mp3_tag_packet(const AVPacket& packet) const {
        if (stream_->codecpar->codec_id != AV_CODEC_ID_MP3 || packet.data == nullptr || packet.size < 4)
            return false;
        std::string_view bytes(reinterpret_cast<const char*>(packet.data),
                               static_cast<std::size_t>(packet.size));
        bytes.remove_prefix(std::min(after_id3(bytes), bytes.size()));
        const auto header = read_mp3_frame_header(bytes);
        return header && is_mp3_tag_frame(bytes, *header);
    }

    // The time, in samples, of the bytes of an MP3 stream that no frame holds, up to and with
    // `packet`: a scratch inside an MP3 leaves bytes FFmpeg's parser finds no frame in, which it
    // skips, joins to the packet before them, or cuts into packets of any size at a false frame
    // header; an MP3 stream's timestamps count packets, not bytes, so the scratch's time vanished
    // (every syllable after it came early, and a file whose LAME tag states its length was called
    // truncated). At a constant bit rate, the rate recorders and phones write, every byte takes
    // its time: the bytes between packets and each packet's bytes beyond or short of its frame's
    // are summed, and given out as lost once they reach kTimestampSlackS (a frame's padding byte
    // is a fraction of a millisecond and evens out). A variable rate (packets of other sizes
    // among the first kMp3PacketsToJudgeRate) gives its frames any size: there only the bytes
    // between packets and those of a packet larger than any MP3 frame count, beyond a frame's:
    // their time is what the stream's table of contents (mp3_toc.hpp: a Xing or a VBRI header)
    // gives the bytes from the packet before to the end of this one, where it places the packets
    // before where they reach (toc_agrees_at); else an estimate at the rate of the
    // kMp3RecentPackets packets before them, which misses where the lost frames were larger or
    // smaller than those: the sweep's two scratches of a VBR MP3 (2000 bytes hitting frames of
    // 0.21 s) read as 0.23 and 0.34 s lost by the rate, where nothing was counted before (every
    // later syllable came 0.18 s early).
    // 0 for every other codec.
    std::size_t mp3_bytes_lost(const AVPacket& packet) {
        const std::int64_t next_byte = next_packet_byte_;
        next_packet_byte_ = packet.pos >= 0 ? packet.pos + packet.size : -1;
        const std::int64_t bit_rate = stream_->codecpar->bit_rate;
        if (stream_->codecpar->codec_id != AV_CODEC_ID_MP3 || bit_rate <= 0 || packet.pos < 0 || next_byte < 0)
            return 0;
        const double frames_per_byte = 8.0 * sample_rate_hz_ / static_cast<double>(bit_rate);
        const auto packet_length = static_cast<double>(packet_frames(packet.duration));
        const double frame_bytes = packet_length / frames_per_byte;
        const double bytes_between = static_cast<double>(packet.pos - next_byte);
        // A second recording's header frame (is_mp3_tag_packet) is bytes of no sound, at a bit rate of
        // its own, its ID3 tag with it (FFmpeg's LAME: 45 bytes of tag and a frame of 180 where the
        // sound's take 108, read as 39 ms lost).
        if (last_packet_is_mp3_tag_) {
            mp3_frames_before_ += packet_length;
            return 0;
        }
        if (mp3_packets_judged_ < kMp3PacketsToJudgeRate) {
            ++mp3_packets_judged_;
            mp3_rate_is_constant_ &= packet.pos == next_byte && std::fabs(packet.size - frame_bytes) <= 1.0;
            follow_toc(packet, packet_length);
        } else if (mp3_rate_is_constant_)
            mp3_lost_frames_ += (bytes_between + packet.size) * frames_per_byte - packet_length;
        else if (bytes_between > 0.0 || packet.size > kLargestMp3FrameBytes) {
            if (toc_agrees_at(next_byte)) {
                // Where a table's points lie on frames (VBRI), the stretch the packets reached is
                // placed by them, and only the scratch's end is read between points.
                const double start = mp3_toc_->points_on_frames && mp3_toc_followed_
                                         ? mp3_frames_before_ - mp3_toc_offset_
                                         : mp3_toc_->sample_at(next_byte);
                mp3_lost_frames_ +=
                    std::max(0.0, mp3_toc_->sample_at(packet.pos + packet.size) - start - packet_length);
            } else {
                // Bytes a sample over the recent packets, else the stream's average.
                const double recent_frames_per_byte =
                    mp3_recent_bytes_ > 0.0 ? mp3_recent_frames_ / mp3_recent_bytes_ : frames_per_byte;
                mp3_lost_frames_ += (bytes_between + packet.size) * recent_frames_per_byte - packet_length;
            }
        } else {
            follow_toc(packet, packet_length);
            mp3_recent_bytes_ += packet.size - mp3_recent_bytes_ / kMp3RecentPackets;
            mp3_recent_frames_ += packet_length - mp3_recent_frames_ / kMp3RecentPackets;
        }
        std::size_t lost = 0;
        if (mp3_lost_frames_ > kTimestampSlackS * sample_rate_hz_) {
            lost = static_cast<std::size_t>(std::llround(mp3_lost_frames_));
            mp3_lost_frames_ = 0.0;
        }
        // Whole numbers of samples, far below 2^53: the sum is exact.
        mp3_frames_before_ += packet_length + static_cast<double>(lost);
        return lost;
    }

    // Holds a variable-rate MP3's table of contents to a whole packet: at the last table point
    // inside it, the samples the packets reach (as mp3_frames_before_ counts them, the packet's
    // own linear in its bytes) less the table's sample there.
    void follow_toc(const AVPacket& packet, double packet_length) {
        if (!mp3_toc_ || packet.size <= 0) return;
        const std::vector<Mp3Toc::Point>& points = mp3_toc_->points;
        const auto start = static_cast<double>(packet.pos);
        const double end = start + packet.size;
        while (mp3_toc_point_ < points.size() && points[mp3_toc_point_].byte < start) ++mp3_toc_point_;
        for (; mp3_toc_point_ < points.size() && points[mp3_toc_point_].byte < end; ++mp3_toc_point_) {
            const Mp3Toc::Point& point = points[mp3_toc_point_];
            mp3_toc_offset_ =
                mp3_frames_before_ + (point.byte - start) / packet.size * packet_length - point.sample;
            mp3_toc_followed_ = true;
        }
    }

    // Whether a variable-rate MP3's table of contents (mp3_toc.hpp) places the byte `file_byte`
    // where the packets before it reach, within kMp3TocSlackShare of that: a header written
    // before its encoder finished, or the first of two files joined, states another stream.
    bool toc_agrees_at(std::int64_t file_byte) const {
        if (!mp3_toc_) return false;
        const double reached = mp3_frames_before_;
        return std::fabs(mp3_toc_->sample_at(file_byte) - reached) <=
               kMp3TocSlackShare * reached + kLengthSlackS * sample_rate_hz_;
    }

    // A packet's length in samples (its duration in the stream's time base), 0 where unknown.
    std::size_t packet_frames(std::int64_t duration) const {
        if (duration <= 0) return 0;
        const std::int64_t frames = av_rescale_q(duration, stream_->time_base, AVRational{1, sample_rate_hz_});
        return frames > 0 ? static_cast<std::size_t>(frames) : 0;
    }

    // A frame whose timestamp lies later than the samples before it reach: the packets between were
    // lost before the decoder saw them (a scratch inside an MKV or WebM loses the cluster it hits,
    // and the demuxer goes on at the next one, whose timestamp says where it belongs). The gap is
    // kept as silence, as a refused packet's time is. Time 0 is placed by the second frame: the
    // first may have lost its start to the codec's delay (an MP3's LAME tag, Opus's pre-skip) and
    // keep the timestamp of its whole. The first frame is held to where the stream says its sound
    // starts (keep_lost_start). A gap within kTimestampSlackS is a container's rounding
    // (Matroska's milliseconds), not a loss.
    void skip_to_timestamp(const AVFrame& frame) {
        const std::int64_t timestamp = frame.best_effort_timestamp;
        if (timestamp == AV_NOPTS_VALUE) return;
        const std::int64_t at = av_rescale_q(timestamp, stream_->time_base, AVRational{1, sample_rate_hz_});
        if (timed_frames_ < 2) {
            if (timed_frames_ == 0) keep_lost_start(at);
            // Packets refused between the first two frames are held to their timestamps as later
            // ones are (the first frame's may be off by a codec's delay, a few milliseconds).
            else if (skipped_frames_ > 0)
                keep_gap(at - (time_zero_frames_ + static_cast<std::int64_t>(frames_decoded_ + skipped_frames_)));
            ++timed_frames_;
            second_frame_at_ = static_cast<std::int64_t>(frames_decoded_ + skipped_frames_);
            time_zero_frames_ = at - second_frame_at_;
            return;
        }
        keep_gap(at - (time_zero_frames_ + static_cast<std::int64_t>(frames_decoded_ + skipped_frames_)));
    }

    // The first frame's timestamp against where the stream's sound starts, in a file damaged
    // before it: a scratch in the first frames (the first Ogg page of sound after Vorbis's headers,
    // the first AAC packets of an MP4) lost them, and the first frame decoded placed time 0, so
    // every syllable came early by what was lost (1 s after a lost Ogg page), or late where AAC
    // refused one packet more than it lost (64 ms). The start is the stream's start_time as FFmpeg
    // reads it from the container (an MP4's index), except in a damaged Ogg file
    // (FfmpegReading::keeps_stated_length), whose start FFmpeg takes from the first page it can
    // read: there it is 0, where an Ogg stream's granule positions begin. Only after damage (a
    // damaged Ogg file, packets refused before the first frame): in a whole file the first frame
    // may lie past start_time by a decoder's delay (WMA's by 64 ms), which the second frame's
    // placing of time 0 already takes out.
    void keep_lost_start(std::int64_t at) {
        std::int64_t start = 0;
        if (!reading_.keeps_stated_length) {
            if (stream_->start_time == AV_NOPTS_VALUE || skipped_frames_ == 0) return;
            start = av_rescale_q(stream_->start_time, stream_->time_base, AVRational{1, sample_rate_hz_});
        }
        keep_gap(at - (start + static_cast<std::int64_t>(frames_decoded_ + skipped_frames_)));
    }

    // A video whose sound track starts after its picture (a camera or a screen recorder that starts
    // its sound late, an editor's offset): players play silence until the sound starts, and the
    // times a user lays over the video, or a page plays with it (--audio-embed original), are the
    // picture's; counted from the sound's own start, every syllable came early by the offset (0.5 s
    // in the sweep's case). The sound's start as the container states it (to which keep_lost_start
    // holds a first frame after damage) is placed against the earliest start of a picture stream (a
    // cover picture in an MP3 or an M4A is none), the time before it read as silence, and the user
    // told.
    void keep_picture_lead() {
        if (stream_->start_time == AV_NOPTS_VALUE) return;
        std::int64_t picture_start = std::numeric_limits<std::int64_t>::max();
        for (unsigned i = 0; i < format_->nb_streams; ++i) {
            const AVStream* picture = format_->streams[i];
            if (picture->codecpar->codec_type != AVMEDIA_TYPE_VIDEO ||
                (picture->disposition & AV_DISPOSITION_ATTACHED_PIC) != 0 ||
                picture->start_time == AV_NOPTS_VALUE)
                continue;
            picture_start = std::min(picture_start, av_rescale_q(picture->start_time, picture->time_base,
                                                                 AVRational{1, sample_rate_hz_}));
        }
        if (picture_start == std::numeric_limits<std::int64_t>::max()) return;
        const std::int64_t lead =
            av_rescale_q(stream_->start_time, stream_->time_base, AVRational{1, sample_rate_hz_}) -
            picture_start;
        if (static_cast<double>(lead) <= kTimestampSlackS * sample_rate_hz_) return;
        // Nothing is given out yet: the lead goes before the first frame (and any silence before it).
        silence_ahead_ += static_cast<std::size_t>(lead);
        frames_decoded_ += static_cast<std::size_t>(lead);
        picture_lead_frames_ = static_cast<std::size_t>(lead);
        time_zero_frames_ -= lead;
        add_note("its sound track starts " + seconds_text(static_cast<double>(lead) / sample_rate_hz_) +
                 " after its picture; read as silence until then, so that the times are the video's");
    }

    // `gap`: how much later than the samples before it a frame's timestamp places it.
    void keep_gap(std::int64_t gap) {
        if (static_cast<double>(gap) > kTimestampSlackS * sample_rate_hz_) {
            skipped_frames_ += static_cast<std::size_t>(gap);
            skipped_is_damage_ = true;
        } else if (gap < 0 && skipped_frames_ > 0) {
            // The refused packets counted more time than the frame's timestamp leaves them: FFmpeg's
            // AAC decoder, fed a scratched MP4, refused 9 packets but lost only 8 (the 9th error
            // came with a frame), and every syllable after it came 64 ms late. The silence not yet
            // given out is cut to what the timestamp says.
            skipped_frames_ -= std::min(skipped_frames_, static_cast<std::size_t>(-gap));
            if (skipped_frames_ == 0) skipped_is_damage_ = false;
        }
    }

    // Puts the time of the packets skipped since the last frame, as silence, before pending_'s samples.
    void fill_skipped_time() {
        if (skipped_frames_ == 0) return;
        // The silence goes where read_frames() stands: after every frame given out so far.
        if (skipped_is_damage_) note_lost_audio(frames_given_, skipped_frames_);
        else if (skipped_is_pause_)
            note_codec_pause(frames_given_, skipped_frames_);
        silence_ahead_ += skipped_frames_;
        frames_decoded_ += skipped_frames_;
        skipped_frames_ = 0;
        skipped_is_damage_ = false;
        skipped_is_pause_ = true;
    }

    // The frame's samples, its channels averaged (FrameMixer), into pending_.
    void mix_down(const AVFrame& frame) {
        pending_.clear();
        pending_position_ = 0;
        if (frame.nb_samples <= 0) return;
        if (frame.sample_rate != sample_rate_hz_)
            throw ParseError(path_, 0, 0, "",
                             "the sample rate changes from " + std::to_string(sample_rate_hz_) + " to " +
                                 std::to_string(frame.sample_rate) + " Hz at " +
                                 seconds_text(seconds_read()));
        const int channels = frame.ch_layout.nb_channels;
        if (channels <= 0 || channels > kMaxChannels)
            throw ParseError(path_, 0, 0, "",
                             std::to_string(channels) + " channels at " + seconds_text(seconds_read()));
        if (!mixer_.takes(frame)) {
            const char* format = av_get_sample_fmt_name(static_cast<AVSampleFormat>(frame.format));
            throw ParseError(path_, 0, 0, "",
                             std::string("cannot convert its samples (") + (format ? format : "unknown format") +
                                 ") at " + seconds_text(seconds_read()));
        }
        const int converted = mixer_.mix(frame, frames_to_skip_, pending_);
        if (converted < 0) throw decode_error(converted);
        const auto count = static_cast<std::size_t>(converted);
        frames_to_skip_ -= std::min(frames_to_skip_, count);
        frames_decoded_ += count;
    }

    std::string path_;
    FfmpegReading reading_;
    bool end_filled_ = false;  // fill_lost_end() has run
    bool end_noted_ = false;   // note_length_at_end() has run
    // The last packet of an MP3 stream, where it holds fewer bytes than its frame's header states.
    struct ShortFrame {
        std::size_t stated_bytes = 0;
        std::size_t held_bytes = 0;
        std::int64_t end_byte = 0;  // where the packet ends in the file
    };
    std::optional<ShortFrame> short_mp3_frame_;
    // Before format_, which reads through it and is closed first.
    std::unique_ptr<HidingReader> hiding_reader_;
    std::unique_ptr<AVFormatContext, FormatCloser> format_;
    std::unique_ptr<AVCodecContext, CodecFreer> codec_;
    std::unique_ptr<AVPacket, PacketFreer> packet_;
    std::unique_ptr<AVFrame, FrameFreer> frame_;
    FrameMixer mixer_;
    AVStream* stream_ = nullptr;
    int sample_rate_hz_ = 0;
    std::size_t estimated_frames_ = 1;
    double stated_seconds_ = 0.0;
    std::size_t frames_decoded_ = 0;
    std::size_t frames_to_skip_ = 0;
    std::size_t skipped_frames_ = 0;  // the time of refused packets not yet put in silence_ahead_
    bool skipped_is_damage_ = false;  // some of skipped_frames_ is lost to damage, not a codec's gap
    bool last_packet_is_pause_ = false;  // the last packet sent is an AMR pause frame
    bool last_packet_is_mp3_tag_ = false;  // the last packet sent is an MP3 header frame (is_mp3_tag_packet)
    bool skipped_is_pause_ = true;       // every packet refused since the last frame is an AMR pause frame
    std::size_t frames_given_ = 0;    // frames read_frames() has returned
    std::size_t picture_lead_frames_ = 0;  // keep_picture_lead's silence before the sound
    int last_refusal_ = 0;            // the decoder's error for the last packet it refused
    std::size_t last_packet_frames_ = 0;  // the length of the last packet sent
    std::int64_t time_zero_frames_ = 0;  // a frame's timestamp in samples less the samples before it
    int timed_frames_ = 0;               // frames with a timestamp seen, up to the 2 that place time 0
    std::int64_t second_frame_at_ = 0;   // where the last of those starts, in the reading's counting
    std::int64_t packets_end_byte_ = -1;  // the furthest byte of the file a packet (of any stream) reached
    std::int64_t next_packet_byte_ = -1;  // where the last packet of the sound track ended in the file
    int mp3_packets_judged_ = 0;          // packets that judged whether an MP3's bit rate is constant
    bool mp3_rate_is_constant_ = true;
    double mp3_lost_frames_ = 0.0;        // an MP3's bytes no frame holds, as samples, not yet given out
    double mp3_recent_bytes_ = 0.0;       // a variable-rate MP3's recent packets' bytes (decaying sum)
    double mp3_recent_frames_ = 0.0;      // and their samples
    double mp3_frames_before_ = 0.0;      // an MP3's samples up to the last packet, lost ones with them
    std::optional<Mp3Toc> mp3_toc_;       // a variable-rate MP3's table of contents, if it has one
    std::size_t mp3_toc_point_ = 0;       // the first point of mp3_toc_ past the packets read
    double mp3_toc_offset_ = 0.0;         // the packets' samples less the table's at the last point passed
    bool mp3_toc_followed_ = false;       // a point of mp3_toc_ lay inside a whole packet
    bool flushed_ = false;
    bool first_packet_sent_ = false;  // of the sound track
    // The timestamp a seek placed the opening at (none: its start), and the packets of every stream
    // read since: where return_to_packets_read() brings a file opened again.
    std::optional<std::int64_t> opening_seek_at_;
    std::int64_t packets_read_ = 0;
    std::vector<float> pending_;
    std::size_t pending_position_ = 0;
    // Silence read_frames() gives out before pending_'s samples: a lost end or a gap can be hours
    // (a damaged length up to kMostLostEndShare times the sound read), given out as it is read, as
    // the samples are, rather than held at once.
    std::size_t silence_ahead_ = 0;
};

}  // namespace

std::unique_ptr<AudioSource> open_ffmpeg_file(const std::string& path, const FfmpegReading& reading) {
    return std::make_unique<FfmpegSource>(path, reading);
}

bool ffmpeg_is_loadable() {
    return true;
}

}  // namespace talkface::detail
