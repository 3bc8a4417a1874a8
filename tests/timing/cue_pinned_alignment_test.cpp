// Subtitle cues pin the aligner (time_transcript with SRT/WebVTT, issue #15): each sentence is
// searched inside its cue, where the aligner's own cut would take a pause inside a sentence for
// the sentence end; cues that part from the transcript are refused before any audio is aligned.
#include <doctest/doctest.h>

#include <sndfile.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "common/speech_clips.hpp"
#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/timing_formats.hpp"
#include "talkface/transcript.hpp"

using talkface::Timeline;

namespace {

using talkface::test::clip_path;
using talkface::test::true_starts;

// 16-bit samples as they are: the spliced clip holds the committed clip's samples bit for bit.
std::vector<short> read_mono(const std::string& path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    REQUIRE(file != nullptr);
    REQUIRE(info.channels == 1);
    REQUIRE(info.samplerate == 16000);
    std::vector<short> samples(static_cast<std::size_t>(info.frames));
    sf_readf_short(file, samples.data(), info.frames);
    sf_close(file);
    return samples;
}

void write_wav(const std::string& path, const std::vector<short>& samples) {
    SF_INFO info{};
    info.samplerate = 16000;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    REQUIRE(file != nullptr);
    sf_writef_short(file, samples.data(), static_cast<sf_count_t>(samples.size()));
    sf_close(file);
}

std::size_t sample_at(double seconds) { return static_cast<std::size_t>(std::lround(seconds * 16000.0)); }

std::string srt_time(double seconds) {
    const auto ms = static_cast<int>(std::lround(seconds * 1000.0)) % 60000;
    char text[32];
    std::snprintf(text, sizeof text, "00:00:%02d,%03d", ms / 1000, ms % 1000);
    return text;
}

struct Cue {
    double start_s;
    double end_s;
    std::string text;
};

std::string write_srt(const std::string& name, const std::vector<Cue>& cues) {
    std::string text;
    for (std::size_t c = 0; c < cues.size(); ++c)
        text += std::to_string(c + 1) + "\n" + srt_time(cues[c].start_s) + " --> " + srt_time(cues[c].end_s) + "\n" +
                cues[c].text + "\n\n";
    const std::string path = talkface::test::output_path(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// two_sentences (今天下午有雨。 0.30-1.69 s, 我们明天再去吧。 2.59-4.15 s) made harder to cut:
// 0.5 s of silence after 今天 (0.853 s), and the 0.9 s pause between the sentences taken out,
// so that the only pause is inside the first sentence. The aligner's own cut ends the first
// sentence there and refuses the right text (checked by hand: "the audio does not sound like its
// text"). Returns the true onsets moved with the audio.
constexpr double kInsideS = 0.853;
constexpr double kSilenceS = 0.5;
constexpr double kFirstEndS = 1.686;
constexpr double kSecondStartS = 2.5859;

std::vector<double> make_run_together(const std::string& path) {
    const std::vector<short> clip = read_mono(clip_path("two_sentences.wav"));
    std::vector<short> audio(clip.begin(), clip.begin() + static_cast<std::ptrdiff_t>(sample_at(kInsideS)));
    // The silence is the clip's own, from the pause between its sentences (1.8-2.3 s).
    audio.insert(audio.end(), clip.begin() + static_cast<std::ptrdiff_t>(sample_at(1.8)),
                 clip.begin() + static_cast<std::ptrdiff_t>(sample_at(1.8 + kSilenceS)));
    audio.insert(audio.end(), clip.begin() + static_cast<std::ptrdiff_t>(sample_at(kInsideS)),
                 clip.begin() + static_cast<std::ptrdiff_t>(sample_at(kFirstEndS)));
    audio.insert(audio.end(), clip.begin() + static_cast<std::ptrdiff_t>(sample_at(kSecondStartS)), clip.end());
    write_wav(path, audio);
    std::vector<double> starts = true_starts("two_sentences");
    for (double& start : starts) {
        if (start >= kSecondStartS) start -= kSecondStartS - kFirstEndS;
        if (start >= kInsideS) start += kSilenceS;
    }
    return starts;
}

// Every syllable of `timeline` inside the cue of its sentence, and its onset within 50 ms of the truth.
void check_pinned(const Timeline& timeline, const std::vector<Cue>& sentence_cues, const std::vector<double>& truth) {
    REQUIRE(timeline.syllables.size() == truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const talkface::Syllable& syllable = timeline.syllables[i];
        const Cue& cue = sentence_cues[syllable.sentence];
        CAPTURE(i);
        CAPTURE(syllable.text);
        CHECK(syllable.start_s >= cue.start_s - 1e-9);
        CHECK(syllable.end_s <= cue.end_s + 1e-9);
        CHECK(std::abs(syllable.start_s - truth[i]) < 0.050);
    }
}

}  // namespace

TEST_SUITE("cue-pinned alignment") {
    TEST_CASE("each sentence is aligned inside its cue where the aligner's own cut would take a pause inside one") {
        const std::string audio = talkface::test::output_path("cue_pinned_run_together.wav");
        const std::vector<double> truth = make_run_together(audio);
        const Timeline transcript = talkface::load_transcript(clip_path("two_sentences.txt"));
        const double junction_s = kFirstEndS + kSilenceS;
        const double duration_s = talkface::audio_duration_s(audio);
        const std::vector<Cue> cues = {{0.25, junction_s, "今天下午有雨。"}, {junction_s, duration_s - 0.05, "我们明天再去吧。"}};
        const Timeline timeline = talkface::time_transcript(write_srt("cue_pinned.srt", cues), audio, transcript);
        check_pinned(timeline, cues, truth);
        CHECK(timeline.duration_s == doctest::Approx(duration_s));
        CHECK(timeline.sentences[1].start_s >= junction_s);
    }

    TEST_CASE("one cue for two sentences aligns them as one, inside it") {
        const Timeline transcript = talkface::load_transcript(clip_path("two_sentences.txt"));
        const std::vector<Cue> cue = {{0.2, 4.3, "今天下午有雨。我们明天再去吧。"}};
        const Timeline timeline =
            talkface::time_transcript(write_srt("cue_pinned_one.srt", cue), clip_path("two_sentences.wav"), transcript);
        check_pinned(timeline, {cue[0], cue[0]}, true_starts("two_sentences"));
    }

    TEST_CASE("a cue that parts from the transcript is refused, naming the first place") {
        const Timeline transcript = talkface::load_transcript(clip_path("two_sentences.txt"));
        const std::string path =
            write_srt("cue_pinned_wrong.srt", {{0.25, 1.75, "今天下午有雨。"}, {2.5, 4.3, "我们后天再去吧。"}});
        const std::string expected = path + ":6: \"我们后天再去吧。\": \"后\" parts from the transcript";
        CHECK_THROWS_WITH_AS(talkface::time_transcript(path, clip_path("two_sentences.wav"), transcript),
                             doctest::Contains(expected.c_str()), talkface::ParseError);
    }

    TEST_CASE("WebVTT cues that time every syllable are read as they are, not aligned") {
        // Times no aligner would find: a syllable every 0.3 s from 0.4 s, whatever was said.
        Timeline timed = talkface::load_transcript(clip_path("two_sentences.txt"));
        for (std::size_t i = 0; i < timed.syllables.size(); ++i) {
            timed.syllables[i].start_s = 0.4 + 0.3 * static_cast<double>(i);
            timed.syllables[i].end_s = timed.syllables[i].start_s + 0.3;
        }
        timed.sentences[0].start_s = 0.4;
        timed.sentences[0].end_s = timed.sentences[1].start_s = timed.syllables[6].start_s;
        timed.sentences[1].end_s = timed.syllables.back().end_s;
        timed.duration_s = 4.45;
        const std::string path = talkface::test::output_path("cue_pinned_karaoke.vtt");
        std::ofstream(path, std::ios::binary) << talkface::write_timing_string(timed, "vtt");
        const Timeline timeline =
            talkface::time_transcript(path, clip_path("two_sentences.wav"), talkface::load_transcript(clip_path("two_sentences.txt")));
        REQUIRE(timeline.syllables.size() == timed.syllables.size());
        for (std::size_t i = 0; i < timed.syllables.size(); ++i) {
            CAPTURE(i);
            CHECK(std::abs(timeline.syllables[i].start_s - timed.syllables[i].start_s) < 0.0015);
        }
        // Nothing is aligned, so lenient alignment has nothing to do: refused by name.
        talkface::AlignOptions lenient;
        lenient.lenient = true;
        CHECK_THROWS_WITH_AS(talkface::time_transcript(path, clip_path("two_sentences.wav"),
                                                       talkface::load_transcript(clip_path("two_sentences.txt")), lenient),
                             doctest::Contains(("lenient: " + path + " (vtt with a timestamp per syllable) times every syllable").c_str()),
                             talkface::InvalidArgument);
    }

    TEST_CASE("lenient options reach the aligner the cues pin: a word the cue's text lacks is reported, not refused") {
        // lenient_espeak says 小朋友们在公园里放风筝 (2.97 s); the cue and the transcript lack 公园.
        const Timeline transcript = talkface::read_transcript("小朋友们在里放风筝。");
        const std::string path = write_srt("cue_pinned_lenient.srt", {{0.2, 3.1, "小朋友们在里放风筝。"}});
        const std::string audio = clip_path("lenient_espeak.flac");
        CHECK(talkface::time_transcript(path, audio, transcript).mismatches.empty());  // the default: not lenient
        talkface::AlignOptions lenient;
        lenient.lenient = true;
        const Timeline timeline = talkface::time_transcript(path, audio, transcript, lenient);
        REQUIRE(timeline.mismatches.size() == 1);
        const auto truth = true_starts("lenient_espeak");
        CHECK(timeline.mismatches[0].syllable_count == 0);
        CHECK(std::abs(timeline.mismatches[0].start_s - truth[5]) < 0.05);  // 公
        CHECK(std::abs(timeline.mismatches[0].end_s - truth[7]) < 0.05);    // 里
        CHECK_FALSE(timeline.mismatches[0].loudness.empty());
    }

    TEST_CASE("lenient options with a timing that times every syllable are refused, naming lenient and why") {
        const Timeline transcript = talkface::load_transcript(clip_path("two_sentences.txt"));
        const std::string path = talkface::test::output_path("cue_pinned_words.json");
        std::ofstream(path, std::ios::binary) << talkface::write_timing_string(transcript, "words-json");
        talkface::AlignOptions lenient;
        lenient.lenient = true;
        CHECK_THROWS_WITH_AS(talkface::time_transcript(path, clip_path("two_sentences.wav"), transcript, lenient),
                             doctest::Contains("(json) times every syllable itself: nothing is aligned"),
                             talkface::InvalidArgument);
        lenient.c1 = 2.0;
        CHECK_THROWS_WITH_AS(talkface::time_transcript(path, clip_path("two_sentences.wav"), transcript, lenient),
                             doctest::Contains("c1"), talkface::InvalidArgument);
    }
}
