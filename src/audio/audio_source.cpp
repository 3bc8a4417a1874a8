#include "audio/audio_source.hpp"

#include <sndfile.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

#include "audio/ffmpeg_source.hpp"
#include "common/number_format.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

constexpr std::size_t kMaxChannels = 64;

std::string seconds_text(std::size_t frame, int sample_rate_hz) {
    return format_fixed(static_cast<double>(frame) / sample_rate_hz, 3) + " s";
}

// The data chunk's size as the header states it and as the file holds it.
struct DataBytes {
    std::size_t stated = 0;
    std::size_t present = 0;
};

// libsndfile shortens the frame count of a WAV/AIFF whose data chunk is cut off and only says so
// in its log ("data : 79912 (should be 19956)"): the header's promise, then what is there.
std::optional<DataBytes> data_bytes_if_truncated(SNDFILE* file) {
    char log[4096] = {};
    sf_command(file, SFC_GET_LOG_INFO, log, sizeof log);
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        const std::size_t should_be = line.find("(should be");
        if (line.rfind("data :", 0) != 0 || should_be == std::string::npos) continue;
        std::istringstream stated(line.substr(6)), present(line.substr(should_be + 10));
        unsigned long long stated_bytes = 0, present_bytes = 0;
        if (stated >> stated_bytes && present >> present_bytes)
            return DataBytes{static_cast<std::size_t>(stated_bytes), static_cast<std::size_t>(present_bytes)};
    }
    return std::nullopt;
}

// A data size a writer leaves when it cannot seek back to fill in the real one (FFmpeg writing a
// WAV to a pipe states 0xFFFFFFFF, "as long as it goes"; some cap it at the signed maximum): no
// promise that the file broke, so the data is read to the end of the file, as libsndfile's frame
// count already says. (A size left at 0 gives no frames at all: see open_audio_file.)
bool is_placeholder_size(std::size_t stated_bytes) { return stated_bytes == 0xFFFFFFFFu || stated_bytes == 0x7FFFFFFFu; }

// The frames a cut-off data chunk promised: its stated bytes over a frame's bytes, or for a codec
// of blocks (GSM 06.10, ADPCM), whose frames have no size of their own, the frames present scaled
// by how much more the header states than the file holds.
std::size_t frames_promised_by(const SF_INFO& info, std::size_t frame_bytes, const DataBytes& data) {
    if (frame_bytes > 0) return data.stated / frame_bytes;
    if (data.present == 0) return 0;
    return static_cast<std::size_t>(std::ceil(static_cast<double>(info.frames) * static_cast<double>(data.stated) /
                                              static_cast<double>(data.present)));
}

std::size_t bytes_per_frame(const SF_INFO& info) {
    int sample_bytes = 0;
    switch (info.format & SF_FORMAT_SUBMASK) {
        case SF_FORMAT_PCM_S8: case SF_FORMAT_PCM_U8: case SF_FORMAT_ULAW: case SF_FORMAT_ALAW:
            sample_bytes = 1; break;
        case SF_FORMAT_PCM_16: sample_bytes = 2; break;
        case SF_FORMAT_PCM_24: sample_bytes = 3; break;
        case SF_FORMAT_PCM_32: case SF_FORMAT_FLOAT: sample_bytes = 4; break;
        case SF_FORMAT_DOUBLE: sample_bytes = 8; break;
        default: return 0;
    }
    return static_cast<std::size_t>(sample_bytes) * static_cast<std::size_t>(info.channels);
}

// The containers libsndfile reads, by their first bytes: WAV (RIFF, RIFX, RF64, BW64), Wave64,
// AIFF, AU, CAF, FLAC and Ogg. Everything else (MP3, M4A, video, and what is not audio at all) goes
// to FFmpeg: libsndfile tries any unknown file as MP3 through mpg123, which prints "Illegal
// Audio-MPEG-Header" on stderr for bad input, and its MP3 length is an estimate from the first
// frame's bit rate (sox's MP3s at 22.05 and 44.1 kHz came out "truncated"); FFmpeg reads them to
// the real end and prints nothing (ffmpeg_source.cpp).
bool is_sndfile_container(const std::array<char, 12>& header) {
    const std::string_view start(header.data(), header.size());
    const bool is_iff = (start.substr(0, 4) == "RIFF" || start.substr(0, 4) == "RIFX" || start.substr(0, 4) == "RF64" ||
                         start.substr(0, 4) == "BW64") && start.substr(8, 4) == "WAVE";
    const bool is_aiff = start.substr(0, 4) == "FORM" && (start.substr(8, 4) == "AIFF" || start.substr(8, 4) == "AIFC");
    return is_iff || is_aiff || start.substr(0, 4) == "riff" || start.substr(0, 4) == ".snd" ||
           start.substr(0, 4) == "dns." || start.substr(0, 4) == "caff" || start.substr(0, 4) == "fLaC" ||
           start.substr(0, 4) == "OggS";
}

