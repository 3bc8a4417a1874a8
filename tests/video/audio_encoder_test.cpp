// The pages' compressed audio (src/video/audio_encoder): each container read back by libavformat.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <string>
#include <vector>

#include "media_probe.hpp"
#include "talkface/errors.hpp"
#include "video/audio_encoder.hpp"
#include "video/ffmpeg_support.hpp"

using talkface::detail::AudioContainer;
using talkface::detail::AudioEncodeOptions;

namespace {

const std::string kOutputDir = TALKFACE_TEST_OUTPUT_DIR;

// A second and a half of a 220 Hz tone with a pause in its middle, at `rate_hz`.
std::vector<float> tone(int rate_hz, double seconds = 1.5) {
    std::vector<float> samples(static_cast<std::size_t>(seconds * rate_hz));
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double t = static_cast<double>(i) / rate_hz;
        const bool is_pause = t > 0.6 && t < 0.9;
        samples[i] = is_pause ? 0.0F : static_cast<float>(0.4 * std::sin(2.0 * M_PI * 220.0 * t));
    }
    return samples;
}

talkface::AudioView view_of(const std::vector<float>& samples, int rate_hz) {
    return {samples.data(), samples.size(), 1, rate_hz};
}

// A source that fails half way, as a truncated file does.
class FailingSource : public talkface::detail::AudioSource {
public:
    std::size_t read_frames(float* mono, std::size_t max_frames) override {
        if (reads_++ > 2) throw talkface::FileError("broken.wav", "the data ends early");
        std::fill(mono, mono + max_frames, 0.1F);
        return max_frames;
    }
    int sample_rate_hz() const override { return 16000; }
    std::size_t frame_count() const override { return 160000; }
    const std::string& name() const override { return name_; }

private:
    int reads_ = 0;
    std::string name_ = "broken.wav";
};

}  // namespace

TEST_SUITE("audio encoder") {

TEST_CASE("each container holds its codec at 48 kHz and lasts as long as the speech") {
    for (const int rate_hz : {16000, 44100, 48000}) {
        const std::vector<float> samples = tone(rate_hz);
        for (const AudioContainer container :
             {AudioContainer::ogg_opus, AudioContainer::webm_opus, AudioContainer::mp4_aac}) {
            CAPTURE(rate_hz);
            CAPTURE(talkface::detail::audio_container_extension(container));
            AudioEncodeOptions options;
            options.container = container;
            const std::string bytes = talkface::detail::encode_audio(view_of(samples, rate_hz), options);
            const std::string path = kOutputDir + "/audio_encoder_" + std::to_string(rate_hz) +
                                     talkface::detail::audio_container_extension(container);
            talkface_test::write_bytes(path, bytes);
            const talkface_test::MediaInfo info = talkface_test::probe_media(path);
            REQUIRE(info.streams.size() == 1);
            const talkface_test::StreamInfo& stream = info.streams[0];
            CHECK(stream.codec == (container == AudioContainer::mp4_aac ? "aac" : "opus"));
            CHECK(stream.sample_rate_hz == 48000);
            // The first sound is at 0 (after the codec's priming samples, which players skip).
            CHECK(std::abs(stream.start_s + stream.priming_s) < 0.001);
            // Within one 20 ms Opus frame / 21 ms AAC frame of the input's 1.5 s.
            CHECK(stream.duration_s == doctest::Approx(1.5).epsilon(0.022 / 1.5));
            // Speech-sized (48 kb/s Opus, 96 kb/s AAC, plus the container's headers, a good part
            // of 1.5 s): a tenth of 16-bit PCM at 48 kHz.
            const double kilobits_per_s = static_cast<double>(bytes.size()) * 8.0 / 1000.0 / 1.5;
            CAPTURE(kilobits_per_s);
            CHECK(kilobits_per_s < (container == AudioContainer::mp4_aac ? 130.0 : 100.0));
        }
    }
}

TEST_CASE("the containers begin with their own signatures") {
    const std::vector<float> samples = tone(16000, 0.5);
    AudioEncodeOptions options;
    options.container = AudioContainer::ogg_opus;
    CHECK(talkface::detail::encode_audio(view_of(samples, 16000), options).substr(0, 4) == "OggS");
    options.container = AudioContainer::webm_opus;
    CHECK(talkface::detail::encode_audio(view_of(samples, 16000), options).substr(0, 4) == "\x1a\x45\xdf\xa3");
    options.container = AudioContainer::mp4_aac;
    CHECK(talkface::detail::encode_audio(view_of(samples, 16000), options).substr(4, 4) == "ftyp");
}

TEST_CASE("an MP4 file has its index before its data, so it plays while it downloads") {
    const std::vector<float> samples = tone(44100);
    const std::string path = kOutputDir + "/audio_encoder_faststart.m4a";
    std::filesystem::remove(path);
    AudioEncodeOptions options;
    options.container = AudioContainer::mp4_aac;
    const std::unique_ptr<talkface::detail::AudioSource> source =
        talkface::detail::open_audio_view(view_of(samples, 44100));
    talkface::detail::write_encoded_audio(path, *source, options);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.find("moov") != std::string::npos);
    CHECK(bytes.find("moov") < bytes.find("mdat"));
    CHECK((std::filesystem::status(path).permissions() & std::filesystem::perms::others_read) !=
          std::filesystem::perms::none);
}

