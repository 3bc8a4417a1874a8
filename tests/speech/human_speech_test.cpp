// The aligner on a person's voice (issue 12): a phrase joined in the test from the syllables
// Debian's gcin-voice recorded of its speaker 3 (the project's development voice; the other
// speaker is kept for measurement and never read), with the joins as the truth. Labelled slow:
// it reads 15 recordings.
#include <doctest/doctest.h>

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "common/room_audio.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

const char* const kVoiceDir = "/usr/share/gcin-voice/ogg/";

struct Spoken {
    const char* folder;  // gcin-voice's zhuyin and tone
    bool has_closure;    // a stop or affricate: after speech it starts with a closure (SPEC "Alignment")
    bool is_voiced;      // m n l r or no initial: it runs on from the vowel before, voiced
    // Said quickly: only its first heard_s seconds, the last 20 ms faded out (0: all of it).
    double heard_s = 0.0;
};

// 今天天氣很好，我們去公園散步吧。
const std::vector<Spoken> kPhrase = {
    {"ㄐㄧㄣ", true, false}, {"ㄊㄧㄢ", true, false}, {"ㄊㄧㄢ", true, false}, {"ㄑㄧ4", true, false},
    {"ㄏㄣ3", false, false}, {"ㄏㄠ3", false, false}, {"ㄨㄛ3", false, true},  {"ㄇㄣ2", false, true},
    {"ㄑㄩ4", true, false},  {"ㄍㄨㄥ", true, false}, {"ㄩㄢ2", false, true},  {"ㄙㄢ4", false, false},
    {"ㄅㄨ4", true, false},  {"ㄅㄚ1", true, false},
};
constexpr std::size_t kCommaAfter = 5;  // 好，

// Speaker 3's recording of `folder`, mono, its DC offset removed and trimmed to its sound: from
// the first 5 ms within 45 dB of its loudest to the last within 25 dB.
std::vector<float> recorded(const std::string& folder, int& rate_hz) {
    const std::string path = kVoiceDir + folder + "/3.ogg";
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    REQUIRE_MESSAGE(file != nullptr, path << " (Debian package gcin-voice)");
    std::vector<float> interleaved(static_cast<std::size_t>(info.frames * info.channels));
    sf_readf_float(file, interleaved.data(), info.frames);
    sf_close(file);
    rate_hz = info.samplerate;
    std::vector<float> samples(static_cast<std::size_t>(info.frames));
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = interleaved[i * static_cast<std::size_t>(info.channels)];
    double mean = 0.0;
    for (float sample : samples) mean += sample;
    mean /= static_cast<double>(samples.size());
    for (float& sample : samples) sample -= static_cast<float>(mean);
    const std::size_t frame = static_cast<std::size_t>(rate_hz / 200);
    std::vector<double> level_db;
    for (std::size_t i = 0; i + frame <= samples.size(); i += frame) {
        double power = 0.0;
        for (std::size_t k = i; k < i + frame; ++k) power += double(samples[k]) * samples[k];
        level_db.push_back(10.0 * std::log10(power / static_cast<double>(frame) + 1e-12));
    }
    const double peak_db = *std::max_element(level_db.begin(), level_db.end());
    std::size_t first = 0, last = level_db.size() - 1;
    while (first < last && level_db[first] < peak_db - 45.0) ++first;
    while (last > first && level_db[last] < peak_db - 25.0) --last;
    return {samples.begin() + static_cast<std::ptrdiff_t>(first * frame),
            samples.begin() + static_cast<std::ptrdiff_t>((last + 1) * frame)};
}

struct Phrase {
    std::vector<float> samples;
    int rate_hz = 0;
    std::vector<double> starts_s;  // the truth: where each syllable starts
    double end_s = 0.0;
};

