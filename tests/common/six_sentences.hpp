// Six sentences under music (issue 13): tests/data/speech/two_sentences.wav three times over, and
// whether the cutter finds each of the five gaps between them as one pause.
#ifndef TALKFACE_TESTS_SIX_SENTENCES_HPP
#define TALKFACE_TESTS_SIX_SENTENCES_HPP

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/speech_clips.hpp"
#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::test {

struct SixSentences {
    std::vector<float> samples;
    int rate_hz = 0;
    // The five gaps between the sentences, seconds (two_sentences.json: 1.69-2.59 s in each copy,
    // 4.15 s to the next copy's 0.3 s).
    std::vector<std::pair<double, double>> gaps;
};

inline SixSentences six_sentences() {
    auto source = detail::open_audio_file(clip_path("two_sentences.wav"));
    SixSentences six;
    six.rate_hz = source->sample_rate_hz();
    const std::vector<float> once = read_all(*source);
    const double copy_s = static_cast<double>(once.size()) / six.rate_hz;
    for (int copy = 0; copy < 3; ++copy) {
        six.samples.insert(six.samples.end(), once.begin(), once.end());
        six.gaps.emplace_back(copy * copy_s + 1.69, copy * copy_s + 2.59);
        if (copy < 2) six.gaps.emplace_back(copy * copy_s + 4.15, (copy + 1) * copy_s + 0.3);
    }
    return six;
}

// Whether one of `pauses` lies inside the gap `start_s`-`end_s` (give or take 50 ms) and covers at
// least `share` of it: found as one pause, not cut in pieces by the music.
inline bool is_found_whole(const std::vector<detail::FrameSpan>& pauses, double start_s, double end_s, double share) {
    return std::any_of(pauses.begin(), pauses.end(), [&](const detail::FrameSpan& pause) {
        const double first_s = static_cast<double>(pause.first_frame) * detail::kFrameStepS;
        const double found_end_s = static_cast<double>(pause.end_frame) * detail::kFrameStepS;
        return first_s >= start_s - 0.05 && found_end_s <= end_s + 0.05 && found_end_s - first_s >= share * (end_s - start_s);
    });
}

// The six sentences `intro_s` into a recording of silence, with `outro_s` of it after them: room for
// music before the voice and after it (a podcast's intro and outro).
inline std::vector<float> with_silent_edges(const SixSentences& six, double intro_s, double outro_s) {
    std::vector<float> samples(static_cast<std::size_t>(intro_s * six.rate_hz), 0.0f);
    samples.insert(samples.end(), six.samples.begin(), six.samples.end());
    samples.insert(samples.end(), static_cast<std::size_t>(outro_s * six.rate_hz), 0.0f);
    return samples;
}

// How far from the six sentences' first syllable, `intro_s` into the recording, the speech that
// `loudness` finds starts, seconds.
inline double start_error_s(const detail::LoudnessProfile& loudness, double intro_s) {
    const double first_s = intro_s + true_starts("two_sentences").front();
    return std::fabs(static_cast<double>(loudness.speech_first_frame) * detail::kFrameStepS - first_s);
}

}  // namespace talkface::test

#endif
