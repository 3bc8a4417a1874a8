// Recordings as people have them, made here by ffmpeg from tests/data/speech/one_sentence.wav
// rather than committed (issue #13): MP3 at every common rate from 8 to 48 kHz, with and without
// the LAME tag that says how long it is; a phone's M4A (AAC in MP4, stereo at 44.1 kHz); Opus at
// 8 kHz; and phone calls: the telephone band at 8 kHz, as 16-bit WAV, through GSM 06.10 (in WAV, as
// voice mail stores it, read by libsndfile; in QuickTime, read by FFmpeg) and as a low-rate MP3;
// MP3 inside a WAV; AC-3 and MP2 in MPEG transport and program streams, and a bare AC-3 track.
// Each reads to its real end in step with the WAV, and each phone call aligns as the WAV does.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/made_by_command.hpp"
#include "common/test_paths.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

std::string speech_clip(const std::string& file) { return test::source_path("tests/data/speech/" + file); }

// one_sentence.wav encoded by ffmpeg with `options` into test output NAME.
std::string ffmpeg_made(const std::string& name, const std::string& options) {
    return test::made_by_command(
        name, "ffmpeg -nostdin -loglevel error -y -i '" + speech_clip("one_sentence.wav") + "' " + options);
}

// The telephone band at 8 kHz, as a phone call's recording has it.
const char* const kPhoneBand = "-af highpass=f=300:poles=2,lowpass=f=3400:poles=2 -ar 8000 -ac 1";

struct Made {
    std::string path;
    int sample_rate_hz;           // 0: the decoder's choice (Opus decodes at the rate it was given)
    bool is_phone_call = false;   // the telephone band at 8 kHz
    double padding_s = 0.08;      // how much longer than the WAV it may read: its codec's last frame
};

// Each recording, made once per run of the test program.
const std::vector<Made>& recordings() {
    static const std::vector<Made> made = [] {
        std::vector<Made> files;
        for (const int rate : {8000, 11025, 12000, 16000, 22050, 24000, 32000, 44100, 48000}) {
            const std::string rate_text = std::to_string(rate);
            // A LAME tag (ffmpeg's default) gives the encoder's delay and the length; without one
            // (as sox writes them) both are guessed.
            files.push_back({ffmpeg_made("lame_" + rate_text + ".mp3", "-ar " + rate_text + " -c:a libmp3lame -b:a 32k"), rate});
            files.push_back({ffmpeg_made("untagged_" + rate_text + ".mp3",
                                         "-ar " + rate_text + " -c:a libmp3lame -b:a 32k -write_xing 0"), rate});
        }
        files.push_back({ffmpeg_made("phone_stereo_44100.m4a", "-ar 44100 -ac 2 -c:a aac -b:a 64k"), 44100});
        // AAC's frame is 1024 samples: 128 ms at 8 kHz.
        files.push_back({ffmpeg_made("call_aac.m4a", std::string(kPhoneBand) + " -c:a aac -b:a 16k"), 8000, true, 0.14});
        files.push_back({ffmpeg_made("call_opus.opus", std::string(kPhoneBand) + " -c:a libopus -b:a 8k"), 0, true});
        files.push_back({ffmpeg_made("call_pcm.wav", kPhoneBand), 8000, true});
        files.push_back({ffmpeg_made("call_gsm.mov", std::string(kPhoneBand) + " -c:a libgsm"), 8000, true});
        files.push_back({ffmpeg_made("call_mp3.mp3", std::string(kPhoneBand) + " -c:a libmp3lame -b:a 16k"), 8000, true});
        // GSM 06.10 in WAV (Microsoft's packing, as voice mail and sox store it) is libsndfile's to read.
        files.push_back({ffmpeg_made("call_gsm.wav", std::string(kPhoneBand) + " -c:a libgsm_ms"), 8000, true});
        // MP3 inside a WAV, as dictaphones and broadcast systems write it: libsndfile's length is an
        // estimate (a whole file was called truncated 26 ms short of it), FFmpeg's is the real one.
        files.push_back({ffmpeg_made("mp3_in.wav", "-c:a libmp3lame -b:a 32k -f wav"), 16000});
        // A camcorder's AVCHD file (AC-3 in an MPEG transport stream), a TV recording's MP2 in one,
        // an old camera's or a DVD's MPEG program stream, and a film's bare AC-3 track: at 48 kHz,
        // their codecs' frames are 24-32 ms.
        files.push_back(
            {ffmpeg_made("camcorder.mts", "-ar 48000 -ac 2 -c:a ac3 -b:a 128k -f mpegts"), 48000});
        files.push_back({ffmpeg_made("broadcast.ts", "-ar 48000 -c:a mp2 -b:a 128k -f mpegts"), 48000});
        files.push_back({ffmpeg_made("camera.mpg", "-ar 48000 -c:a mp2 -b:a 128k -f mpeg"), 48000});
        files.push_back({ffmpeg_made("film.ac3", "-ar 48000 -c:a ac3 -b:a 96k -f ac3"), 48000});
        // A stream's segment as a download tool saves it: AAC in an MPEG transport stream.
        files.push_back({ffmpeg_made("stream.ts", "-ar 44100 -c:a aac -b:a 64k -f mpegts"), 44100});
        // A browser's MediaRecorder's AAC in a fragmented MP4, whose index holds no edit list.
        files.push_back(
            {ffmpeg_made("mediarecorder.mp4",
                         "-ar 48000 -c:a aac -b:a 64k -movflags frag_keyframe+empty_moov+default_base_moof "
                         "-f mp4"),
             48000});
        return files;
    }();
    return made;
}

