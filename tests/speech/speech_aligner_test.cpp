#include <doctest/doctest.h>

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "common/speech_clips.hpp"
#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

struct Clip {
    std::string audio;
    std::string name;
};

using test::clip_path;
using test::true_starts;

Timeline clip_transcript(const std::string& name) { return load_transcript(clip_path(name + ".txt")); }

std::vector<double> sentence_truth(const std::string& name, const char* key) {
    std::ifstream in(clip_path(name + ".json"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<double> values;
    const std::size_t end = text.find("\"syllables\"");
    const std::string pattern = std::string("\"") + key + "\":";
    for (std::size_t at = text.find(pattern); at != std::string::npos && at < end; at = text.find(pattern, at + 1))
        values.push_back(std::stod(text.substr(at + pattern.size())));
    return values;
}

std::vector<float> read_mono(const std::string& path, int& rate_hz) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    REQUIRE(file != nullptr);
    std::vector<float> samples(static_cast<std::size_t>(info.frames * info.channels));
    sf_readf_float(file, samples.data(), info.frames);
    sf_close(file);
    rate_hz = info.samplerate;
    return samples;
}

void write_wav(const std::string& path, const std::vector<float>& samples, int rate_hz, int format = SF_FORMAT_PCM_16) {
    SF_INFO info{};
    info.samplerate = rate_hz;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | format;
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    REQUIRE(file != nullptr);
    sf_writef_float(file, samples.data(), static_cast<sf_count_t>(samples.size()));
    sf_close(file);
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// Properties every aligned timeline has, whatever the audio.
void check_well_formed(const Timeline& timeline, const Timeline& transcript) {
    REQUIRE(timeline.syllables.size() == transcript.syllables.size());
    REQUIRE(timeline.sentences.size() == transcript.sentences.size());
    double previous_end = 0.0;
    for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
        const auto& syllable = timeline.syllables[i];
        CAPTURE(i);
        CAPTURE(syllable.pinyin);
        CHECK(syllable.pinyin == transcript.syllables[i].pinyin);
        CHECK(syllable.start_s >= previous_end - 1e-9);
        CHECK(syllable.start_s < syllable.end_s);
        REQUIRE(syllable.final_start_s.has_value());
        CHECK(*syllable.final_start_s >= syllable.start_s);
        CHECK(*syllable.final_start_s < syllable.end_s);
        const char initial = syllable.pinyin[0];
        if (initial != 'y' && initial != 'w' && std::string("aeo").find(initial) == std::string::npos)
            CHECK(*syllable.final_start_s > syllable.start_s);
        CHECK(syllable.confidence >= 0.0);
        CHECK(syllable.confidence <= 1.0);
        CHECK(syllable.end_s <= timeline.duration_s + 1e-9);
        previous_end = syllable.end_s;
    }
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        CHECK(timeline.sentences[k].start_s <= timeline.sentences[k].end_s);
        if (k > 0) CHECK(timeline.sentences[k].start_s >= timeline.sentences[k - 1].end_s);
    }
}

double share_within(const Timeline& timeline, const std::vector<double>& truth, double tolerance_s) {
    REQUIRE(truth.size() == timeline.syllables.size());
    std::size_t within = 0;
    for (std::size_t i = 0; i < truth.size(); ++i)
        if (std::fabs(timeline.syllables[i].start_s - truth[i]) <= tolerance_s) ++within;
    return static_cast<double>(within) / static_cast<double>(truth.size());
}

// Vowel-like bursts (a 150 Hz buzz with formant-ish harmonics), 0.2 s each with 0.05 s gaps,
// one group per sentence, groups 0.7 s apart, in faint noise.
std::vector<float> synthetic_speech(const std::vector<int>& syllables_per_sentence, int rate_hz,
                                    std::vector<double>& pause_midpoints_s) {
    std::vector<float> samples(static_cast<std::size_t>(0.4 * rate_hz), 0.0f);
    for (std::size_t k = 0; k < syllables_per_sentence.size(); ++k) {
        if (k > 0) {
            pause_midpoints_s.push_back((static_cast<double>(samples.size()) + 0.35 * rate_hz) / rate_hz);
            samples.resize(samples.size() + static_cast<std::size_t>(0.7 * rate_hz), 0.0f);
        }
        for (int s = 0; s < syllables_per_sentence[k]; ++s) {
            const auto length = static_cast<std::size_t>(0.2 * rate_hz);
            for (std::size_t i = 0; i < length; ++i) {
                const double t = static_cast<double>(i) / rate_hz;
                const double envelope = std::sin(M_PI * static_cast<double>(i) / static_cast<double>(length));
                double value = 0.0;
                for (int h = 1; h <= 20; ++h) value += std::sin(2.0 * M_PI * 150.0 * h * t) / h * (h >= 4 && h <= 6 ? 3.0 : 1.0);
                samples.push_back(static_cast<float>(0.1 * envelope * value));
            }
            samples.resize(samples.size() + static_cast<std::size_t>(0.05 * rate_hz), 0.0f);
        }
    }
    samples.resize(samples.size() + static_cast<std::size_t>(0.4 * rate_hz), 0.0f);
    std::mt19937 random(7);
    std::normal_distribution<float> noise(0.0f, 0.001f);
    for (auto& sample : samples) sample += noise(random);
    return samples;
}

