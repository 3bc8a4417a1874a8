// Viterbi search of a hidden semi-Markov model: a left-to-right chain of states, each held for an
// explicit number of frames drawn from its duration prior (thesis 3.3 names an HMM with Viterbi
// search; SPEC "Alignment": explicit durations are what keeps a slow sentence's consonants short).
#ifndef TALKFACE_SPEECH_HSMM_HPP
#define TALKFACE_SPEECH_HSMM_HPP

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "speech/duration_tables.hpp"
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
// They only grow: a shorter search uses the start of each.
struct ViterbiWorkspace {
    std::vector<float> entry;
    std::vector<float> finish;
    std::vector<float> entry_minus_prefix;
    DurationTables durations;
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

// For each state j of a chain searched whole and each frame t of its search (0 to frame_count), the
// score of the best whole path on which state j starts at frame t and holds it: against the
// path's own score, how much worse the search finds each other start of a state
// (alignment_confidence.hpp: start_sureness). State-major, `width` frames a state. Only paths on
// which the state and every later one start within 30 frames of their starts on the path are
// searched (a start further off: minus infinity): a start moved further is as surely wrong, and
// the search costs the bands' width, not the sentence's.
struct EntryMaxMarginals {
    std::size_t width = 0;
    std::vector<float> values;  // empty: the chain was searched in windows (too long for these tables)
    float at(std::size_t state, std::size_t frame) const { return values[state * width + frame]; }
};

// The path viterbi_align finds (the sounds at full weight, over all frames), and its
// EntryMaxMarginals in `marginals`: the path search's own table of the best way to each state's
// entry is kept, and one search more, over the chain and the frames reversed and only near the
// path, gives the best way from there to the end (bench/ Session 18: two whole searches more cost
// session 17's aligner 29% of its speed; this costs 2-3% of its instructions).
std::vector<StateSegment> viterbi_align_with_marginals(const std::vector<PhoneState>& states,
                                                       const EmissionScores& emissions,
                                                       ViterbiWorkspace& workspace,
                                                       EntryMaxMarginals& marginals);

}  // namespace talkface::detail

#endif
