#include "speech/text_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "common/order_statistics.hpp"
#include "speech/lenient_chain.hpp"

namespace talkface::detail {

namespace {

// What the phone loop of text_fit_gap pays for a change of sound, in the re-estimated model's
// log-likelihood (bench/ tuning passages: at 2 right and wrong texts lie furthest apart in every
// condition; at 5 they overlap).
constexpr double kLoopSwitchPenalty = 2.0;

// What the frames of `path` score on `scores`, pauses included.
double path_score(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores) {
    double sum = 0.0;
    for (const auto& segment : path)
        for (std::size_t t = segment.first_frame; t < segment.end_frame; ++t) sum += scores.at(t, chain.states[segment.state].phone_class);
    return sum;
}

// Whether path[i] is a stop's closure after speech, the state before it on the path a sound, not a
// pause: after a pause the closure is silence either way (SPEC), and no sound runs on into it.
bool is_closure_after_speech(const SentenceChain& chain, const std::vector<StateSegment>& path,
                             std::size_t i) {
    return i > 0 && chain.states[path[i].state].role == StateRole::closure &&
           !is_pause(chain.states[path[i - 1].state].role);
}

// The frames [first, end) from the first frame of `path`'s speech to its last, pauses outside it
// left out; first == end where it has none.
std::pair<std::size_t, std::size_t> speech_extent(const SentenceChain& chain,
                                                  const std::vector<StateSegment>& path) {
    std::size_t first = 0, end = 0;
    bool has_speech = false;
    for (const auto& segment : path) {
        if (is_pause(chain.states[segment.state].role)) continue;
        if (!has_speech) first = segment.first_frame;
        has_speech = true;
        end = segment.end_frame;
    }
    return has_speech ? std::make_pair(first, end) : std::make_pair(std::size_t{0}, std::size_t{0});
}

}  // namespace

double speech_fit(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores) {
    double sum = 0.0;
    std::size_t frames = 0;
    for (const auto& segment : path) {
        const PhoneState& state = chain.states[segment.state];
        if (is_pause(state.role)) continue;
        for (std::size_t t = segment.first_frame; t < segment.end_frame; ++t) sum += scores.at(t, state.phone_class);
        frames += segment.end_frame - segment.first_frame;
    }
    return frames > 0 ? sum / static_cast<double>(frames) : -std::numeric_limits<double>::infinity();
}

std::vector<std::pair<std::size_t, std::vector<StateSegment>>> split_by_sentence(const SentenceChain& chain,
                                                                                const std::vector<StateSegment>& path) {
    std::vector<std::pair<std::size_t, std::vector<StateSegment>>> shares;
    for (const auto& segment : path) {
        const std::size_t sentence = chain.syllables[chain.states[segment.state].syllable]->sentence;
        if (shares.empty() || shares.back().first != sentence) shares.emplace_back(sentence, std::vector<StateSegment>());
        shares.back().second.push_back(segment);
    }
    return shares;
}

// The loop pays for each change of sound, so on the right text it gains little over the path; on
// a wrong text of the same length (two sentences swapped, another sentence) the path is forced
// through sounds that are not there. Unlike the fit against the other sentences, this needs none.
// A closure spoken through is the sound before it run on: the speaker's tongue did not close, and
// the text said nothing else there; forgiven only as far as this speaker's closures are.
double text_fit_gap(const SentenceChain& chain, const std::vector<StateSegment>& path,
                    const EmissionScores& scores, double forgiven_run_on) {
    const auto [first, end] = speech_extent(chain, path);
    if (end <= first) return 0.0;
    double forced = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const StateSegment& segment = path[i];
        const PhoneState& state = chain.states[segment.state];
        const std::size_t segment_first = std::max(segment.first_frame, first);
        const std::size_t segment_end = std::min(segment.end_frame, end);
        const bool is_run_on = forgiven_run_on > 0.0 && is_closure_after_speech(chain, path, i);
        const int run_on = is_run_on ? chain.states[path[i - 1].state].phone_class : state.phone_class;
        for (std::size_t t = segment_first; t < segment_end; ++t) {
            const double closed = scores.at(t, state.phone_class);
            forced += closed + std::clamp(scores.at(t, run_on) - closed, 0.0, forgiven_run_on);
        }
    }
    return (free_sounds_score(scores, first, end) - forced) / static_cast<double>(end - first);
}

