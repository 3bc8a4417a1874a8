// A voice in a room (issue 12, room_closures.hpp): a recording told a room by its sentences'
// tails, and the stops after its ringing vowels placed where they start.
#include <doctest/doctest.h>

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "common/room_audio.hpp"
#include "common/speech_clips.hpp"
#include "speech/frame_features.hpp"
#include "speech/room_closures.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;
using namespace talkface::detail;

namespace {

std::vector<SentenceChain> chains_with_tails(const std::vector<std::size_t>& tail_frames) {
    std::vector<SentenceChain> chains(tail_frames.size());
    for (std::size_t w = 0; w < chains.size(); ++w) chains[w].tail_frames = tail_frames[w];
    return chains;
}

struct Clip {
    std::vector<float> samples;
    int rate_hz = 0;
    Timeline transcript;
};

// tests/data/speech/NAME: its audio (mono) and its transcript.
Clip read_clip(const std::string& name) {
    Clip clip;
    for (const char* extension : {".flac", ".wav"}) {
        SF_INFO info{};
        SNDFILE* file = sf_open(test::clip_path(name + extension).c_str(), SFM_READ, &info);
        if (file == nullptr) continue;
        REQUIRE(info.channels == 1);
        clip.samples.resize(static_cast<std::size_t>(info.frames));
        sf_readf_float(file, clip.samples.data(), info.frames);
        sf_close(file);
        clip.rate_hz = info.samplerate;
    }
    REQUIRE(!clip.samples.empty());
    clip.transcript = load_transcript(test::clip_path(name + ".txt"));
    return clip;
}

// The chains the aligner searches in `samples` for `transcript`, their search spans set.
std::vector<SentenceChain> chains_of(const std::vector<float>& samples, int rate_hz,
                                     const Timeline& transcript) {
    const auto source = open_audio_view({samples.data(), samples.size(), 1, rate_hz});
    const FeatureTrack track = analyze_audio(*source, [](double) {});
    const LoudnessProfile loudness = measure_loudness(track);
    const SentenceCut cut = cut_sentences(track, loudness, transcript, AlignOptions());
    std::vector<SentenceChain> chains = group_chains(transcript, cut, cut.spans);
    set_search_spans(track, loudness, chains);
    return chains;
}

}  // namespace

TEST_SUITE("room closures") {
    TEST_CASE("a recording is a room when its typical sentence end rings on, not one") {
        CHECK(is_room(chains_with_tails({9})));
        CHECK_FALSE(is_room(chains_with_tails({8})));
        CHECK(is_room(chains_with_tails({0, 12, 9, 15, 3})));
        // One long fade (a phone codec's noise after a last syllable) is no room.
        CHECK_FALSE(is_room(chains_with_tails({2, 0, 20, 4})));
        // An even count's median is its middle two's mean.
        CHECK(is_room(chains_with_tails({8, 10, 2, 20})));
        CHECK_FALSE(is_room(chains_with_tails({8, 9, 2, 20})));
        CHECK_FALSE(is_room({}));
    }

    TEST_CASE("ringing closures score any sound, for a price a frame, their durations as they were") {
        std::vector<Syllable> said(3);
        said[0].pinyin = "ma1";
        said[1].pinyin = "ba5";
        said[2].pinyin = "ta1";
        const std::vector<const Syllable*> syllables = {&said[0], &said[1], &said[2]};
        const std::vector<PhoneState> silent = build_phone_chain(syllables, 80, 60);
        std::vector<PhoneState> ringing = silent;
        let_closures_ring(ringing);
        REQUIRE(ringing.size() == silent.size());
        std::size_t closures = 0;
        for (std::size_t s = 0; s < silent.size(); ++s) {
            CAPTURE(s);
            CHECK(ringing[s].median_frames == silent[s].median_frames);
            CHECK(ringing[s].max_frames == silent[s].max_frames);
            CHECK(ringing[s].skip_log_penalty == silent[s].skip_log_penalty);
            if (silent[s].role != StateRole::closure) {
                CHECK(ringing[s].phone_class == silent[s].phone_class);
                CHECK(ringing[s].frame_log_penalty == silent[s].frame_log_penalty);
                continue;
            }
            ++closures;
            CHECK(ringing[s].phone_class == kGenericSpeech);
            CHECK(ringing[s].frame_log_penalty == kRoomClosureFrameLogPenalty);
        }
        CHECK(closures == 2);  // 吧's and 他's, after speech; 妈 has none
    }

    // Dry, a recording is never placed with ringing closures: its times are the silent closures'.
    TEST_CASE("the clips are dry, the same in a room are rooms") {
        for (const std::string name : {"one_sentence", "two_sentences", "comma_pause"}) {
            CAPTURE(name);
            const Clip clip = read_clip(name);
            CHECK_FALSE(is_room(chains_of(clip.samples, clip.rate_hz, clip.transcript)));
            CHECK(
                is_room(chains_of(test::in_room(clip.samples, clip.rate_hz), clip.rate_hz, clip.transcript)));
        }
    }

    TEST_CASE("in a room, the stops after ringing vowels start where they start") {
        // 请把桌子上的杯子拿给我，谢谢。 On the silent closures' paths 桌 after 把, 子 after 桌 and
        // 子 after 杯 come 51-66 ms late, each waiting for silence after the vowel before rang on.
        const Clip clip = read_clip("comma_pause");
        const std::vector<float> wet = test::in_room(clip.samples, clip.rate_hz);
        const Timeline aligned =
            SpeechAligner().align({wet.data(), wet.size(), 1, clip.rate_hz}, clip.transcript);
        const std::vector<double> truth = test::true_starts("comma_pause");
        REQUIRE(aligned.syllables.size() == truth.size());
        for (std::size_t i = 0; i < truth.size(); ++i) {
            CAPTURE(clip.transcript.syllables[i].text);
            CAPTURE(aligned.syllables[i].start_s);
            CAPTURE(truth[i]);
            CHECK(std::fabs(aligned.syllables[i].start_s - truth[i]) <= 0.050);
        }
    }
}