// The transcript of tests/data/speech/NAME.txt with every punctuation mark taken out.
std::string unpunctuated_text(const std::string& name) {
    std::ifstream in(clip_path(name + ".txt"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* mark : {"\xE3\x80\x82", "\xEF\xBC\x8C", "\n"})  // 。 ， and line ends
        for (std::size_t at = text.find(mark); at != std::string::npos; at = text.find(mark))
            text.erase(at, std::string(mark).size());
    return text;
}

// Minutes of speech: the 16 kHz mono clips over and over, between pauses of 0.2-1.2 s, with the
// true onsets moved to where each copy starts.
struct JoinedSpeech {
    std::vector<float> samples;
    std::string text;
    std::vector<double> starts;
};

JoinedSpeech join_clips(double minimum_s) {
    const char* const names[] = {"one_sentence", "two_sentences", "comma_pause"};
    const char* const audio[] = {"one_sentence.wav", "two_sentences.wav", "comma_pause.flac"};
    JoinedSpeech joined;
    for (std::size_t copy = 0; static_cast<double>(joined.samples.size()) < minimum_s * 16000; ++copy) {
        const std::size_t clip = copy % 3;
        int rate_hz = 0;
        const auto samples = read_mono(clip_path(audio[clip]), rate_hz);
        REQUIRE(rate_hz == 16000);
        joined.samples.resize(joined.samples.size() + 3200 * (copy % 6), 0.0f);
        const double offset_s = static_cast<double>(joined.samples.size()) / 16000.0;
        for (double start : true_starts(names[clip])) joined.starts.push_back(offset_s + start);
        joined.samples.insert(joined.samples.end(), samples.begin(), samples.end());
        joined.text += unpunctuated_text(names[clip]);
    }
    std::mt19937 random(11);
    std::normal_distribution<float> noise(0.0f, 0.0005f);
    for (auto& sample : joined.samples) sample += noise(random);
    return joined;
}

}  // namespace