// Every syllable of `timeline` starts within `tolerance_s` of `reference`'s, moved by `shift_s`.
void check_starts_as(const Timeline& timeline, const Timeline& reference, double shift_s,
                     double tolerance_s) {
    REQUIRE(timeline.syllables.size() == reference.syllables.size());
    for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
        CAPTURE(i);
        CHECK(std::fabs(timeline.syllables[i].start_s - (reference.syllables[i].start_s + shift_s)) <=
              tolerance_s);
    }
}

}  // namespace

TEST_SUITE("audio") {
    TEST_CASE("MP3 at every rate, a phone's M4A, Opus and GSM read to the real end, in step with the WAV") {
        const auto wav = detail::open_audio_file(speech_clip("one_sentence.wav"));
        const std::vector<float> reference = test::read_all(*wav);
        const double reference_s = static_cast<double>(reference.size()) / wav->sample_rate_hz();
        const std::vector<double> reference_loudness = test::envelope(reference, wav->sample_rate_hz());
        for (const Made& made : recordings()) {
            CAPTURE(made.path);
            const auto source = detail::open_audio_file(made.path);
            if (made.sample_rate_hz != 0) CHECK(source->sample_rate_hz() == made.sample_rate_hz);
            const std::vector<float> samples = test::read_all(*source);
            const double seconds = static_cast<double>(samples.size()) / source->sample_rate_hz();
            // Codecs pad the end to a whole frame; none stops short.
            CHECK(seconds >= reference_s - 0.005);
            CHECK(seconds <= reference_s + made.padding_s);
            // No codec's delay left in: the speech starts where the WAV's does, within 5 ms.
            CHECK(std::abs(test::best_lag(reference_loudness, test::envelope(samples, source->sample_rate_hz()))) <= 1);
        }
    }

    TEST_CASE("an Opus stream reads the same in Ogg as in Matroska or WebM: one decoder reads them all") {
        // Ogg Opus was libsndfile's (libopus at the rate its header names: 16 kHz here), 8 times as
        // slow as FFmpeg's decoder on a long silence; the same stream moved into Matroska was FFmpeg's.
        const std::string ogg = ffmpeg_made("voice_message.opus", "-c:a libopus -b:a 16k");
        const std::vector<float> from_ogg = test::read_all(*detail::open_audio_file(ogg));
        for (const std::string container : {"mka", "webm"}) {
            CAPTURE(container);
            const std::string moved =
                test::made_by_command("voice_message." + container,
                                      "ffmpeg -nostdin -loglevel error -y -i '" + ogg + "' -c:a copy");
            CHECK(test::read_all(*detail::open_audio_file(moved)) == from_ogg);
        }
    }

    TEST_CASE("a phone call (300-3400 Hz at 8 kHz, PCM, GSM, MP3, Opus, AAC) aligns as the WAV does") {
        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        const SpeechAligner aligner;
        const Timeline reference = aligner.align_file(speech_clip("one_sentence.wav"), transcript);
        int calls = 0;
        for (const Made& made : recordings()) {
            if (!made.is_phone_call) continue;
            ++calls;
            CAPTURE(made.path);
            const Timeline timeline = aligner.align_file(made.path, transcript);
            REQUIRE(timeline.syllables.size() == reference.syllables.size());
            // All but two syllables within 30 ms of the WAV's, none over 0.25 s off: without the
            // sound above 3.4 kHz the models place 園 after 公 140-160 ms early in the PCM, MP3 and
            // AAC calls, and the MP3's 裡 too (the GSM and Opus ones place them right; bench/
            // r-phone, a person's voice: 94% of onsets within 50 ms, as r-white20).
            std::size_t close = 0;
            for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
                CAPTURE(i);
                const double off_s = std::fabs(timeline.syllables[i].start_s - reference.syllables[i].start_s);
                CHECK(off_s <= 0.25);
                close += off_s <= 0.0301;
            }
            CHECK(close + 2 >= timeline.syllables.size());
        }
        CHECK(calls == 6);
    }

    TEST_CASE("stereo with one side's polarity inverted reads as the voice, not as silence") {
        // A miswired microphone or a "wide" effect leaves one channel the other's negative; their
        // plain average is nothing, and the recording was refused as silent (-96 dBFS). In a WAV
        // (libsndfile), an M4A (FFmpeg) and the caller's samples, the mix keeps the voice's level.
        const auto wav = detail::open_audio_file(speech_clip("one_sentence.wav"));
        const std::vector<float> mono = test::read_all(*wav);
        const auto rms = [](const std::vector<float>& samples) {
            double sum = 0.0;
            for (const float sample : samples) sum += static_cast<double>(sample) * sample;
            return std::sqrt(sum / static_cast<double>(samples.size()));
        };
        const std::string inverted = "-af 'pan=stereo|c0=c0|c1=-1*c0' ";
        for (const std::string& path : {ffmpeg_made("inverted.wav", inverted + "-c:a pcm_s16le"),
                                        ffmpeg_made("inverted.m4a", inverted + "-c:a aac -b:a 96k")}) {
            CAPTURE(path);
            const auto source = detail::open_audio_file(path);
            CHECK(rms(test::read_all(*source)) >= 0.9 * rms(mono));
        }
        std::vector<float> interleaved;
        for (const float sample : mono) interleaved.insert(interleaved.end(), {sample, -sample});
        const auto view = detail::open_audio_view({interleaved.data(), mono.size(), 2, wav->sample_rate_hz()});
        const std::vector<float> mixed = test::read_all(*view);
        REQUIRE(mixed.size() == mono.size());
        // Turned over once the first 1024 frames are mixed (their sum is nothing), and exact from there.
        std::size_t differing = 0;
        for (std::size_t i = 0; i < mono.size(); ++i) differing += mixed[i] != mono[i];
        CHECK(differing <= 1024);

        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        const SpeechAligner aligner;
        const Timeline reference = aligner.align_file(speech_clip("one_sentence.wav"), transcript);
        const Timeline timeline = aligner.align_file(test::output_path("inverted.wav"), transcript);
        check_starts_as(timeline, reference, 0.0, 0.0101);
    }

    TEST_CASE("a video whose sound starts 0.5 s after its picture is read with the picture's time") {
        // A camera or screen recorder that starts its sound late: players play silence until it
        // starts. On 2d28134 the sound was read from its own start, every syllable 0.44-0.49 s early
        // against the video (the MP4's first AAC frame is the encoder's delay, 64 ms).
        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        const SpeechAligner aligner;
        const Timeline reference = aligner.align_file(speech_clip("one_sentence.wav"), transcript);
        for (const std::string& file : {std::string("late_sound.mp4"), std::string("late_sound.mkv")}) {
            CAPTURE(file);
            const std::string codecs =
                file == "late_sound.mp4" ? "-c:v libx264 -c:a aac -b:a 64k" : "-c:v libvpx -c:a libopus";
            const std::string path =
                test::made_by_command(file,
                                      "ffmpeg -nostdin -loglevel error -y -f lavfi -i "
                                      "color=c=gray:s=16x16:r=2:d=3.6 -itsoffset 0.5 -i '" +
                                          speech_clip("one_sentence.wav") + "' -map 0:v -map 1:a " + codecs);
            const auto source = detail::open_audio_file(path);
            const std::vector<float> samples = test::read_all(*source);
            const auto silent = static_cast<std::size_t>(0.4 * source->sample_rate_hz());
            REQUIRE(samples.size() > silent);
            CHECK(std::all_of(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(silent),
                              [](float sample) { return sample == 0.0f; }));
            REQUIRE(source->notes().size() == 1);
            CHECK_MESSAGE(source->notes()[0].find("after its picture") != std::string::npos,
                          source->notes()[0]);
            const Timeline timeline = aligner.align_file(path, transcript);
            check_starts_as(timeline, reference, 0.5, 0.0301);
        }
    }
}

