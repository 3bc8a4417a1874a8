// A word an editor silenced while its text is kept is named (issue 13, "Recordings as people have
// them"): the aligner squeezes its syllables against the zeros, and said nothing of it before.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <string>

#include "common/clip_audio.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

std::string silenced_warnings(const test::ClipSamples& audio) {
    const Timeline timeline =
        SpeechAligner().align(AudioView{audio.values.data(), audio.values.size(), 1, audio.rate_hz},
                              load_transcript(test::clip_path("one_sentence.txt")));
    std::string found;
    for (const std::string& warning : timeline.warnings)
        if (warning.find("digital silence") != std::string::npos) found += warning + "\n";
    return found;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("a word silenced by an editor, its text kept, is named with its time and syllables") {
        const test::ClipSamples clip = test::clip_samples("one_sentence.wav");
        CHECK(silenced_warnings(clip).empty());
        // 公園 of 小朋友們在公園裡放風箏, 1.362-1.824 s by the generator's truth, put to exact zeros.
        test::ClipSamples edited = clip;
        const auto first = static_cast<std::size_t>(1.362 * edited.rate_hz);
        const auto end = static_cast<std::size_t>(1.824 * edited.rate_hz);
        std::fill(edited.values.begin() + static_cast<std::ptrdiff_t>(first),
                  edited.values.begin() + static_cast<std::ptrdiff_t>(end), 0.0f);
        const std::string warning = silenced_warnings(edited);
        CHECK(warning.find("sentence 1: 1.37-1.81 s is digital silence") != std::string::npos);
        CHECK(warning.find("squeezed against it (\"們\"") != std::string::npos);
        CHECK(warning.find("is a word of \"們在公園\" silenced there by an editor, its text kept?") !=
              std::string::npos);
    }
}