TEST_SUITE("SpeechAligner") {
    TEST_CASE("every clip format aligns: ordered syllables inside the audio, onsets near the truth") {
        const std::vector<Clip> clips = {{"one_sentence.wav", "one_sentence"},
                                         {"two_sentences.wav", "two_sentences"},
                                         {"comma_pause.flac", "comma_pause"},
                                         {"stereo_44k.ogg", "stereo_44k"}};
        for (const auto& clip : clips) {
            CAPTURE(clip.audio);
            const Timeline transcript = clip_transcript(clip.name);
            const Timeline timeline = SpeechAligner().align_file(clip_path(clip.audio), transcript);
            check_well_formed(timeline, transcript);
            // An even split of each sentence puts about a third of onsets within 50 ms; the
            // aligner must do far better (the benchmark measures the real targets).
            CHECK(share_within(timeline, true_starts(clip.name), 0.05) >= 0.75);
            CHECK(share_within(timeline, true_starts(clip.name), 0.10) >= 0.85);
        }
    }

    TEST_CASE("sentence boundaries are found at the pause between sentences") {
        const Timeline timeline = SpeechAligner().align_file(clip_path("two_sentences.wav"), clip_transcript("two_sentences"));
        const auto starts = sentence_truth("two_sentences", "start");
        const auto ends = sentence_truth("two_sentences", "end");
        REQUIRE(starts.size() == 2);
        for (std::size_t k = 0; k < 2; ++k) {
            CAPTURE(k);
            CHECK(std::fabs(timeline.sentences[k].start_s - starts[k]) < 0.05);
            CHECK(std::fabs(timeline.sentences[k].end_s - ends[k]) < 0.08);
        }
    }

    TEST_CASE("sentences run together without a pause end where their syllables do") {
        // The only pauses are the commas inside the sentences: cut there, the first sentence
        // ended half-way and the rest were squeezed, with no error (issue #4).
        const Timeline transcript = clip_transcript("run_together");
        const Timeline timeline = SpeechAligner().align_file(clip_path("run_together.flac"), transcript);
        check_well_formed(timeline, transcript);
        const auto starts = sentence_truth("run_together", "start");
        const auto ends = sentence_truth("run_together", "end");
        REQUIRE(starts.size() == 3);
        for (std::size_t k = 0; k < 3; ++k) {
            CAPTURE(k);
            CHECK(std::fabs(timeline.sentences[k].start_s - starts[k]) < 0.1);
            CHECK(std::fabs(timeline.sentences[k].end_s - ends[k]) < 0.1);
        }
        CHECK(share_within(timeline, true_starts("run_together"), 0.05) >= 0.75);
    }

    TEST_CASE("a wrong transcript of sentences run together is an AlignmentError naming where") {
        const SpeechAligner aligner;
        const std::string audio = clip_path("run_together.flac");
        SUBCASE("a missing sentence") {
            CHECK_THROWS_WITH_AS(aligner.align_file(audio, read_transcript("他每天早上跑步，锻炼身体。我们都觉得他的脸色很好。")),
                                 doctest::Contains("sentence 2 ("), AlignmentError);
        }
        SUBCASE("an extra sentence") {
            CHECK_THROWS_WITH_AS(
                aligner.align_file(audio, read_transcript("他每天早上跑步，锻炼身体。我们都觉得他的脸色很好。明天，他要去北京开会。他们都很好。")),
                doctest::Contains("run_together.flac: "), AlignmentError);
        }
        SUBCASE("two sentences swapped") {
            CHECK_THROWS_WITH_AS(
                aligner.align_file(audio, read_transcript("他每天早上跑步，锻炼身体。明天，他要去北京开会。我们都觉得他的脸色很好。")),
                doctest::Contains("does not sound like its text"), AlignmentError);
        }
        SUBCASE("another sentence of as many syllables") {
            CHECK_THROWS_WITH_AS(
                aligner.align_file(audio, read_transcript("他每天早上跑步，锻炼身体。小朋友们在公园里放风筝。明天，他要去北京开会。")),
                doctest::Contains("\"小朋友们在公园里放风筝。\""), AlignmentError);
        }
    }

    TEST_CASE("the automatic cut finds synthetic sentences between tone bursts in noise") {
        const int rate_hz = 22050;
        std::vector<double> pauses_s;
        const auto samples = synthetic_speech({3, 5, 2}, rate_hz, pauses_s);
        const Timeline transcript = read_transcript("a1 a1 a1. a1 a1 a1 a1 a1. a1 a1.");
        AudioView view{samples.data(), samples.size(), 1, rate_hz};
        const Timeline timeline = SpeechAligner().align(view, transcript);
        REQUIRE(timeline.sentences.size() == 3);
        for (std::size_t k = 0; k + 1 < 3; ++k) {
            CAPTURE(k);
            CHECK(timeline.sentences[k].end_s < pauses_s[k]);
            CHECK(timeline.sentences[k + 1].start_s > pauses_s[k]);
            CHECK(pauses_s[k] - timeline.sentences[k].end_s < 0.45);
            CHECK(timeline.sentences[k + 1].start_s - pauses_s[k] < 0.45);
        }
    }

    TEST_CASE("Algorithm 3.1 cuts sentences from the first pause the caller selects") {
        AlignOptions options;
        options.sentence_cut = SentenceCutMode::first_pause;
        options.first_pause_start_s = 1.8;
        options.first_pause_end_s = 2.4;
        const Timeline transcript = clip_transcript("two_sentences");
        const Timeline timeline = SpeechAligner(options).align_file(clip_path("two_sentences.wav"), transcript);
        check_well_formed(timeline, transcript);
        const auto starts = sentence_truth("two_sentences", "start");
        CHECK(std::fabs(timeline.sentences[1].start_s - starts[1]) < 0.06);

        options.first_pause_start_s = 0.9;  // inside the first sentence: the gaps between syllables
        options.first_pause_end_s = 0.92;
        CHECK_THROWS_WITH_AS(SpeechAligner(options).align_file(clip_path("two_sentences.wav"), transcript),
                             doctest::Contains("speaking parts"), AlignmentError);
        options.first_pause_start_s = 9.0;
        options.first_pause_end_s = 9.5;
        CHECK_THROWS_WITH_AS(SpeechAligner(options).align_file(clip_path("two_sentences.wav"), transcript),
                             doctest::Contains("first_pause"), InvalidArgument);
    }

    TEST_CASE("options out of range are named") {
        AlignOptions options;
        options.c1 = 0.3;
        CHECK_THROWS_WITH_AS(SpeechAligner{options}, doctest::Contains("c1"), InvalidArgument);
        options.c1 = 0.95;
        options.c2 = 2.0;
        CHECK_THROWS_WITH_AS(SpeechAligner{options}, doctest::Contains("c2"), InvalidArgument);
        options.c2 = 1.45;
        options.sentence_cut = SentenceCutMode::first_pause;
        options.first_pause_start_s = 2.0;
        options.first_pause_end_s = 1.0;
        CHECK_THROWS_WITH_AS(SpeechAligner{options}, doctest::Contains("first_pause"), InvalidArgument);
    }

    TEST_CASE("a transcript that does not match the audio is an AlignmentError naming where") {
        const SpeechAligner aligner;
        SUBCASE("an extra sentence") {
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("two_sentences.wav"),
                                                    read_transcript("今天下午有雨。我们明天再去吧。他们都很好。")),
                                 doctest::Contains("3 spoken sentences"), AlignmentError);
        }
        SUBCASE("a missing sentence") {
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("two_sentences.wav"), read_transcript("今天下午有雨。")),
                                 doctest::Contains("sentence 1 (0."), AlignmentError);
        }
        SUBCASE("the wrong text: far too few syllables") {
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("one_sentence.wav"), read_transcript("我很好。")),
                                 doctest::Contains("\"我很好。\""), AlignmentError);
        }
        SUBCASE("the wrong text of the same length: two sentences swapped") {
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("two_sentences.wav"), read_transcript("我们明天再去吧。今天下午有雨。")),
                                 doctest::Contains("does not sound like its text"), AlignmentError);
        }
        SUBCASE("the wrong text of the same length: another sentence of as many syllables") {
            const Timeline replaced = read_transcript("今天下午有雨。四十四只石狮子。");
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("two_sentences.wav"), replaced),
                                 doctest::Contains("sentence 2 (2."), AlignmentError);
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("two_sentences.wav"), replaced),
                                 doctest::Contains("\"四十四只石狮子。\""), AlignmentError);
        }
        SUBCASE("the wrong text of the same length in a file of one sentence") {
            // The hardest case: no other sentence to compare with, and models re-estimated on it
            // fit any text. The checks together find about three in ten of such texts
            // (bench/README.md); this one differs enough for the syllables' rhythm (and, before the
            // analysis dithered digital silence, for the held-out halves).
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("one_sentence.wav"), read_transcript("我昨天在超市买了苹果和。")),
                                 doctest::Contains("is it another sentence, or are two sentences swapped?"), AlignmentError);
        }
        SUBCASE("the wrong text of a similar length in a file of one sentence, forced out of the voice's rhythm") {
            // Ten syllables for twelve, as the benchmark picks them: the held-out halves pass it, the
            // lengths the path gives its syllables do not (bench/README.md: with the fit on the
            // file's own models, 31% of one-sentence wrong texts found, 26% before). 上 is fixed to
            // shang4, the reading the text was picked with: read wan3 shang5 (the light tone the
            // reader gives 晚上 since session 20), its lengths spread less than the 2.01 allowed.
            const auto wrong = read_transcript("图书馆周末开放到晚上{shang4}。");
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("one_sentence.wav"), wrong),
                                 doctest::Contains("sentence 1 (0."), AlignmentError);
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("one_sentence.wav"), wrong),
                                 doctest::Contains("one voice's rhythm"), AlignmentError);
        }
        SUBCASE("the wrong text: far too many syllables") {
            CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("two_sentences.wav"),
                                                    read_transcript("今天下午有雨。我们明天再去吧吗吗吗吗吗吗。")),
                                 doctest::Contains("sentence 2"), AlignmentError);
        }
    }

    TEST_CASE("minutes of speech whose transcript has no punctuation align as one sentence") {
        // Three minutes: searched in windows, past the first pass's two minutes on hand-set models.
        const JoinedSpeech joined = join_clips(190.0);
        const Timeline transcript = read_transcript(joined.text);
        REQUIRE(transcript.sentences.size() == 1);
        const Timeline timeline = SpeechAligner().align(AudioView{joined.samples.data(), joined.samples.size(), 1, 16000}, transcript);
        check_well_formed(timeline, transcript);
        CHECK(share_within(timeline, joined.starts, 0.05) >= 0.85);
        CHECK(share_within(timeline, joined.starts, 0.10) >= 0.95);
    }

    TEST_CASE("a message quotes a long sentence by its start") {
        std::string text;
        for (int i = 0; i < 6; ++i) text += "今天下午有雨我们明天再去吧";
        try {
            SpeechAligner().align_file(clip_path("two_sentences.wav"), read_transcript(text + "。"));
            FAIL("78 syllables in 3 s of speech aligned");
        } catch (const AlignmentError& error) {
            const std::string message = error.what();
            CHECK(message.find("sentence 1 (0.") != std::string::npos);
            CHECK(message.find("\"今天下午有雨我们明天再去吧今天下午有雨我\xE2\x80\xA6\")") != std::string::npos);
            CHECK(message.find(text) == std::string::npos);
        }
    }

    TEST_CASE("a transcript with nothing to align says what its reader skipped") {
        const SpeechAligner aligner;
        // A star and a full-width ampersand, each alone: a speaker may say either, so each is warned of (an
        // emoji is unsaid without a warning, as punctuation is, and would leave nothing to report; since
        // session 32 a katakana letter is said, ア a, and an ampersand between two words, and).
        const Timeline symbols = read_transcript("\xE2\x98\x85 \xEF\xBC\x86");
        CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("one_sentence.wav"), symbols),
                             doctest::Contains("no syllables to align (0 sentences, none with a Mandarin reading; <transcript>:1:1: "),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(aligner.align_file(clip_path("one_sentence.wav"), symbols),
                             doctest::Contains("has no Mandarin reading; skipped (and 1 more warning))"), InvalidArgument);
    }

    TEST_CASE("unreadable, empty, silent and truncated audio name the file and what is wrong") {
        const SpeechAligner aligner;
        const Timeline transcript = read_transcript("ni3 hao3.");
        const std::string missing = test::output_path("no_such_audio.wav");
        CHECK_THROWS_WITH_AS(aligner.align_file(missing, transcript), doctest::Contains(missing.c_str()), FileError);

        const std::string text = test::output_path("not_audio.wav");
        write_bytes(text, "this is not a sound file, only text.\n");
        // A text file is named as one (a transcript given as the recording is the likely slip).
        CHECK_THROWS_WITH_AS(aligner.align_file(text, transcript), doctest::Contains((text + ": a text file").c_str()),
                             ParseError);

        const std::string empty = test::output_path("empty.wav");
        write_bytes(empty, "");
        CHECK_THROWS_WITH_AS(aligner.align_file(empty, transcript), doctest::Contains("empty"), InvalidArgument);

        const std::string no_frames = test::output_path("no_frames.wav");
        write_wav(no_frames, {}, 16000);
        CHECK_THROWS_WITH_AS(aligner.align_file(no_frames, transcript), doctest::Contains((no_frames + ": empty").c_str()),
                             InvalidArgument);

        const std::string silent = test::output_path("silent.wav");
        write_wav(silent, std::vector<float>(16000, 0.0f), 16000);
        CHECK_THROWS_WITH_AS(aligner.align_file(silent, transcript), doctest::Contains((silent + ": silent").c_str()), InvalidArgument);

        int rate_hz = 0;
        const auto samples = read_mono(clip_path("one_sentence.wav"), rate_hz);
        const std::string whole = test::output_path("whole.wav");
        write_wav(whole, samples, rate_hz);
        const std::string bytes = [&] {
            std::ifstream in(whole, std::ios::binary);
            return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        }();
        const std::string truncated = test::output_path("truncated.wav");
        write_bytes(truncated, bytes.substr(0, 44 + 2 * 20000));
        CHECK_THROWS_WITH_AS(aligner.align_file(truncated, transcript),
                             doctest::Contains((truncated + ": truncated: the header promises " +
                                                                std::to_string(samples.size()) + " frames")
                                                                   .c_str()),
                             FileError);
        CHECK_THROWS_WITH_AS(aligner.align_file(truncated, transcript), doctest::Contains("ends at frame 20000 (1.25 s)"),
                             FileError);
    }

    TEST_CASE("samples in memory align like the file they came from, and twice the same") {
        int rate_hz = 0;
        const auto samples = read_mono(clip_path("comma_pause.flac"), rate_hz);
        const Timeline transcript = clip_transcript("comma_pause");
        const SpeechAligner aligner;
        const Timeline from_file = aligner.align_file(clip_path("comma_pause.flac"), transcript);
        const Timeline from_memory = aligner.align(AudioView{samples.data(), samples.size(), 1, rate_hz}, transcript);
        const Timeline again = aligner.align(AudioView{samples.data(), samples.size(), 1, rate_hz}, transcript);
        for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
            CAPTURE(i);
            CHECK(from_memory.syllables[i].start_s == from_file.syllables[i].start_s);
            CHECK(from_memory.syllables[i].end_s == from_file.syllables[i].end_s);
            CHECK(again.syllables[i].start_s == from_memory.syllables[i].start_s);
            CHECK(again.syllables[i].final_start_s == from_memory.syllables[i].final_start_s);
            CHECK(again.syllables[i].confidence == from_memory.syllables[i].confidence);
        }
        CHECK_THROWS_WITH_AS(aligner.align(AudioView{nullptr, 10, 1, 16000}, transcript), doctest::Contains("audio.samples"),
                             InvalidArgument);
        CHECK_THROWS_WITH_AS(aligner.align(AudioView{samples.data(), samples.size(), 1, rate_hz}, read_transcript("♪♪.")),
                             doctest::Contains("transcript"), InvalidArgument);
    }

    TEST_CASE("progress rises through the stages, and returning false cancels") {
        const Timeline transcript = clip_transcript("two_sentences");
        std::vector<std::pair<double, std::string>> reports;
        SpeechAligner().align_file(clip_path("two_sentences.wav"), transcript, [&](double fraction, const std::string& stage) {
            reports.emplace_back(fraction, stage);
            return true;
        });
        REQUIRE(reports.size() >= 5);
        CHECK(reports.front().second == "reading");
        CHECK(reports.back().first == 1.0);
        CHECK(reports.back().second == "syllables");
        for (std::size_t i = 1; i < reports.size(); ++i) {
            CAPTURE(i);
            CHECK(reports[i].first >= reports[i - 1].first);
        }
        CHECK(std::any_of(reports.begin(), reports.end(), [](const auto& r) { return r.second == "sentences"; }));

        int calls = 0;
        CHECK_THROWS_AS(SpeechAligner().align_file(clip_path("two_sentences.wav"), transcript,
                                                   [&](double fraction, const std::string&) {
                                                       ++calls;
                                                       return fraction < 0.6;
                                                   }),
                        Cancelled);
        CHECK(calls >= 2);
    }

    // A line of about a second (你好。, 1.28 s) is read in three blocks and aligned as one chain, so its bar
    // has few steps: each stage still shows, no step jumps more than 0.4 (the longest, 0.36, is the blocks
    // read before the first step: 80% of the reading's 45%), the bar never goes back, and 1.0 comes once,
    // at the end, after the work done again (the recording read a second time).
    TEST_CASE("a one-second line's progress shows each stage in small steps and reaches 1.0 only when done") {
        std::vector<std::pair<double, std::string>> reports;
        SpeechAligner().align_file(clip_path("short_line.flac"), clip_transcript("short_line"),
                                   [&](double fraction, const std::string& stage) {
                                       reports.emplace_back(fraction, stage);
                                       return true;
                                   });
        REQUIRE(reports.size() >= 8);
        CHECK(reports.front().second == "reading");
        for (const char* stage : {"reading", "sentences", "syllables"}) {
            CAPTURE(stage);
            CHECK(std::count_if(reports.begin(), reports.end(),
                                [&](const auto& r) { return r.second == stage; }) >= 1);
        }
        CHECK(std::count_if(reports.begin(), reports.end(),
                            [](const auto& r) { return r.second == "syllables"; }) >= 4);
        for (std::size_t i = 1; i < reports.size(); ++i) {
            CAPTURE(i);
            CHECK(reports[i].first >= reports[i - 1].first);
            CHECK(reports[i].first - reports[i - 1].first <= 0.4);
            CHECK((reports[i - 1].first < 1.0));
        }
        CHECK(reports.back().first == 1.0);
    }
}