TEST_SUITE("audio") {
    TEST_CASE("of several sound tracks, the one with the speech is read, and the user is told which") {
        // OBS writes the desktop's sound and the microphone's as two tracks, the first empty where
        // nothing played: on 5842241 the first was read, and the recording refused as silent.
        const auto wav = detail::open_audio_file(speech_clip("one_sentence.wav"));
        const std::vector<float> reference = test::read_all(*wav);
        const std::vector<double> reference_loudness = test::envelope(reference, wav->sample_rate_hz());
        const std::string picture = "-f lavfi -i color=c=gray:s=16x16:r=2:d=3.6 ";
        const std::string silence = "-f lavfi -i anullsrc=r=48000:cl=stereo:d=3.6 ";
        // A held chord under a plucked line.
        const std::string music =
            "-f lavfi -i 'aevalsrc=0.05*sin(2*PI*220*t)+0.2*(0.1+0.9*exp(-6*mod(t\\,0.375)))*"
            "sin(2*PI*t*440*pow(2\\,floor(mod(t/0.375\\,5))*2/12)):s=48000:d=3.6' ";
        // A drum kit alone: a falling kick each beat, a snare, a hi-hat; as many low-energy frames as
        // the voice has, but seldom voiced, so a beat as the default track beside the voice kept the
        // beat on 436b8aa.
        const std::string drums =
            "-f lavfi -i 'aevalsrc=0.3*(sin(2*PI*(50*mod(t\\,0.5)+3.2*(1-exp(-mod(t\\,0.5)/0.04))))*"
            "exp(-mod(t\\,0.5)/0.15)+(0.5*(2*random(0)-1)+0.3*sin(2*PI*190*t))*exp(-mod(t+0.25\\,0.5)/0.1)*"
            "lt(mod(t+0.25\\,1)\\,0.5)+0.2*(2*random(1)-1)*exp(-mod(t\\,0.25)/0.03)):s=48000:d=3.6' ";
        const std::string voice = "-i '" + speech_clip("one_sentence.wav") + "' ";
        struct Tracks {
            std::string name;
            std::string inputs;
            std::string maps;
            std::string said;
        };
        const std::vector<Tracks> files = {
            {"screen_recording.mkv", silence + voice, "-map 0:v -map 1:a -map 2:a",
             "it has 2 sound tracks: the second was read, for the first is silent; to align another"},
            {"music_first.mp4", music + voice, "-map 0:v -map 1:a -map 2:a",
             "it has 2 sound tracks: the second was read, for it sounds more like speech than the first; to "
             "align another"},
            {"three_tracks.mp4", music + silence + voice, "-map 0:v -map 1:a -map 2:a -map 3:a",
             "it has 3 sound tracks: the third was read, for it sounds more like speech than the first; the "
             "other: the second (silent)"},
            {"drums_first.mkv", drums + voice, "-map 0:v -map 1:a -map 2:a",
             "it has 2 sound tracks: the second was read, for it sounds more like speech than the first; to "
             "align another"},
            {"drums_second.mkv", voice + drums, "-map 0:v -map 1:a -map 2:a",
             "it has 2 sound tracks: the first was read; the other: the second"},
            // A film's languages, each speech: the default track, the first, is read.
            {"two_voices.mkv", voice + voice, "-map 0:v -map 1:a -map 2:a",
             "it has 2 sound tracks: the first was read; the other: the second"}};
        for (const Tracks& tracks : files) {
            CAPTURE(tracks.name);
            const std::string path = test::made_by_command(
                tracks.name, "ffmpeg -nostdin -loglevel error -y " + picture + tracks.inputs + tracks.maps +
                                 " -c:v libx264 -c:a aac -b:a 64k -shortest");
            const auto source = detail::open_audio_file(path);
            const std::vector<float> samples = test::read_all(*source);
            CHECK(std::abs(test::best_lag(reference_loudness,
                                          test::envelope(samples, source->sample_rate_hz()))) <= 1);
            REQUIRE(source->notes().size() == 1);
            CHECK_MESSAGE(source->notes()[0].find(tracks.said) == 0, source->notes()[0]);
        }
        const Timeline transcript = load_transcript(speech_clip("one_sentence.txt"));
        const SpeechAligner aligner;
        const Timeline reference_timeline = aligner.align_file(speech_clip("one_sentence.wav"), transcript);
        const Timeline timeline = aligner.align_file(test::output_path("screen_recording.mkv"), transcript);
        check_starts_as(timeline, reference_timeline, 0.0, 0.0301);
    }
}
