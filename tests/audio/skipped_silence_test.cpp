// A reading that passes a recording's leading silence by a seek (AudioSource::skip_to, which the
// aligner asks for where hours of digital silence come first) gives, from the frame it passes to,
// exactly the samples a reading from the start gives there, in every container that seeks: the
// frames keep their grid, a codec's delay stays cut. Made here by ffmpeg from
// tests/data/speech/one_sentence.wav after 8 s of digital silence.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/made_by_command.hpp"
#include "common/test_paths.hpp"

using namespace talkface;

namespace {

struct Made {
    const char* file;     // its name, whose extension ffmpeg reads as the container
    const char* options;  // ffmpeg's options for it
    bool seeks;           // skip_to() seeks in it; else it reads on
};

const Made kMade[] = {
    {"silence_first.wav", "-c:a pcm_s16le", true},
    {"silence_first.flac", "-c:a flac", true},
    {"silence_first_lame.mp3", "-c:a libmp3lame -b:a 32k", true},
    {"silence_first_untagged.mp3", "-c:a libmp3lame -b:a 32k -write_xing 0", true},
    {"silence_first_stereo.mp3", "-ar 44100 -ac 2 -c:a libmp3lame -b:a 64k -write_xing 0", true},
    {"silence_first.m4a", "-c:a aac -b:a 32k", true},
    {"silence_first.aac", "-c:a aac -b:a 32k", true},
    {"silence_first.opus", "-c:a libopus -b:a 16k", true},
    {"silence_first_clip.mp4", "-c:v libx264 -crf 40 -c:a aac -b:a 24k -shortest -movflags +faststart", true},
    {"silence_first_clip.mov", "-c:v libx264 -crf 40 -c:a aac -b:a 24k -shortest", true},
    // A dictaphone's MP3 inside a WAV.
    {"silence_first_mp3_in.wav", "-c:a libmp3lame -b:a 32k", true},
    // An MPEG transport stream's timestamps (90 kHz) do not place a sample, nor do Matroska's
    // milliseconds: the codec's frames do (MP2's 1152 samples, Opus's 2.5 ms steps, AAC's 1024).
    {"silence_first.ts", "-ar 48000 -c:a mp2 -b:a 128k", true},
    {"silence_first.mka", "-c:a libopus -b:a 16k", true},
    {"silence_first_10ms.mka", "-c:a libopus -b:a 16k -frame_duration 10", true},
    {"silence_first.webm", "-c:a libopus -b:a 16k", true},
    {"silence_first_aac.mka", "-c:a aac -b:a 32k", true},
    {"silence_first_clip.mkv", "-c:v libvpx -b:v 8k -c:a libopus -b:a 16k -shortest", true},
    // Vorbis's blocks may end on any sample, and AC-3's decoder dithers along the whole stream (a
    // bare AC-3's timestamps are 90 kHz too): read on.
    {"silence_first_vorbis.mka", "-c:a libvorbis -q:a 1", false},
    {"silence_first.ac3", "-ar 48000 -c:a ac3 -b:a 96k", false},
    {"silence_first_ac3.ts", "-ar 48000 -c:a ac3 -b:a 96k", false},
};

bool is_video(const std::string& file) {
    return file.find("clip") != std::string::npos;
}

std::string made(const Made& recording) {
    const std::string speech = test::source_path("tests/data/speech/one_sentence.wav");
    return test::made_by_command(
        recording.file, std::string("ffmpeg -nostdin -loglevel error -y ") +
                            (is_video(recording.file) ? "-f lavfi -i color=c=gray:s=16x16:r=2:d=12 " : "") +
                            "-i '" + speech + "' -af adelay=delays=8000:all=1 " + recording.options);
}

// A made recording read whole from its start.
struct WholeReading {
    std::string path;
    int rate_hz = 0;
    std::vector<float> samples;
};

WholeReading read_whole(const Made& recording) {
    WholeReading whole;
    whole.path = made(recording);
    const auto source = detail::open_audio_file(whole.path);
    whole.rate_hz = source->sample_rate_hz();
    whole.samples = test::read_all(*source);
    return whole;
}

// Whether `rest` is `samples` from `frame` on, bit for bit.
bool is_rest_from(const std::vector<float>& rest, const std::vector<float>& samples, std::size_t frame) {
    return rest.size() == samples.size() - frame &&
           std::memcmp(rest.data(), samples.data() + frame, rest.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_SUITE("audio") {
    TEST_CASE("a seek past a leading silence lands on the sample a reading from the start gives there") {
        for (const Made& recording : kMade) {
            const std::string file = recording.file;
            CAPTURE(file);
            const WholeReading whole = read_whole(recording);
            // Inside the silence, and inside the speech after it (8.5 s).
            for (const double at_s : {1.5, 5.0 + 123.0 / 16000, 7.9, 8.5}) {
                CAPTURE(at_s);
                const auto frame = static_cast<std::size_t>(at_s * whole.rate_hz);
                const auto reading = detail::open_audio_file(whole.path);
                const bool skipped = reading->skip_to(frame);
                CHECK(skipped == recording.seeks);
                if (!skipped) continue;
                CHECK(is_rest_from(test::read_all(*reading), whole.samples, frame));
            }
        }
    }

    TEST_CASE("a seek that cannot land leaves the reading as it was, after a seek that landed too") {
        // Past the end, FFmpeg's decode from the seek finds no frame that holds the sample: the file
        // is opened again at the packet the reading had reached and read on from there, to its end,
        // with no gap; libsndfile's reading stays where it was.
        for (const Made& recording : kMade) {
            if (!recording.seeks) continue;
            const std::string file = recording.file;
            CAPTURE(file);
            const WholeReading whole = read_whole(recording);
            for (const bool landed_before : {false, true}) {
                CAPTURE(landed_before);
                const auto reading = detail::open_audio_file(whole.path);
                const std::size_t at = landed_before ? static_cast<std::size_t>(5.0 * whole.rate_hz) : 0;
                if (landed_before) REQUIRE(reading->skip_to(at));
                CHECK_FALSE(
                    reading->skip_to(whole.samples.size() + static_cast<std::size_t>(2.0 * whole.rate_hz)));
                const std::vector<float> rest = test::read_all(*reading);
                CHECK((rest.empty() || is_rest_from(rest, whole.samples, at)));
                CHECK(reading->notes().empty());
                CHECK(reading->lost_audio().empty());
            }
        }
    }
}
