#include "speech/duration_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace talkface::detail {

namespace {

// More tables than a few minutes of chains hold (a state's table is up to a few hundred floats).
constexpr std::size_t kMostTables = 4096;

// A state's log-normal duration prior, with the logs that do not depend on the duration taken once.
struct LogNormalDuration {
    double log_median;
    double log_sigma;
    double log_of_log_sigma;

    LogNormalDuration(double median_frames, double sigma)
        : log_median(std::log(median_frames)), log_sigma(sigma), log_of_log_sigma(std::log(sigma)) {}

    // log of the density at d frames, up to a constant shared by every path.
    double at(double frames) const { return at_log(std::log(frames)); }
    // The same, given log(d).
    double at_log(double log_frames) const {
        const double z = (log_frames - log_median) / log_sigma;
        return -log_frames - 0.5 * z * z - log_of_log_sigma;
    }
};

// log(d) of a whole number of frames, from a table made once for the durations the priors reach
// (a vowel's longest is 3.5 times its median, a comma's pause 200 frames): every search took one
// logarithm per duration of every state, a twentieth of its work.
constexpr std::size_t kTabledFrames = 2048;
double log_of_frames(std::size_t frames) {
    static const std::vector<double> logs = [] {
        std::vector<double> table(kTabledFrames, -std::numeric_limits<double>::infinity());
        for (std::size_t d = 1; d < kTabledFrames; ++d) table[d] = std::log(static_cast<double>(d));
        return table;
    }();
    return frames < kTabledFrames ? logs[frames] : std::log(static_cast<double>(frames));
}

std::vector<float> make_table(const PhoneState& state, std::size_t longest) {
    const std::size_t shortest = std::max<std::size_t>(state.min_frames, 1);
    std::vector<float> reversed;
    const bool is_flat = state.role == StateRole::edge_silence;
    // A state every path passes is scored against its prior's value at the median: the same for
    // every path of a whole sentence, so nothing there changes, but an open-ended window compares
    // paths through different numbers of states, and would otherwise favour the one that passed
    // fewer (each pays -log(median) more) and fall behind the speech, window after window.
    const LogNormalDuration prior(state.median_frames, state.log_sigma);
    const double reference = state.is_optional ? 0.0 : prior.at(state.median_frames);
    for (std::size_t d = longest; d >= shortest && d > 0; --d) {
        const double score =
            is_flat ? 0.0 : state.duration_weight * (prior.at_log(log_of_frames(d)) - reference);
        reversed.push_back(static_cast<float>(score + state.entry_log_penalty +
                                              state.frame_log_penalty * static_cast<double>(d)));
    }
    return reversed;
}

std::uint64_t bits_of(double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

}  // namespace

bool DurationTables::Key::operator==(const Key& other) const {
    // Bit for bit: a table is the same only for the same numbers.
    return bits_of(median_frames) == bits_of(other.median_frames) &&
           bits_of(log_sigma) == bits_of(other.log_sigma) &&
           bits_of(duration_weight) == bits_of(other.duration_weight) &&
           bits_of(entry_log_penalty) == bits_of(other.entry_log_penalty) &&
           bits_of(frame_log_penalty) == bits_of(other.frame_log_penalty) && min_frames == other.min_frames &&
           longest == other.longest && is_flat == other.is_flat && is_optional == other.is_optional;
}

std::size_t DurationTables::KeyHash::operator()(const Key& key) const {
    // FNV-1a over the fields' bits.
    std::uint64_t hash = 14695981039346656037ull;
    for (const std::uint64_t field :
         {bits_of(key.median_frames), bits_of(key.log_sigma), bits_of(key.duration_weight),
          bits_of(key.entry_log_penalty), bits_of(key.frame_log_penalty),
          static_cast<std::uint64_t>(key.min_frames), static_cast<std::uint64_t>(key.longest),
          static_cast<std::uint64_t>(key.is_flat) << 1 | static_cast<std::uint64_t>(key.is_optional)})
        hash = (hash ^ field) * 1099511628211ull;
    return static_cast<std::size_t>(hash);
}

const std::vector<float>& DurationTables::of(const PhoneState& state, std::size_t frames) {
    const std::size_t longest = longest_duration(state, frames);
    const Key key{state.median_frames,
                  state.log_sigma,
                  state.duration_weight,
                  state.entry_log_penalty,
                  state.frame_log_penalty,
                  state.min_frames,
                  longest,
                  state.role == StateRole::edge_silence,
                  state.is_optional};
    auto found = tables_.find(key);
    if (found == tables_.end()) found = tables_.emplace(key, make_table(state, longest)).first;
    return found->second;
}

void DurationTables::forget_beyond_limit() {
    if (tables_.size() > kMostTables) tables_.clear();
}

}  // namespace talkface::detail
