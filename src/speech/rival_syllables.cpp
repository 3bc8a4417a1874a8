#include "speech/rival_syllables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "speech/phone_chain.hpp"

namespace talkface::detail {

namespace {

// Syllables whose sounds differ from one another's (one of each broad initial and final; the
// broad classes know no tones), fitted over a syllable's stretch in place of its own text.
constexpr const char* kRivalPinyin[] = {
    "ba1", "pa1", "ma1", "fa1", "da1", "ta1", "na1", "la1", "ga1", "ka1", "ha1", "ji1", "qi1", "xi1",
    "zhi1", "chi1", "shi1", "ri4", "zi1", "ci2", "si1", "yi1", "wu1", "yu2", "e4", "ou1", "ai4", "ei4",
    "ao4", "an1", "en1", "ang2", "eng1", "er2", "yue4", "guo2", "xian1", "zhuang4", "lie4", "nv3",
    "sun1", "kong1", "tui1", "mian4", "chuan2", "hui4", "jiong3", "bing1", "shou3", "rong2"};

// A syllable's own states (no pauses), its vowels scaled so that the whole lasts about `frames`.
std::vector<PhoneState> lone_syllable_states(const std::string& pinyin, std::size_t frames) {
    Syllable syllable;
    syllable.pinyin = pinyin;
    syllable.text = pinyin;
    std::vector<PhoneState> states = build_phone_chain({&syllable}, frames + 2, frames);
    states.erase(std::remove_if(states.begin(), states.end(), [](const PhoneState& state) { return is_pause(state.role); }),
                 states.end());
    return states;
}

// The best score of `states` in order over exactly frames [first, end) of `scores` (emissions and
// log-normal duration priors), per frame; minus infinity where they do not fit.
double lone_fit(const std::vector<PhoneState>& states, const EmissionScores& scores, std::size_t first, std::size_t end) {
    const std::size_t frames = end - first;
    constexpr double kImpossible = -std::numeric_limits<double>::infinity();
    std::vector<double> best(frames + 1, kImpossible), next(frames + 1);
    best[0] = 0.0;
    for (const PhoneState& state : states) {
        std::fill(next.begin(), next.end(), kImpossible);
        const double log_median = std::log(state.median_frames);
        for (std::size_t from = 0; from < frames; ++from) {
            if (best[from] == kImpossible) continue;
            double emission = 0.0;
            for (std::size_t to = from + 1; to <= frames; ++to) {
                emission += scores.at(first + to - 1, state.phone_class);
                const std::size_t d = to - from;
                if (d < std::max<std::size_t>(state.min_frames, 1)) continue;
                const double z = (std::log(static_cast<double>(d)) - log_median) / state.log_sigma;
                next[to] = std::max(next[to], best[from] + emission - std::log(static_cast<double>(d)) - 0.5 * z * z);
            }
        }
        best.swap(next);
    }
    return frames > 0 ? best[frames] / static_cast<double>(frames) : kImpossible;
}

}  // namespace

double rival_share(const SentenceChain& chain, std::size_t syllable, const SyllableFrames& frames,
                   const EmissionScores& scores) {
    const std::size_t first = std::min(frames.first_frame, scores.frame_count);
    const std::size_t end = std::min(frames.end_frame, scores.frame_count);
    if (end <= first || chain.syllables[syllable]->generic_speech) return 0.0;
    const double own = lone_fit(lone_syllable_states(chain.syllables[syllable]->pinyin, end - first), scores, first, end);
    std::size_t better = 0, counted = 0;
    for (const char* rival : kRivalPinyin) {
        const double fit = lone_fit(lone_syllable_states(rival, end - first), scores, first, end);
        if (fit == -std::numeric_limits<double>::infinity()) continue;
        ++counted;
        if (fit > own) ++better;
    }
    return counted > 0 ? static_cast<double>(better) / static_cast<double>(counted) : 0.0;
}

}  // namespace talkface::detail
