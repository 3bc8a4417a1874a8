// Viterbi search of a hidden semi-Markov model: a left-to-right chain of states, each held for an
// explicit number of frames drawn from its duration prior (thesis 3.3 names an HMM with Viterbi
// search; SPEC "Alignment": explicit durations are what keeps a slow sentence's consonants short).
#ifndef TALKFACE_SPEECH_HSMM_HPP
#define TALKFACE_SPEECH_HSMM_HPP

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "speech/phone_chain.hpp"

namespace talkface::detail {

// Per-frame log-likelihood of each phone class, frame-major (kPhoneClassCount per frame).
struct EmissionScores {
    std::vector<float> values;
    std::size_t frame_count = 0;
    // What a state entered at frame t gains, frame_count + 1 of them (spectral_landmarks.hpp: where
    // the spectrum changes fast); empty: nothing, every frame alike.
    std::vector<float> boundary;
    // kGenericSpeech scores as the class that fits the frame best.
    float at(std::size_t frame, int phone_class) const {
        const float* row = &values[frame * kPhoneClassCount];
        if (phone_class == kGenericSpeech) return *std::max_element(row, row + kPhoneClassCount);
        return row[static_cast<std::size_t>(phone_class)];
    }
};

// Frames [first_frame, end_frame) held by `state`; optional states the path skipped have none.
struct StateSegment {
    std::size_t state = 0;
    std::size_t first_frame = 0;
    std::size_t end_frame = 0;
};

// The search's tables, kept between calls: a sentence is searched four times and a recording has
// many sentences, and allocating them afresh each time cost a fifth of the run in page faults.
struct ViterbiWorkspace {
    std::vector<float> entry;
    std::vector<float> finish;
    std::vector<float> entry_minus_prefix;
    std::vector<float> duration_score;
    std::vector<double> prefix;
};

// At most this many (state, frame) cells are searched at once (8 bytes each, 16 MB): a longer
// sentence (over half a minute) is searched in overlapping windows, so that an hour with no
// punctuation stays within the memory target beside its features and emission scores.
constexpr std::size_t kMaxSearchCells = std::size_t{2} << 20;

// The best path through all of `states` over all frames of `emissions` (each non-optional state
// at least its min_frames). Empty if no path fits (too few frames for the chain).
// A sentence searched in windows may stop early: once the path it keeps reaches `stop_frame`, it
// returns that path, which ends inside the chain. `emission_weight` multiplies every emission
// score against the duration priors and boundary bonuses (1: as scored; alignment_confidence.hpp
// searches again with the sounds weighing less, to see which syllables stay put).
std::vector<StateSegment> viterbi_align(const std::vector<PhoneState>& states, const EmissionScores& emissions,
                                        ViterbiWorkspace& workspace,
                                        std::size_t stop_frame = std::numeric_limits<std::size_t>::max(),
                                        double emission_weight = 1.0);

}  // namespace talkface::detail

#endif