TEST_CASE("the same samples give the same bytes") {
    const std::vector<float> samples = tone(16000);
    for (const AudioContainer container :
         {AudioContainer::ogg_opus, AudioContainer::webm_opus, AudioContainer::mp4_aac}) {
        CAPTURE(talkface::detail::audio_container_extension(container));
        AudioEncodeOptions options;
        options.container = container;
        CHECK(talkface::detail::encode_audio(view_of(samples, 16000), options) ==
              talkface::detail::encode_audio(view_of(samples, 16000), options));
    }
}

TEST_CASE("a read that fails half way leaves no file, not even a temporary one") {
    const std::string folder = kOutputDir + "/audio_encoder_failing";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    FailingSource source;
    CHECK_THROWS_WITH_AS(talkface::detail::write_encoded_audio(folder + "/speech.ogg", source, {}),
                         doctest::Contains("broken.wav"), talkface::FileError);
    CHECK(std::filesystem::is_empty(folder));
}

TEST_CASE("a folder that does not exist is a FileError naming the path") {
    const std::vector<float> samples = tone(16000, 0.2);
    const std::unique_ptr<talkface::detail::AudioSource> source =
        talkface::detail::open_audio_view(view_of(samples, 16000));
    CHECK_THROWS_WITH_AS(talkface::detail::write_encoded_audio(kOutputDir + "/no/such/folder/a.ogg", *source, {}),
                         doctest::Contains("no/such/folder/a.ogg"), talkface::FileError);
}

TEST_CASE("an encoder missing from the system's FFmpeg is named, with what it was for") {
    CHECK_THROWS_WITH_AS(talkface::detail::find_encoder("libno-such-codec", "Opus audio", "talk.webm"),
                         doctest::Contains("talk.webm: this system's FFmpeg"), talkface::InvalidArgument);
    CHECK_THROWS_WITH_AS(talkface::detail::find_encoder("libno-such-codec", "Opus audio", "talk.webm"),
                         doctest::Contains("no encoder \"libno-such-codec\" for Opus audio"),
                         talkface::InvalidArgument);
}

TEST_CASE("the MIME types name the codecs") {
    CHECK(std::string(talkface::detail::audio_container_mime_type(AudioContainer::ogg_opus)) ==
          "audio/ogg; codecs=opus");
    CHECK(std::string(talkface::detail::audio_container_mime_type(AudioContainer::webm_opus)) ==
          "audio/webm; codecs=opus");
    CHECK(std::string(talkface::detail::audio_container_mime_type(AudioContainer::mp4_aac)) ==
          "audio/mp4; codecs=mp4a.40.2");
}

}  // TEST_SUITE
