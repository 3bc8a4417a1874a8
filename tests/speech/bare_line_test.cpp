// A line cut to its sound (issues 12 and 13: a game's or a chat's line as its file holds it): less
// quiet than a pause between the recording's edge and the speech is the speech's own weak edge, so
// the first syllable starts with the file. Its floors come from its own weakest sound, under which
// espeak-ng's h of 好 read as silence: the path gave the file's first 80 ms to the edge's silence.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/speech_clips.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

TEST_SUITE("speech") {
    TEST_CASE("a line cut to its sound starts its first syllable where the file starts") {
        const Timeline transcript = load_transcript(test::clip_path("bare_line.txt"));
        const Timeline aligned = SpeechAligner().align_file(test::clip_path("bare_line.flac"), transcript);
        const std::vector<double> truth = test::true_starts("bare_line");
        REQUIRE(aligned.syllables.size() == truth.size());
        CHECK(aligned.syllables[0].start_s <= truth[0] + 0.02);
        CHECK(aligned.syllables.back().end_s == doctest::Approx(aligned.duration_s).epsilon(0.02));
    }

    TEST_CASE("digital zeros before a line cut to its sound stay a pause, however short") {
        auto source = detail::open_audio_file(test::clip_path("bare_line.flac"));
        const int rate_hz = source->sample_rate_hz();
        const std::vector<float> line = test::read_all(*source);
        for (const double lead_s : {0.05, 0.1}) {
            CAPTURE(lead_s);
            std::vector<float> samples(static_cast<std::size_t>(lead_s * rate_hz), 0.0f);
            samples.insert(samples.end(), line.begin(), line.end());
            AudioView audio;
            audio.samples = samples.data();
            audio.frame_count = samples.size();
            audio.sample_rate_hz = rate_hz;
            const Timeline aligned =
                SpeechAligner().align(audio, load_transcript(test::clip_path("bare_line.txt")));
            REQUIRE(aligned.syllables.size() == 1);
            CHECK(aligned.syllables[0].start_s >= lead_s - 0.02);
        }
    }
}