// The syllables of `spoken` joined as running speech: a stop or affricate after a 40 ms closure
// (its start is the closure's), a voiced initial cross-faded 40 ms into the vowel before, others
// right after it; a 0.25 s pause after syllable `comma_after` (none past the end), 0.3 s of
// silence around the phrase.
Phrase join_phrase(const std::vector<Spoken>& spoken = kPhrase, std::size_t comma_after = kCommaAfter) {
    Phrase phrase;
    std::size_t end = 0;
    for (std::size_t i = 0; i < spoken.size(); ++i) {
        int rate_hz = 0;
        std::vector<float> sound = recorded(spoken[i].folder, rate_hz);
        if (spoken[i].heard_s > 0.0) {
            sound.resize(std::min(sound.size(), static_cast<std::size_t>(spoken[i].heard_s * rate_hz)));
            const std::size_t fade_out = std::min(sound.size(), static_cast<std::size_t>(0.02 * rate_hz));
            for (std::size_t n = 0; n < fade_out; ++n)
                sound[sound.size() - 1 - n] *= static_cast<float>(n) / static_cast<float>(fade_out);
        }
        phrase.rate_hz = rate_hz;
        const auto samples_of = [&](double seconds) { return static_cast<std::size_t>(seconds * rate_hz); };
        const bool after_pause = i == 0 || i == comma_after + 1;
        if (i == 0) end = samples_of(0.3);
        if (i == comma_after + 1) end += samples_of(0.25);
        std::size_t at = end, start = end;
        std::size_t fade = 0;
        if (!after_pause && spoken[i].has_closure) {
            at = end + samples_of(0.04);
        } else if (!after_pause && spoken[i].is_voiced) {
            fade = std::min(samples_of(0.04), sound.size() / 4);
            at = start = end - fade;
        }
        phrase.starts_s.push_back(static_cast<double>(start) / rate_hz);
        phrase.samples.resize(std::max(phrase.samples.size(), at + sound.size()), 0.0f);
        for (std::size_t n = 0; n < sound.size(); ++n) {
            const double share = n < fade ? static_cast<double>(n) / static_cast<double>(fade) : 1.0;
            float& out = phrase.samples[at + n];
            out = static_cast<float>(out * (n < fade ? 1.0 - share : 1.0) + share * sound[n]);
        }
        end = at + sound.size();
    }
    phrase.end_s = static_cast<double>(end) / phrase.rate_hz;
    phrase.samples.resize(end + static_cast<std::size_t>(0.3 * phrase.rate_hz), 0.0f);
    return phrase;
}

// The phrase said in a reverberant room (room_audio.hpp).
Phrase phrase_in_room() {
    REQUIRE_MESSAGE(std::filesystem::exists(kVoiceDir),
                    kVoiceDir << ": install the Debian package gcin-voice");
    Phrase phrase = join_phrase();
    phrase.samples = test::in_room(phrase.samples, phrase.rate_hz);
    return phrase;
}

// `phrase` aligned to `transcript` (of as many syllables): each syllable starts within
// `tolerance_s` of the truth.
void check_starts_within(const Phrase& phrase, const Timeline& transcript, double tolerance_s) {
    const AudioView view{phrase.samples.data(), phrase.samples.size(), 1, phrase.rate_hz};
    const Timeline aligned = SpeechAligner().align(view, transcript);
    for (std::size_t i = 0; i < phrase.starts_s.size(); ++i) {
        INFO(transcript.syllables[i].text << " true " << phrase.starts_s[i] << " s, aligned "
                                          << aligned.syllables[i].start_s << " s");
        CHECK(std::fabs(aligned.syllables[i].start_s - phrase.starts_s[i]) <= tolerance_s);
    }
}

double share_within(const std::vector<double>& errors_s, double tolerance_s) {
    const auto hits = std::count_if(errors_s.begin(), errors_s.end(), [&](double e) { return e <= tolerance_s; });
    return static_cast<double>(hits) / static_cast<double>(errors_s.size());
}

}  // namespace

