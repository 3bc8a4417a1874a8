// Recordings as people have them (issue #13): every format of tests/data/audio/ (make_fixtures.sh)
// reads to its real end, gives the WAV's samples' timing, and aligns; what cannot be read says why.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/made_by_command.hpp"
#include "common/number_format.hpp"
#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

std::string fixture(const std::string& file) { return test::source_path("tests/data/audio/" + file); }
std::string speech_clip(const std::string& file) { return test::source_path("tests/data/speech/" + file); }

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

const char* const kRecordings[] = {"sox_22050.mp3",  "sox_44100.mp3", "ffmpeg_16000.mp3", "ffmpeg_48000.mp3",
                                   "phone.m4a",      "voice.opus",    "clip.mp4",         "clip.mov",
                                   "clip.mkv",       "clip.webm"};

}  // namespace

TEST_SUITE("audio") {
    TEST_CASE("MP3, M4A, Opus and a video's sound track read to the real end, in step with the WAV") {
        const auto wav = detail::open_audio_file(speech_clip("one_sentence.wav"));
        const std::vector<float> reference = test::read_all(*wav);
        const double reference_s = static_cast<double>(reference.size()) / wav->sample_rate_hz();
        const std::vector<double> reference_loudness = test::envelope(reference, wav->sample_rate_hz());
        for (const std::string name : kRecordings) {
            CAPTURE(name);
            const auto source = detail::open_audio_file(fixture(name));
            CHECK(source->name() == fixture(name));
            const std::vector<float> samples = test::read_all(*source);
            const double seconds = static_cast<double>(samples.size()) / source->sample_rate_hz();
            // Codecs pad the end to a whole frame (at most ~50 ms); none stops short.
            CHECK(seconds >= reference_s - 0.005);
            CHECK(seconds <= reference_s + 0.08);
            // No codec's delay left in: the speech starts where the WAV's does, within 5 ms.
            CHECK(std::abs(test::best_lag(reference_loudness, test::envelope(samples, source->sample_rate_hz()))) <= 1);
        }
    }

    TEST_CASE("each recording aligns as its WAV does") {
        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        const SpeechAligner aligner;
        const Timeline reference = aligner.align_file(speech_clip("one_sentence.wav"), transcript);
        for (const std::string name : kRecordings) {
            CAPTURE(name);
            const Timeline timeline = aligner.align_file(fixture(name), transcript);
            REQUIRE(timeline.syllables.size() == reference.syllables.size());
            for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
                CAPTURE(i);
                CHECK(std::fabs(timeline.syllables[i].start_s - reference.syllables[i].start_s) <= 0.0301);
            }
        }
    }

    TEST_CASE("a video without a sound track, a damaged file and a wrong format say so, naming the file") {
        const std::string silent_video = fixture("no_sound.mp4");
        CHECK_THROWS_WITH_AS(detail::open_audio_file(silent_video),
                             doctest::Contains((silent_video + ": a video without a sound track").c_str()), ParseError);

        std::ifstream in(fixture("phone.m4a"), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string cut = test::output_path("cut_header.m4a");
        write_bytes(cut, bytes.substr(0, 200));
        CHECK_THROWS_WITH_AS(detail::open_audio_file(cut),
                             doctest::Contains((cut + ": truncated: an MP4/M4A/MOV file without its index").c_str()),
                             FileError);

        const std::string image = test::output_path("picture.mp3");
        write_bytes(image, std::string("\x89PNG\r\n\x1a\n", 8) + std::string(400, '\0'));
        CHECK_THROWS_WITH_AS(detail::open_audio_file(image), doctest::Contains((image + ": not audio").c_str()), ParseError);

        CHECK_THROWS_WITH_AS(SpeechAligner().align_file(silent_video, read_transcript("ni3 hao3.")),
                             doctest::Contains("without a sound track"), ParseError);
    }

    TEST_CASE("AAC whose container does not state the encoder's delay starts where the WAV does") {
        // An MP4's edit list states the delay an AAC encoder puts before the sound, and FFmpeg
        // drops it; a raw AAC file (ADTS, an Android recorder's .aac), Matroska (a screen
        // recorder's MKV) and AVI do not, and the speech came 64 ms late.
        const std::string speech = speech_clip("one_sentence.wav");
        const auto wav = detail::open_audio_file(speech);
        const std::vector<double> reference = test::envelope(test::read_all(*wav), wav->sample_rate_hz());
        for (const std::string name : {"adts.aac", "aac.mkv", "aac.avi", "aac.m4a"}) {
            CAPTURE(name);
            const std::string path = test::made_by_command(
                "delay_" + name, "ffmpeg -nostdin -loglevel error -y -i '" + speech + "' -c:a aac -b:a 32k");
            const auto source = detail::open_audio_file(path);
            const std::vector<float> samples = test::read_all(*source);
            CHECK(std::abs(test::best_lag(reference, test::envelope(samples, source->sample_rate_hz()))) <=
                  1);
        }
    }

    TEST_CASE("a WeChat or QQ voice message in SILK v3 is named as such, not as bytes that are no audio") {
        // FFmpeg has no decoder for SILK outside Opus, and said "Invalid data found when processing
        // input". WeChat saves its voice messages with a byte 2 before the mark (often named .amr).
        for (const std::string& mark : {std::string("\x02#!SILK_V3"), std::string("#!SILK_V3")}) {
            const std::string message = test::output_path(mark.size() == 10 ? "wechat.amr" : "qq.silk");
            write_bytes(message, mark + std::string("\x14\0", 2) + std::string(20, '\x5a'));
            CHECK_THROWS_WITH_AS(detail::open_audio_file(message),
                                 doctest::Contains((message + ": a voice message in SILK v3").c_str()),
                                 ParseError);
        }
    }

    TEST_CASE("bad input prints nothing on stderr: the library reports through its errors only") {
        // libsndfile's MP3 decoder (mpg123) printed "Illegal Audio-MPEG-Header" for bytes it could
        // not place; FFmpeg logs to stderr unless its process-wide level is lowered.
        std::ifstream in(fixture("sox_22050.mp3"), std::ios::binary);
        const std::string mp3((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::string noise(3000, '\0');
        std::uint32_t state = 1;
        for (char& c : noise) c = static_cast<char>((state = state * 1664525u + 1013904223u) >> 24);
        const std::vector<std::pair<std::string, std::string>> inputs = {
            {"noise.bin", noise},
            {"noise.mp3", noise},
            {"frame_then_noise.mp3", std::string("\xff\xfb\x90\x00", 4) + noise},
            {"mp3_cut.mp3", mp3.substr(0, mp3.size() / 3) + noise},
            {"riff_noise.wav", std::string("RIFF\x10\0\0\0WAVE", 12) + noise},
        };
        const std::string captured = test::output_path("stderr_of_bad_input.txt");
        std::fflush(stderr);
        const int saved = dup(2);
        const int sink = open(captured.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        REQUIRE(saved >= 0);
        REQUIRE(sink >= 0);
        dup2(sink, 2);
        close(sink);
        int refused = 0;
        for (const auto& [name, bytes] : inputs) {
            const std::string path = test::output_path(name);
            write_bytes(path, bytes);
            try {
                auto source = detail::open_audio_file(path);
                std::vector<float> block(4096);
                while (source->read(block.data(), block.size()) > 0) {
                }
            } catch (const Error&) {
                ++refused;
            }
        }
        std::fflush(stderr);
        dup2(saved, 2);
        close(saved);
        std::ifstream printed(captured);
        const std::string text((std::istreambuf_iterator<char>(printed)), std::istreambuf_iterator<char>());
        CHECK(text == "");
        CHECK(refused >= 3);
    }

    TEST_CASE("a sample that is not a number reads as 0: the speech aligns as with a 0 there") {
        const auto wav = detail::open_audio_file(speech_clip("one_sentence.wav"));
        std::vector<float> zeroed = test::read_all(*wav);
        std::vector<float> damaged = zeroed;
        const std::size_t third = damaged.size() / 3;
        damaged[third] = std::nanf("");
        damaged[third + 1] = INFINITY;
        damaged[2 * third] = -INFINITY;
        for (const std::size_t i : {third, third + 1, 2 * third}) zeroed[i] = 0.0f;
        const AudioView damaged_view{damaged.data(), damaged.size(), 1, wav->sample_rate_hz()};
        const auto source = detail::open_audio_view(damaged_view);
        for (const float sample : test::read_all(*source)) REQUIRE(std::isfinite(sample));
        const std::string said = "3 of its " + std::to_string(damaged.size()) +
                                 " samples are not numbers (NaN or infinite), the first at " +
                                 detail::format_fixed(static_cast<double>(third) / wav->sample_rate_hz(), 3) +
                                 " s";
        REQUIRE(source->notes().size() == 1);
        CHECK(source->notes()[0].rfind(said, 0) == 0);

        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        const SpeechAligner aligner;
        const Timeline reference = aligner.align({zeroed.data(), zeroed.size(), 1, wav->sample_rate_hz()}, transcript);
        const Timeline timeline = aligner.align(damaged_view, transcript);
        REQUIRE(timeline.syllables.size() == reference.syllables.size());
        for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
            CAPTURE(i);
            CHECK(timeline.syllables[i].start_s == reference.syllables[i].start_s);
        }
        // Said once, though a short transcript's refusal vote reads the recording three times.
        CHECK(std::count_if(
                  timeline.warnings.begin(), timeline.warnings.end(),
                  [&](const std::string& warning) { return warning.rfind("audio: " + said, 0) == 0; }) == 1);
        CHECK(reference.warnings.empty());
    }

    TEST_CASE("samples that are not numbers inside a leading silence the reading seeks past are noted") {
        // 70 s of silence holding 4 NaN from 2 s on, then the voice: the reading that is kept seeks
        // past all but the last minute of the silence, which the first reading read.
        const auto wav = detail::open_audio_file(speech_clip("one_sentence.wav"));
        const int rate_hz = wav->sample_rate_hz();
        const std::vector<float> voice = test::read_all(*wav);
        std::vector<float> samples(static_cast<std::size_t>(70 * rate_hz), 0.0f);
        const std::size_t first = static_cast<std::size_t>(2 * rate_hz);
        for (std::size_t i = first; i < first + 4; ++i) samples[i] = std::nanf("");
        samples.insert(samples.end(), voice.begin(), voice.end());
        const Timeline timeline = SpeechAligner().align({samples.data(), samples.size(), 1, rate_hz},
                                                        load_transcript(speech_clip("one_sentence.txt")));
        const std::string said = "audio: 4 of its " + std::to_string(samples.size()) +
                                 " samples are not numbers (NaN or infinite), the first at " +
                                 detail::format_fixed(2.0, 3) + " s";
        std::string warnings;
        for (const std::string& warning : timeline.warnings) warnings += warning + "\n";
        CAPTURE(warnings);
        CHECK(std::count_if(timeline.warnings.begin(), timeline.warnings.end(),
                            [&](const std::string& warning) { return warning.rfind(said, 0) == 0; }) == 1);
    }

    TEST_CASE("a recording none of whose samples is a number is refused as silent, saying why") {
        const std::vector<float> samples(16000, std::nanf(""));
        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        CHECK_THROWS_WITH_AS(
            SpeechAligner().align({samples.data(), samples.size(), 1, 16000}, transcript),
            doctest::Contains("is all zero; there is no speech to align (the file: none of its "
                              "16000 samples is a number (each is NaN or infinite)"),
            InvalidArgument);
    }

    TEST_CASE("a directory is a file error, not a parse error") {
        const std::string folder = test::source_path("tests/data/audio");
        CHECK_THROWS_AS(detail::open_audio_file(folder), FileError);
    }

    TEST_CASE("two channels mix as the rule for any count says, sample for sample, in blocks of any size") {
        // ChannelMixer mixes stereo in a loop of its own (its sums held in registers): it must give
        // the samples the rule gives, written here one frame at a time: channels averaged, the second
        // turned over while its correlation with the first, over every frame so far, is below -0.2
        // (back above +0.2), from frame 1024 on. The signal turns the side over and back: 0.3 s of
        // two independent noises, 1 s of a tone with the right side inverted, 2 s with it agreeing.
        constexpr int kRateHz = 16000;
        std::vector<float> interleaved;
        std::uint32_t seed = 11;
        const auto noise = [&seed] { return static_cast<float>(static_cast<int>((seed = seed * 1664525u + 1013904223u) >> 16) - 32768) / 3.3e6f; };
        for (int i = 0; i < 3 * kRateHz / 10; ++i) interleaved.insert(interleaved.end(), {noise(), noise()});
        for (int i = 0; i < 3 * kRateHz; ++i) {
            const float tone = 0.3f * static_cast<float>(std::sin(2.0 * M_PI * 220.0 * i / kRateHz)) + noise();
            interleaved.insert(interleaved.end(), {tone, (i < kRateHz ? -0.7f : 0.9f) * tone + noise()});
        }
        const std::size_t frames = interleaved.size() / 2;
        std::vector<float> expected(frames);
        double first_energy = 0.0, energy = 0.0, with_first = 0.0;
        float sign = 1.0f;
        int turns = 0;
        for (std::size_t i = 0; i < frames; ++i) {
            const double first = interleaved[2 * i], second = interleaved[2 * i + 1];
            first_energy += first * first;
            energy += second * second;
            with_first += second * first;
            const float before = sign;
            if (i >= 1024 && with_first * with_first > 0.2 * 0.2 * first_energy * energy) sign = with_first < 0.0 ? -1.0f : 1.0f;
            turns += sign != before;
            float sum = interleaved[2 * i];
            sum += sign * interleaved[2 * i + 1];
            expected[i] = sum / 2.0f;
        }
        REQUIRE(turns == 2);
        for (const std::size_t block : {std::size_t{1}, std::size_t{7}, std::size_t{1000}, std::size_t{4096}, frames}) {
            CAPTURE(block);
            detail::ChannelMixer mixer;
            std::vector<float> mixed(frames);
            for (std::size_t at = 0; at < frames; at += block)
                mixer.mix(interleaved.data() + 2 * at, std::min(block, frames - at), 2, mixed.data() + at);
            std::size_t differing = 0;
            for (std::size_t i = 0; i < frames; ++i) differing += mixed[i] != expected[i];
            CHECK(differing == 0);
        }
    }
}
