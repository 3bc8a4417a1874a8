// A test clip's samples in memory, changed by a test (a beep put before it, dropouts cut into it)
// and aligned or analysed as they are.
#ifndef TALKFACE_TESTS_CLIP_AUDIO_HPP
#define TALKFACE_TESTS_CLIP_AUDIO_HPP

#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/speech_clips.hpp"
#include "speech/frame_features.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

namespace talkface::test {

struct ClipSamples {
    std::vector<float> values;
    int rate_hz = 0;
};

// tests/data/speech/FILE, read whole.
inline ClipSamples clip_samples(const std::string& file) {
    auto source = detail::open_audio_file(clip_path(file));
    return {read_all(*source), source->sample_rate_hz()};
}

// The syllables' starts of `audio` aligned with tests/data/speech/TRANSCRIPT.
inline std::vector<double> aligned_starts(const ClipSamples& audio, const std::string& transcript) {
    const Timeline timeline =
        SpeechAligner().align(AudioView{audio.values.data(), audio.values.size(), 1, audio.rate_hz},
                              load_transcript(clip_path(transcript)));
    std::vector<double> starts;
    for (const auto& syllable : timeline.syllables) starts.push_back(syllable.start_s);
    return starts;
}

inline detail::FeatureTrack features_of(const std::vector<float>& samples, int rate_hz) {
    const auto source = detail::open_audio_view(AudioView{samples.data(), samples.size(), 1, rate_hz});
    return detail::analyze_audio(*source, {});
}

}  // namespace talkface::test

#endif
