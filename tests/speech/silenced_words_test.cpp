// A word an editor silenced while its text is kept is named (issue 13, "Recordings as people have
// them"): the aligner squeezes its syllables against the zeros, and said nothing of it before.
#include <doctest/doctest.h>

#include <sndfile.h>

#include <algorithm>
#include <cstddef>
#include <string>

#include "common/clip_audio.hpp"
#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
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

// What the warnings of `path` aligned with one_sentence.txt say of exact zeros.
std::vector<std::string> zeros_warnings(const std::string& path) {
    std::vector<std::string> found;
    for (const std::string& warning :
         SpeechAligner().align_file(path, load_transcript(test::clip_path("one_sentence.txt"))).warnings)
        if (warning.find("exact") != std::string::npos && warning.find("zeros") != std::string::npos)
            found.push_back(warning);
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

    TEST_CASE("a sentence refused with a word of five syllables silenced inside it names the zeros") {
        // 們在公園裡 of 小朋友們在公園裡放風箏, 0.952-1.953 s by the generator's truth, put to exact
        // zeros: the text is refused as not the speech, and said nothing of the silence.
        test::ClipSamples edited = test::clip_samples("one_sentence.wav");
        std::fill(edited.values.begin() + static_cast<std::ptrdiff_t>(0.952 * edited.rate_hz),
                  edited.values.begin() + static_cast<std::ptrdiff_t>(1.953 * edited.rate_hz), 0.0f);
        std::string refusal;
        try {
            SpeechAligner().align(AudioView{edited.values.data(), edited.values.size(), 1, edited.rate_hz},
                                  load_transcript(test::clip_path("one_sentence.txt")));
        } catch (const AlignmentError& error) {
            refusal = error.what();
        }
        CHECK_MESSAGE(
            refusal.find("(the recording: 0.96-1.94 s, inside sentence 1, is digital silence (exact "
                         "zeros) where its text marks no pause") != std::string::npos,
            refusal);
    }

    TEST_CASE("a block of zeros cut mid-wave into a WAV is named once, by the note on the cut") {
        // 1.1-1.3 s of one_sentence.wav put to zeros, in a file: the reader's note on the cut says an
        // editor's silence leaves it, as a disk's zeroed bytes do; the silenced word said it again.
        test::ClipSamples clip = test::clip_samples("one_sentence.wav");
        std::fill(clip.values.begin() + static_cast<std::ptrdiff_t>(1.1 * clip.rate_hz),
                  clip.values.begin() + static_cast<std::ptrdiff_t>(1.3 * clip.rate_hz), 0.0f);
        const std::string path = test::output_path("silenced_words_cut.wav");
        SF_INFO info{};
        info.samplerate = clip.rate_hz;
        info.channels = 1;
        info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
        SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
        REQUIRE(file != nullptr);
        sf_writef_float(file, clip.values.data(), static_cast<sf_count_t>(clip.values.size()));
        sf_close(file);
        const std::vector<std::string> warnings = zeros_warnings(path);
        REQUIRE(warnings.size() == 1);
        CHECK(warnings[0].find("cut off mid-wave to exact digital zeros at 1.1-1.3 s") != std::string::npos);
    }
}