class FileSource final : public AudioSource {
public:
    FileSource(std::string path, SNDFILE* file, const SF_INFO& info, std::size_t promised_frames)
        : path_(std::move(path)), file_(file), info_(info), promised_frames_(promised_frames) {}
    ~FileSource() override { sf_close(file_); }
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;

    std::size_t read_frames(float* mono, std::size_t max_frames) override {
        const auto channels = static_cast<std::size_t>(info_.channels);
        // One channel is read straight into `mono`: mixing it copied each sample as it was (but for
        // a zero's sign, which no feature tells), at a cost as high as the rest of reading.
        float* into = mono;
        if (channels > 1) {
            interleaved_.resize(max_frames * channels);
            into = interleaved_.data();
        }
        const sf_count_t got = sf_readf_float(file_, into, static_cast<sf_count_t>(max_frames));
        const auto frames = got > 0 ? static_cast<std::size_t>(got) : 0;
        for (std::size_t i = 0; channels > 1 && i < frames; ++i) {
            float sum = 0.0f;
            for (std::size_t c = 0; c < channels; ++c) sum += interleaved_[i * channels + c];
            mono[i] = sum / static_cast<float>(channels);
        }
        frames_read_ += frames;
        if (frames == 0 && frames_read_ < promised_frames_) {
            const std::string reason = sf_error(file_) != SF_ERR_NO_ERROR ? std::string(": ") + sf_strerror(file_) : "";
            throw FileError(path_, "truncated: the header promises " + std::to_string(promised_frames_) +
                                       " frames (" + seconds_text(promised_frames_, info_.samplerate) +
                                       ") but the data ends at frame " + std::to_string(frames_read_) + " (" +
                                       seconds_text(frames_read_, info_.samplerate) + ")" + reason);
        }
        return frames;
    }
    int sample_rate_hz() const override { return info_.samplerate; }
    std::size_t frame_count() const override { return promised_frames_; }
    const std::string& name() const override { return path_; }

private:
    std::string path_;
    SNDFILE* file_;
    SF_INFO info_;
    std::size_t promised_frames_;
    std::size_t frames_read_ = 0;
    std::vector<float> interleaved_;
};

class ViewSource final : public AudioSource {
public:
    explicit ViewSource(const AudioView& audio) : audio_(audio) {}
    std::size_t read_frames(float* mono, std::size_t max_frames) override {
        const auto channels = static_cast<std::size_t>(audio_.channel_count);
        const std::size_t frames = std::min(max_frames, audio_.frame_count - position_);
        const float* in = audio_.samples + position_ * channels;
        for (std::size_t i = 0; i < frames; ++i) {
            float sum = 0.0f;
            for (std::size_t c = 0; c < channels; ++c) sum += in[i * channels + c];
            mono[i] = sum / static_cast<float>(channels);
        }
        position_ += frames;
        return frames;
    }
    int sample_rate_hz() const override { return audio_.sample_rate_hz; }
    std::size_t frame_count() const override { return audio_.frame_count; }
    const std::string& name() const override { return name_; }

private:
    AudioView audio_;
    std::size_t position_ = 0;
    std::string name_ = "audio";
};

}  // namespace

std::size_t AudioSource::read(float* mono, std::size_t max_frames) {
    const std::size_t frames = read_frames(mono, max_frames);
    for (std::size_t i = 0; i < frames; ++i)
        if (!std::isfinite(mono[i])) mono[i] = 0.0f;
    return frames;
}

