// The duration scores a search adds to each way through a state, one per duration its prior allows,
// kept for the states a workspace has searched: a recording's chains are searched a dozen times
// (every re-estimation round, the final pass, the checks' searches) and each state's table read
// again on every way back, and making them anew was 3% of a room's instructions (bench/README.md,
// Session 28).
#ifndef TALKFACE_SPEECH_DURATION_TABLES_HPP
#define TALKFACE_SPEECH_DURATION_TABLES_HPP

#include <cstddef>
#include <unordered_map>
#include <vector>

#include "speech/phone_chain.hpp"

namespace talkface::detail {

// The longest duration a search of `frames` frames scores for `state` (its max_frames, or the
// search's length where that is shorter).
inline std::size_t longest_duration(const PhoneState& state, std::size_t frames) {
    return state.max_frames < frames ? state.max_frames : frames;
}

class DurationTables {
public:
    // The duration scores of `state` in a search of `frames` frames, for d = longest_duration down
    // to its shortest (at least one frame), the order in which the search reads the entries before
    // a frame; empty where no duration fits. The same numbers as made afresh each time; the
    // reference holds until forget_beyond_limit is called.
    const std::vector<float>& of(const PhoneState& state, std::size_t frames);

    // Drops every table once they are many (a long sentence searched in windows scales its vowels
    // anew in each), so that an hour's search holds no more than a few minutes' worth.
    void forget_beyond_limit();

private:
    // What a state's table depends on.
    struct Key {
        double median_frames;
        double log_sigma;
        double duration_weight;
        double entry_log_penalty;
        double frame_log_penalty;
        std::size_t min_frames;
        std::size_t longest;
        bool is_flat;
        bool is_optional;
        bool operator==(const Key& other) const;
    };
    struct KeyHash {
        std::size_t operator()(const Key& key) const;
    };
    std::unordered_map<Key, std::vector<float>, KeyHash> tables_;
};

}  // namespace talkface::detail

#endif  // TALKFACE_SPEECH_DURATION_TABLES_HPP
