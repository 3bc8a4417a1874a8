#include "speech/tone_witness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "speech/alignment_confidence.hpp"
#include "speech/tone_contour.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

std::vector<std::vector<double>> tone_gaps_of_chains(
    const std::vector<SentenceChain>& chains, const std::vector<std::vector<StateSegment>>& plain_paths,
    const FeatureTrack& track) {
    // Each syllable's final, in the track's frames.
    std::vector<std::vector<SyllableFrames>> finals(chains.size());
    std::vector<std::size_t> voiced_candidates;
    for (std::size_t w = 0; w < chains.size(); ++w) {
        finals[w].assign(chains[w].syllables.size(), {std::numeric_limits<std::size_t>::max(), 0});
        for (const StateSegment& segment : plain_paths[w]) {
            const PhoneState& state = chains[w].states[segment.state];
            if (state.role != StateRole::final) continue;
            SyllableFrames& frames = finals[w][state.syllable];
            frames.first_frame =
                std::min(frames.first_frame, chains[w].searched.first_frame + segment.first_frame);
            frames.end_frame = std::max(frames.end_frame, chains[w].searched.first_frame + segment.end_frame);
            for (std::size_t t = segment.first_frame; t < segment.end_frame; ++t)
                voiced_candidates.push_back(chains[w].searched.first_frame + t);
        }
    }
    const double reference_hz = median_voiced_hz(track, voiced_candidates);
    std::vector<ToneShape> shapes;
    std::vector<std::string> pinyin;
    std::vector<std::size_t> sentences;
    for (std::size_t w = 0; w < chains.size(); ++w)
        for (std::size_t i = 0; i < chains[w].syllables.size(); ++i) {
            const SyllableFrames& frames = finals[w][i];
            shapes.push_back(frames.first_frame < frames.end_frame
                                 ? tone_shape(track, frames.first_frame, frames.end_frame, reference_hz)
                                 : ToneShape{});
            const Syllable& syllable = *chains[w].syllables[i];
            pinyin.push_back(syllable.generic_speech ? std::string() : syllable.pinyin);
            sentences.push_back(syllable.sentence);
        }
    const std::vector<double> all = tone_gaps(shapes, pinyin, sentences);
    std::vector<std::vector<double>> gaps(chains.size());
    std::size_t k = 0;
    for (std::size_t w = 0; w < chains.size(); ++w)
        for (std::size_t i = 0; i < chains[w].syllables.size(); ++i) gaps[w].push_back(all[k++]);
    return gaps;
}

void set_tone_gaps(const std::vector<SentenceChain>& chains,
                   const std::vector<std::vector<StateSegment>>& paths, const FeatureTrack& track,
                   std::vector<SentenceMetrics>& metrics) {
    const std::vector<std::vector<double>> gaps = tone_gaps_of_chains(chains, paths, track);
    std::vector<double> sum(metrics.size(), 0.0);
    std::vector<std::size_t> judged(metrics.size(), 0);
    for (std::size_t w = 0; w < chains.size(); ++w)
        for (std::size_t i = 0; i < chains[w].syllables.size(); ++i) {
            if (!std::isfinite(gaps[w][i])) continue;
            const std::size_t k = chains[w].syllables[i]->sentence;
            sum[k] += gaps[w][i];
            ++judged[k];
        }
    for (std::size_t k = 0; k < metrics.size(); ++k)
        if (judged[k] >= kMinToneWitnessSyllables)
            metrics[k].tone_gap = sum[k] / static_cast<double>(judged[k]);
}

}  // namespace talkface::detail