TEST_SUITE("human speech") {
    TEST_CASE("a phrase of speaker 3's syllables run together aligns where an even split cannot") {
        REQUIRE_MESSAGE(std::filesystem::exists(kVoiceDir), kVoiceDir << ": install the Debian package gcin-voice");
        const Phrase phrase = join_phrase();
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        REQUIRE(transcript.syllables.size() == phrase.starts_s.size());
        const AudioView view{phrase.samples.data(), phrase.samples.size(), 1, phrase.rate_hz};
        const Timeline aligned = SpeechAligner().align(view, transcript);
        std::vector<double> errors, naive_errors;
        const double step = (phrase.end_s - phrase.starts_s.front()) / static_cast<double>(phrase.starts_s.size());
        std::size_t worst = 0;
        for (std::size_t i = 0; i < phrase.starts_s.size(); ++i) {
            errors.push_back(std::fabs(aligned.syllables[i].start_s - phrase.starts_s[i]));
            naive_errors.push_back(std::fabs(phrase.starts_s.front() + step * static_cast<double>(i) - phrase.starts_s[i]));
            if (errors[i] > errors[worst]) worst = i;
            INFO(transcript.syllables[i].text << " true " << phrase.starts_s[i] << " s, aligned " << aligned.syllables[i].start_s
                                              << " s, confidence " << aligned.syllables[i].confidence);
            CHECK(errors[i] <= 0.6);
        }
        // The bound is one the naive baseline (the true span divided evenly) fails: 2 of 14 within
        // 50 ms. The aligner places 10: 很, 好 and 我 by the comma go a syllable late (氣 stretched
        // over 很, and the comma's pause taken before 好, issue 12), and 們 after them 220 ms (11
        // before the duration priors were weighted 1.5, phone_chain.hpp, which put 很 right and held
        // the runs of bench/'s running speech; 12 before the spectral landmarks of wave 7).
        CHECK(share_within(naive_errors, 0.050) < 0.6);
        CHECK(share_within(errors, 0.050) >= 0.7);
        // A syllable far off says so: its confidence is below the phrase's typical one. (Under
        // kLowAlignmentConfidence it need not be: calibrated on the recording, that threshold
        // catches about half the syllables more than 100 ms off (52% of bench/'s human tuning
        // ones) at one false alarm in ten.)
        if (errors[worst] > 0.100) {
            std::vector<double> confidences;
            for (const auto& syllable : aligned.syllables) confidences.push_back(syllable.confidence);
            std::nth_element(confidences.begin(), confidences.begin() + static_cast<std::ptrdiff_t>(confidences.size() / 2),
                             confidences.end());
            CHECK(aligned.syllables[worst].confidence < confidences[confidences.size() / 2]);
        }
    }

    TEST_CASE("in white noise at SNR 20 dB the phrase's fricatives start where they start") {
        // A weak fricative's start under noise fits the silence model better than its own; a short
        // pause took it and s, sh, x, f and h came 50-100 ms late (issue 12, bench/ r-white20).
        REQUIRE_MESSAGE(std::filesystem::exists(kVoiceDir), kVoiceDir << ": install the Debian package gcin-voice");
        Phrase phrase = join_phrase();
        double power = 0.0;
        std::size_t active = 0;
        for (float sample : phrase.samples)
            if (std::fabs(sample) > 1e-4f) {
                power += double(sample) * sample;
                ++active;
            }
        std::mt19937 random(12);
        std::normal_distribution<float> noise(0.0f, static_cast<float>(std::sqrt(power / static_cast<double>(active) / 100.0)));
        for (float& sample : phrase.samples) sample += noise(random);
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        const AudioView view{phrase.samples.data(), phrase.samples.size(), 1, phrase.rate_hz};
        const Timeline aligned = SpeechAligner().align(view, transcript);
        std::vector<double> errors;
        for (std::size_t i = 0; i < phrase.starts_s.size(); ++i) {
            errors.push_back(std::fabs(aligned.syllables[i].start_s - phrase.starts_s[i]));
            INFO(transcript.syllables[i].text << " true " << phrase.starts_s[i] << " s, aligned " << aligned.syllables[i].start_s << " s");
            // 散's s follows 園 straight on (60 ms late when a short pause could take its start).
            if (transcript.syllables[i].pinyin == "san4") CHECK(errors[i] <= 0.05);
        }
        // 13 of 14 (很 comes 70 ms early: its h begins inside the noise of 氣's falling tail).
        CHECK(share_within(errors, 0.050) >= 0.9);
    }

    TEST_CASE("in a room the phrase's syllables start where they start") {
        // The syllables are placed on the features without the room's ringing (late_reverb.hpp),
        // where a vowel that fades faster than the room rings is no ringing: with the ringing read
        // from the voice's last frames alone, the fade was taken out with it, and 很 started 81 ms
        // and 好 60 ms early (bench/README.md Session 25).
        const Phrase phrase = phrase_in_room();
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        REQUIRE(transcript.syllables.size() == phrase.starts_s.size());
        check_starts_within(phrase, transcript, 0.05);
    }

    TEST_CASE("in a room the phrase ends where its voice stops") {
        // The 18 dB mark lies 9 frames into the test room's ringing; the syllables given out are
        // searched only to where the ringing's line, followed back, says the voice stopped (57 ms
        // late on main, 37 ms here). The models still learn on the search to the mark, whose tail
        // teaches the pause the room (with them learned to the voice's end 很 started 61 ms early).
        const Phrase phrase = phrase_in_room();
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        const AudioView view{phrase.samples.data(), phrase.samples.size(), 1, phrase.rate_hz};
        const Timeline aligned = SpeechAligner().align(view, transcript);
        CHECK(std::fabs(aligned.syllables.back().end_s - phrase.end_s) <= 0.05);
    }

    TEST_CASE("in a room the bar moves while the models learn the features without the ringing") {
        // The models are re-estimated twice in a room: on the recorded features, then on the
        // features without the room's ringing (late_reverb.hpp), which takes as long. The second
        // has a share of the bar of its own, passes 4-6 of 7 (from 0.5 + 0.45 x 3 of 7), and the
        // callback can cancel there; aligned to the end, the bar never stands still below 100%. On
        // 5bb18ac it stood at the first's end (87.5%, 3 of 4 passes) all through the second, the
        // callback asked with that fraction again and again.
        const Phrase phrase = phrase_in_room();
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        const AudioView view{phrase.samples.data(), phrase.samples.size(), 1, phrase.rate_hz};
        const double first_reestimation_end = 0.5 + 0.45 * 3.0 / 7.0;
        std::vector<double> fractions;
        const auto cancel_in_second_reestimation = [&](double fraction, const std::string& stage) {
            fractions.push_back(fraction);
            return !(stage == "syllables" && fraction > first_reestimation_end + 1e-6);
        };
        CHECK_THROWS_WITH_AS(SpeechAligner().align(view, transcript, cancel_in_second_reestimation),
                             doctest::Contains("while syllables at 75.7%"), Cancelled);
        CHECK(std::is_sorted(fractions.begin(), fractions.end()));
        fractions.clear();
        SpeechAligner().align(view, transcript, [&](double fraction, const std::string&) {
            fractions.push_back(fraction);
            return true;
        });
        CHECK(std::is_sorted(fractions.begin(), fractions.end()));
        const auto below_one = std::lower_bound(fractions.begin(), fractions.end(), 1.0);
        CHECK(std::adjacent_find(fractions.begin(), below_one) == below_one);
    }

    TEST_CASE(
        "while the phrase is aligned again the bar moves below 100%, which it reaches once, at the end") {
        // 0.35 s of silence before 散, where the text marks no pause: the first alignment gives it
        // to a pause between syllables, and the phrase is aligned again with such pauses kept
        // short (cut_alignment.cpp align_cut). The checks only warn: one reading, no other phase.
        // On d608a71 the first alignment's final pass reported 100% and the bar stood there
        // through the second: the callback saw 1.0 six times, five before the work was done.
        Phrase phrase = join_phrase();
        const std::size_t san = 11;
        const auto san_start = static_cast<std::ptrdiff_t>(phrase.starts_s[san] * phrase.rate_hz);
        phrase.samples.insert(phrase.samples.begin() + san_start,
                              static_cast<std::size_t>(0.35 * phrase.rate_hz), 0.0f);
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        REQUIRE(transcript.syllables[san].text == "散");
        const AudioView view{phrase.samples.data(), phrase.samples.size(), 1, phrase.rate_hz};
        AlignOptions options;
        options.check = CheckMode::warn;
        std::vector<double> fractions;
        SpeechAligner(options).align(view, transcript, [&](double fraction, const std::string&) {
            fractions.push_back(fraction);
            return true;
        });
        REQUIRE(!fractions.empty());
        CHECK(fractions.back() == 1.0);
        CHECK(std::count(fractions.begin(), fractions.end(), 1.0) == 1);
        CHECK(std::is_sorted(fractions.begin(), fractions.end()));
        CHECK(std::adjacent_find(fractions.begin(), fractions.end()) == fractions.end());
    }

    TEST_CASE("after an apical vowel the next syllable starts where the spectrum turns") {
        // 他是一個好人。 with 是 said quickly (its first 0.3 s): the apical class, learned on the
        // phrase, fits 一's i better than the i class, and the path ran 是's vowel on over it and
        // started 一 276 ms late (main at 8650c86); where the spectrum turns from 是's vowel, 14 ms.
        REQUIRE_MESSAGE(std::filesystem::exists(kVoiceDir),
                        kVoiceDir << ": install the Debian package gcin-voice");
        const std::vector<Spoken> spoken = {
            {"ㄊㄚ", true, false},  {"ㄕ4", false, false, 0.3}, {"ㄧ", false, true},
            {"ㄍㄜ4", true, false}, {"ㄏㄠ3", false, false},    {"ㄖㄣ2", false, true},
        };
        const Phrase phrase = join_phrase(spoken, spoken.size());
        const Timeline transcript = read_transcript("他是一個好人。");
        REQUIRE(transcript.syllables.size() == phrase.starts_s.size());
        check_starts_within(phrase, transcript, 0.05);
    }

    TEST_CASE("a word silenced by an editor at a sentence's end, its text kept, is named") {
        // 步吧 of the phrase put to exact zeros: the run meets the silence after the phrase, so no
        // syllable of the sentence follows it, and the rule for a run inside a sentence (session 39)
        // passed it by; the aligner squeezes 步 and 吧 against it, 40 ms each.
        REQUIRE_MESSAGE(std::filesystem::exists(kVoiceDir),
                        kVoiceDir << ": install the Debian package gcin-voice");
        const Phrase phrase = join_phrase();
        const Timeline transcript = read_transcript("今天天氣很好，我們{men5}去公園散步吧。");
        const auto silenced_words = [&](const std::vector<float>& samples) {
            const AudioView view{samples.data(), samples.size(), 1, phrase.rate_hz};
            std::string found;
            for (const std::string& warning : SpeechAligner().align(view, transcript).warnings)
                if (warning.find("digital silence (exact zeros)") != std::string::npos) found += warning;
            return found;
        };
        // The phrase's comma and its ends are exact zeros too, with no syllable squeezed.
        CHECK(silenced_words(phrase.samples).empty());
        std::vector<float> edited = phrase.samples;
        const std::size_t step = kPhrase.size() - 2;
        std::fill(edited.begin() + static_cast<std::ptrdiff_t>(phrase.starts_s[step] * phrase.rate_hz),
                  edited.begin() + static_cast<std::ptrdiff_t>(phrase.end_s * phrase.rate_hz), 0.0f);
        const std::string warning = silenced_words(edited);
        CHECK(warning.find("sentence 1: 5.5") != std::string::npos);
        CHECK(warning.find("is a word of \"步吧\" silenced there by an editor, its text kept?") !=
              std::string::npos);
    }
}