std::unique_ptr<AudioSource> open_audio_file(const std::string& path) {
    std::array<char, 12> header{};
    {
        std::ifstream probe(path, std::ios::binary | std::ios::ate);
        if (!probe) throw FileError(path, std::strerror(errno));
        if (probe.tellg() == 0) throw InvalidArgument(path, "empty file: no audio frames");
        probe.seekg(0);
        errno = 0;
        probe.read(header.data(), static_cast<std::streamsize>(header.size()));
        // A directory opens as a stream and fails on the first read (EISDIR).
        if (probe.bad() || (probe.gcount() == 0 && errno != 0)) throw FileError(path, std::strerror(errno));
    }
    if (!is_sndfile_container(header)) return open_ffmpeg_file(path);
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (file == nullptr) {
        // sf_strerror(NULL) is libsndfile's process-global last error: read it before anything else
        // can open a file on this thread.
        const std::string reason = sf_strerror(nullptr);
        if (reason.find("System error") != std::string::npos) throw FileError(path, reason);
        // A container libsndfile knows holding a codec it does not (Opus in an old libsndfile): FFmpeg's turn.
        return open_ffmpeg_file(path);
    }
    if (info.channels <= 0 || static_cast<std::size_t>(info.channels) > kMaxChannels || info.samplerate <= 0) {
        sf_close(file);
        throw ParseError(path, 0, 0, "", "unsupported header: " + std::to_string(info.channels) + " channels at " +
                                             std::to_string(info.samplerate) + " Hz");
    }
    if (info.frames == SF_COUNT_MAX) {
        // libsndfile found no length: in an Ogg stream, no complete last page (the file was cut);
        // in a FLAC stream, no sample count (written to a pipe, a valid file). FFmpeg reads the
        // latter to its real end; the former would be read as far as it goes and never called cut.
        const bool is_ogg = (info.format & SF_FORMAT_TYPEMASK) == SF_FORMAT_OGG;
        sf_close(file);
        if (is_ogg)
            throw FileError(path, "truncated: the Ogg stream breaks off inside a page, before its end; the file "
                                  "was cut while it was copied or recorded");
        return open_ffmpeg_file(path);
    }
    auto promised = static_cast<std::size_t>(std::max<sf_count_t>(info.frames, 0));
    if (const auto data_bytes = data_bytes_if_truncated(file); data_bytes && !is_placeholder_size(data_bytes->stated))
        promised = std::max(promised, frames_promised_by(info, bytes_per_frame(info), *data_bytes));
    if (promised == 0) {
        // libsndfile reads nothing from a data chunk stated as 0 bytes, as a recorder stopped before
        // it closed the file leaves it; FFmpeg reads what follows to the end of the file, and
        // refuses a file with no sound after its header.
        sf_close(file);
        return open_ffmpeg_file(path);
    }
    return std::make_unique<FileSource>(path, file, info, promised);
}

std::string wav_codec_browsers_do_not_play(const std::string& path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (file == nullptr) return {};
    sf_close(file);
    const int type = info.format & SF_FORMAT_TYPEMASK;
    if (type != SF_FORMAT_WAV && type != SF_FORMAT_WAVEX && type != SF_FORMAT_RF64) return {};
    switch (info.format & SF_FORMAT_SUBMASK) {
        case SF_FORMAT_PCM_U8: case SF_FORMAT_PCM_S8: case SF_FORMAT_PCM_16: case SF_FORMAT_PCM_24:
        case SF_FORMAT_PCM_32: case SF_FORMAT_FLOAT: case SF_FORMAT_ULAW: case SF_FORMAT_ALAW:
            return {};
        default: break;
    }
    SF_FORMAT_INFO codec{};
    codec.format = info.format & SF_FORMAT_SUBMASK;
    if (sf_command(nullptr, SFC_GET_FORMAT_INFO, &codec, sizeof codec) != 0 || codec.name == nullptr)
        return "codec " + std::to_string(codec.format);
    return codec.name;
}

std::unique_ptr<AudioSource> open_audio_view(const AudioView& audio) {
    if (audio.frame_count == 0) throw InvalidArgument("audio.frame_count", "empty audio: no frames");
    if (audio.samples == nullptr) throw InvalidArgument("audio.samples", "null, with " + std::to_string(audio.frame_count) + " frames");
    if (audio.channel_count <= 0 || static_cast<std::size_t>(audio.channel_count) > kMaxChannels)
        throw InvalidArgument("audio.channel_count", "expected 1.." + std::to_string(kMaxChannels) + ", found " +
                                                         std::to_string(audio.channel_count));
    if (audio.sample_rate_hz < 4000 || audio.sample_rate_hz > 384000)
        throw InvalidArgument("audio.sample_rate_hz",
                              "expected 4000..384000, found " + std::to_string(audio.sample_rate_hz));
    return std::make_unique<ViewSource>(audio);
}

}  // namespace talkface::detail