// Speech under the noise fits no sound's model well, and there the free loop gains on any text by
// hopping to whichever class the noise of each frame fits best: a right text's gap rises with the
// share of its frames the noise covers, as a wrong one's does, and tells the two apart only where
// the speech stands clear of the noise.
double clear_text_fit_gap(const SentenceChain& chain, const std::vector<StateSegment>& path,
                          const EmissionScores& scores, const std::vector<bool>& is_clear,
                          double forgiven_run_on) {
    const auto [first, end] = speech_extent(chain, path);
    if (end <= first) return 0.0;
    // Only the speech's own frames are copied, a frame under the noise scoring 0 for every sound.
    EmissionScores masked;
    masked.frame_count = end - first;
    masked.values.assign(scores.values.begin() + static_cast<std::ptrdiff_t>(first * kPhoneClassCount),
                         scores.values.begin() + static_cast<std::ptrdiff_t>(end * kPhoneClassCount));
    std::size_t kept = 0;
    for (std::size_t t = first; t < end; ++t) {
        if (is_clear[t]) {
            ++kept;
            continue;
        }
        std::fill_n(masked.values.begin() + static_cast<std::ptrdiff_t>((t - first) * kPhoneClassCount),
                    kPhoneClassCount, 0.0f);
    }
    if (kept == 0) return text_fit_gap(chain, path, scores, forgiven_run_on);
    std::vector<StateSegment> shifted;
    for (StateSegment segment : path) {
        if (segment.end_frame <= first || segment.first_frame >= end) continue;
        segment.first_frame = std::max(segment.first_frame, first) - first;
        segment.end_frame = std::min(segment.end_frame, end) - first;
        shifted.push_back(segment);
    }
    return text_fit_gap(chain, shifted, masked, forgiven_run_on) * static_cast<double>(end - first) /
           static_cast<double>(kept);
}

double noise_covered_share(const SentenceChain& chain, const std::vector<StateSegment>& path,
                           const std::vector<bool>& is_clear) {
    const auto [first, end] = speech_extent(chain, path);
    if (end <= first) return 0.0;
    const auto covered = std::count(is_clear.begin() + static_cast<std::ptrdiff_t>(first),
                                    is_clear.begin() + static_cast<std::ptrdiff_t>(end), false);
    return static_cast<double>(covered) / static_cast<double>(end - first);
}

void add_closure_run_on(const SentenceChain& chain, const std::vector<StateSegment>& path,
                        const EmissionScores& scores, std::vector<double>& losses) {
    for (std::size_t i = 1; i < path.size(); ++i) {
        if (!is_closure_after_speech(chain, path, i)) continue;
        const PhoneState& state = chain.states[path[i].state];
        const PhoneState& before = chain.states[path[i - 1].state];
        for (std::size_t t = path[i].first_frame; t < path[i].end_frame; ++t)
            losses.push_back(std::max(0.0, static_cast<double>(scores.at(t, before.phone_class)) -
                                               scores.at(t, state.phone_class)));
    }
}

double typical_closure_run_on(std::vector<double> losses) {
    return losses.empty() ? 0.0 : upper_median(std::move(losses));
}

double free_sounds_score(const EmissionScores& scores, std::size_t first, std::size_t end) {
    std::array<double, kPhoneClassCount> best{};
    for (std::size_t t = first; t < end; ++t) {
        const double leader = *std::max_element(best.begin(), best.end());
        for (int c = 0; c < kPhoneClassCount; ++c)
            best[static_cast<std::size_t>(c)] = std::max(best[static_cast<std::size_t>(c)], leader - kLoopSwitchPenalty) + scores.at(t, c);
    }
    return *std::max_element(best.begin(), best.end());
}

// The competitor of utterance verification's likelihood ratio, where the free loop of text_fit_gap
// is not one: on models re-estimated on a file of a sentence or two, the text's path shaped the
// models, and a wrong text fits about as well as free sounds do. The same text forced on its speech
// out of order fits only where the sounds repeat, and a right text's path gains on that a great
// deal, a wrong one's little: it fits its speech hardly better than any order of the text's sounds.
double order_margin(const SentenceChain& chain, const std::vector<StateSegment>& path, const EmissionScores& scores,
                    ViterbiWorkspace& workspace) {
    const std::size_t frames = scores.frame_count;
    if (frames == 0 || path.empty()) return std::numeric_limits<double>::quiet_NaN();
    // The frames an edge pause must hold (SentenceChain::syllable_bound) stay where they are: swapped
    // into the middle of the speech, they would hold the rival's pause on the voice.
    const auto held = [](const PhoneState& edge) { return edge.is_optional ? 0 : edge.min_frames; };
    const std::size_t lead = std::min(held(chain.states.front()), frames);
    const std::size_t inner = frames - lead - std::min(held(chain.states.back()), frames - lead);
    // The speech from its frame inner - inner / 2 on, then the speech before it.
    EmissionScores swapped;
    swapped.frame_count = frames;
    swapped.values.assign(scores.values.begin(),
                          scores.values.begin() + static_cast<std::ptrdiff_t>(frames * kPhoneClassCount));
    const auto at = [&](std::size_t t) {
        return swapped.values.begin() + static_cast<std::ptrdiff_t>(t * kPhoneClassCount);
    };
    std::rotate(at(lead), at(lead + inner - inner / 2), at(lead + inner));
    const std::vector<StateSegment> rival = viterbi_align(chain.states, swapped, workspace, frames);
    if (rival.empty()) return std::numeric_limits<double>::quiet_NaN();
    return (path_score(chain, path, scores) - path_score(chain, rival, swapped)) / static_cast<double>(frames);
}

// A text that lacks its last syllables has its speech drawn over them (the vowels scale with the
// speech, so no one syllable stands out); with generic speech free to follow the text, the lost
// syllables' speech goes to it, where a right text's last syllable keeps its own.
std::size_t unspoken_tail_frames(const SentenceChain& chain, const EmissionScores& scores, ViterbiWorkspace& workspace) {
    std::size_t at = chain.states.size();
    while (at > 0 && chain.states[at - 1].role == StateRole::edge_silence) --at;
    if (at == 0 || scores.frame_count == 0) return 0;
    std::vector<PhoneState> states = chain.states;
    states.insert(states.begin() + static_cast<std::ptrdiff_t>(at), generic_speech_state(states[at - 1].syllable));
    std::size_t frames = 0;
    for (const auto& segment : viterbi_align(states, scores, workspace, scores.frame_count))
        if (states[segment.state].role == StateRole::generic_speech) frames += segment.end_frame - segment.first_frame;
    return frames;
}

std::vector<std::vector<StateSegment>> split_in_halves(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    std::vector<std::size_t> half_of_syllable(chain.syllables.size());
    std::size_t first = 0;
    std::size_t sentences = 0;
    for (; first < chain.syllables.size(); ++sentences) {
        std::size_t end = first;
        while (end < chain.syllables.size() && chain.syllables[end]->sentence == chain.syllables[first]->sentence) ++end;
        // Halves of the syllables read from their pinyin: generic speech (a word no table reads)
        // teaches the models nothing, and a half left with few read syllables would be judged by
        // models that never heard some of the other half's sounds.
        std::size_t read = 0;
        for (std::size_t i = first; i < end; ++i) read += chain.syllables[i]->generic_speech ? 0 : 1;
        const std::size_t first_half_read = (read + 1) / 2;
        std::size_t seen = 0;
        for (std::size_t i = first; i < end; ++i) {
            half_of_syllable[i] = 2 * sentences + (seen < first_half_read ? 0 : 1);
            seen += chain.syllables[i]->generic_speech ? 0 : 1;
        }
        first = end;
    }
    std::vector<std::vector<StateSegment>> halves(2 * sentences);
    for (const auto& segment : path) halves[half_of_syllable[chain.states[segment.state].syllable]].push_back(segment);
    return halves;
}

// Models re-estimated on a recording fit whatever text shaped them, and on a file of a sentence or
// two a wrong text shapes most of them; models that never saw these frames cannot bend to it.
// `scores` is overwritten (an hour's scores are 19 MB: no second buffer).
HeldOutGaps held_out_fit_gaps(const SentenceChain& chain,
                              const std::vector<std::vector<StateSegment>>& halves,
                              const std::vector<float>& observations, const ModelEstimator& whole,
                              const std::vector<ModelEstimator>& half_estimators, EmissionScores& scores,
                              double forgiven_run_on) {
    HeldOutGaps gaps;
    gaps.halves.assign(halves.size(), -std::numeric_limits<double>::infinity());
    gaps.syllables.assign(chain.syllables.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t h = 0; h < halves.size(); ++h) {
        if (halves[h].empty()) continue;
        ModelEstimator rest = whole;
        rest.subtract(half_estimators[h]);
        // Only the half's own frames are scored, where they lie: a chain of sentences run together
        // is long, and a copy of an hour's half would be the run's largest allocation.
        const std::size_t first = halves[h].front().first_frame;
        const std::size_t end = halves[h].back().end_frame;
        rest.estimate(kReestimatedWeight).score(observations.data() + first * kObservationCount, end - first, scores);
        std::vector<StateSegment> shifted = halves[h];
        for (auto& segment : shifted) {
            segment.first_frame -= first;
            segment.end_frame -= first;
        }
        gaps.halves[h] = text_fit_gap(chain, shifted, scores, forgiven_run_on);
        // Each syllable's own gap on the same models (a pause goes with the syllable before it).
        for (std::size_t i = 0; i < shifted.size();) {
            const std::size_t syllable = chain.states[shifted[i].state].syllable;
            std::size_t j = i;
            while (j < shifted.size() && chain.states[shifted[j].state].syllable == syllable) ++j;
            const std::vector<StateSegment> own(shifted.begin() + static_cast<std::ptrdiff_t>(i),
                                                shifted.begin() + static_cast<std::ptrdiff_t>(j));
            gaps.syllables[syllable] = text_fit_gap(chain, own, scores, forgiven_run_on);
            i = j;
        }
    }
    return gaps;
}

}  // namespace talkface::detail
