// SpeechAligner: audio -> features (streamed) -> sentence utterances -> per-sentence HSMM
// alignment, re-estimated on the recording (thesis chapter 3, SPEC "Alignment").
#include "talkface/speech_aligner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "audio/audio_source.hpp"
#include "common/number_format.hpp"
#include "speech/acoustic_model.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/phone_chain.hpp"
#include "speech/run_together.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using namespace detail;

// SPEC "Alignment": a first pass on hand-set models, then three rounds re-estimated on the audio.
constexpr int kReestimationRounds = 3;
// Acoustic scale of the re-estimated 28-dimensional model against the duration priors: its
// log-likelihoods are ~10 times those of the three-feature model for the same evidence.
constexpr double kReestimatedWeight = 0.2;
// Each sentence is searched with this much of the pauses around it, so that its first and last
// sounds are free to start and end where the audio says.
constexpr std::size_t kEdgeFrames = 30;
// How far below the loudest frame of the end of a sentence its last sound ends (end_before_tail):
// a room's tail starts 13-20 dB below the last vowel, which may itself be 10 dB below the louder
// syllables before it; the last 0.6 s always hold a syllable's vowel. (bench/ reverb: 15-20 dB
// find every sentence end, 25 dB leaves a tenth of them in the tail.)
constexpr float kTailFallDb = 18.0f;
constexpr std::size_t kTailReferenceFrames = 60;
// A sentence end that end_before_tail moves this far is a room's tail: a voice's own fall past
// kTailFallDb takes a frame or two (bench/: 0-2 frames in every condition but reverb, 3-26 there).
constexpr std::size_t kRoomTailFrames = 3;
// Past the end of a voice in a room, the search reaches only this far into the tail.
constexpr std::size_t kTailEdgeFrames = 5;
// What the phone loop of text_fit_gap pays for a change of sound, in the re-estimated model's
// log-likelihood (bench/ tuning passages: at 2 right and wrong texts lie furthest apart in every
// condition; at 5 they overlap).
constexpr double kLoopSwitchPenalty = 2.0;
// Silence before a burst (a pause and the closure together) from which on the closure is taken
// for part of a pause: a stop's closure lasts under 0.2 s.
constexpr std::size_t kPauseBeforeBurstFrames = 20;
// Files of at most this many sentences get the leave-one-out check (held_out_fit_gaps).
constexpr std::size_t kMaxHeldOutCheckSentences = 2;
// How much of a long sentence the first pass, on hand-set models, aligns: two minutes.
constexpr std::size_t kBootstrapFrames = 12000;
// Shares of the job's progress: reading and features, cutting, the alignment passes.
constexpr double kReadingShare = 0.45;
constexpr double kCuttingShare = 0.05;
constexpr double kProgressStep = 0.002;

class ProgressReporter {
public:
    explicit ProgressReporter(const ProgressCallback& callback) : callback_(callback) {}
    void report(double fraction, const char* stage) {
        if (!callback_) return;
        if (stage == last_stage_ && fraction < last_fraction_ + kProgressStep && fraction < 1.0) return;
        last_stage_ = stage;
        last_fraction_ = fraction;
        if (!callback_(std::clamp(fraction, 0.0, 1.0), stage))
            throw Cancelled(std::string("alignment cancelled by the progress callback while ") + stage + " at " +
                            format_fixed(100.0 * fraction, 1) + "%");
    }

private:
    const ProgressCallback& callback_;
    const char* last_stage_ = nullptr;
    double last_fraction_ = -1.0;
};

void validate_transcript(const Timeline& transcript) {
    if (transcript.syllables.empty())
        throw InvalidArgument("transcript", "no syllables to align (" + std::to_string(transcript.sentences.size()) +
                                                " sentences, none with a Mandarin reading)");
    std::size_t previous = 0;
    for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
        const std::size_t sentence = transcript.syllables[i].sentence;
        if (sentence >= transcript.sentences.size() || sentence < previous)
            throw InvalidArgument("transcript", "syllable " + std::to_string(i) + " (\"" + transcript.syllables[i].text +
                                                    "\") names sentence " + std::to_string(sentence) + " of " +
                                                    std::to_string(transcript.sentences.size()) + " out of order");
        previous = sentence;
    }
}

// One sentence, or neighbouring sentences the speaker ran together, aligned as one chain.
struct SentenceWork {
    std::size_t first_sentence = 0;  // the transcript's sentences [first_sentence, end_sentence)
    std::size_t end_sentence = 0;
    FrameSpan speech;   // from the cutter
    FrameSpan searched; // with the edges
    std::vector<const Syllable*> syllables;
    std::vector<std::size_t> syllable_indices;
    std::vector<PhoneState> states;
    bool ends_in_tail = false;  // its last sound rings on in a room (end_before_tail cut a tail off)
};

bool is_pause(StateRole role) {
    return role == StateRole::edge_silence || role == StateRole::short_pause || role == StateRole::comma_pause;
}

double log_sum_exp(const float* values, int count) {
    float largest = values[0];
    for (int i = 1; i < count; ++i) largest = std::max(largest, values[i]);
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += std::exp(static_cast<double>(values[i] - largest));
    return largest + std::log(sum);
}

// SPEC: a sentence ends with its last sound. In a reverberant room that sound rings on for a few
// hundred ms after the voice stops, and the tail looks like the vowel: it lengthens the sentence
// the cutter finds (so every vowel is stretched to fill it) and the search gives it to the last
// vowel. Where the voice stops the level falls at once far below the vowel's, and the tail only
// decays from there: speech in [first, end) ends after its last frame less than kTailFallDb below
// the loudest frame of its last kTailReferenceFrames. In noise the floor stays above that mark and
// nothing moves.
std::size_t end_before_tail(const FeatureTrack& track, std::size_t first, std::size_t end) {
    if (end <= first + 1) return end;
    std::size_t loudest = end - 1;
    for (std::size_t t = end > first + kTailReferenceFrames ? end - kTailReferenceFrames : first; t < end; ++t)
        if (track.at(t, kEnergyDb) > track.at(loudest, kEnergyDb)) loudest = t;
    const float mark_db = track.at(loudest, kEnergyDb) - kTailFallDb;
    std::size_t trimmed = end;
    while (trimmed > loudest + 1 && track.at(trimmed - 1, kEnergyDb) < mark_db) --trimmed;
    return trimmed;
}

// Frames of `span` that are not in a pause: what the syllables fill, so that the vowels' duration
// priors follow the speaking rate, not the pauses (a transcript without punctuation runs over the
// pauses between its sentences).
std::size_t speech_frames(const LoudnessProfile& loudness, const FrameSpan& span) {
    std::size_t frames = span.length();
    for (const auto& pause : loudness.pauses)
        if (pause.first_frame >= span.first_frame && pause.end_frame <= span.end_frame) frames -= pause.length();
    return frames;
}

// Writes the syllables of one aligned sentence into `result`.
void place_syllables(const SentenceWork& work, const std::vector<StateSegment>& path, const EmissionScores& scores,
                     const FeatureTrack& track, Timeline& result) {
    const double offset_s = static_cast<double>(work.searched.first_frame) * kFrameStepS;
    // The last frame may run past the audio's last sample: no time is later than the audio's end.
    auto time_s = [&](std::size_t frame) {
        return std::min(track.duration_s, offset_s + static_cast<double>(frame) * kFrameStepS);
    };
    for (std::size_t local = 0; local < work.syllables.size(); ++local) {
        Syllable& syllable = result.syllables[work.syllable_indices[local]];
        std::size_t first = 0, end = 0;
        std::optional<std::size_t> final_first;
        bool has_start = false;
        double posterior_sum = 0.0;
        std::size_t frames = 0;
        for (std::size_t p = 0; p < path.size(); ++p) {
            const PhoneState& state = work.states[path[p].state];
            if (state.syllable != local || is_pause(state.role)) continue;
            std::size_t segment_first = path[p].first_frame;
            // SPEC: after a pause the closure cannot be told from the pause; the syllable starts
            // at the burst. A pause the transcript does not mark counts when it is longer than
            // any closure (a sentence end in a transcript without punctuation).
            if (state.role == StateRole::closure && p > 0) {
                const StateSegment& before = path[p - 1];
                const StateRole role = work.states[before.state].role;
                const std::size_t silence = before.end_frame - before.first_frame + path[p].end_frame - path[p].first_frame;
                if (role == StateRole::comma_pause || (role == StateRole::short_pause && silence >= kPauseBeforeBurstFrames))
                    segment_first = path[p].end_frame;
            }
            if (!has_start) {
                first = segment_first;
                has_start = true;
            }
            end = path[p].end_frame;
            if (state.role == StateRole::final && !final_first) final_first = path[p].first_frame;
            for (std::size_t t = path[p].first_frame; t < path[p].end_frame; ++t) {
                const float* row = &scores.values[t * kPhoneClassCount];
                const double total = log_sum_exp(row, kPhoneClassCount);
                posterior_sum += std::exp(static_cast<double>(row[state.phone_class]) - total);
                ++frames;
            }
        }
        if (local + 1 == work.syllables.size()) {
            const std::size_t offset = work.searched.first_frame;
            const std::size_t trimmed = end_before_tail(track, offset + first, offset + end) - offset;
            end = std::max(trimmed, final_first.value_or(first) + 1);
        }
        syllable.start_s = time_s(first);
        syllable.end_s = time_s(std::max(end, first + 1));
        syllable.final_start_s = time_s(final_first.value_or(first));
        syllable.confidence = frames > 0 ? posterior_sum / static_cast<double>(frames) : 0.0;
    }
}

// How well the speech of `path` (a sentence's, or its share of a block's) fits the models of the
// sounds its text says, per frame.
double speech_fit(const SentenceWork& work, const std::vector<StateSegment>& path, const EmissionScores& scores) {
    double sum = 0.0;
    std::size_t frames = 0;
    for (const auto& segment : path) {
        const PhoneState& state = work.states[segment.state];
        if (is_pause(state.role)) continue;
        for (std::size_t t = segment.first_frame; t < segment.end_frame; ++t) sum += scores.at(t, state.phone_class);
        frames += segment.end_frame - segment.first_frame;
    }
    return frames > 0 ? sum / static_cast<double>(frames) : -std::numeric_limits<double>::infinity();
}

// The path of a block cut into its sentences' shares (a pause goes with the sentence before it),
// each with the index of its sentence in the transcript.
std::vector<std::pair<std::size_t, std::vector<StateSegment>>> split_by_sentence(const SentenceWork& work,
                                                                                const std::vector<StateSegment>& path) {
    std::vector<std::pair<std::size_t, std::vector<StateSegment>>> shares;
    for (const auto& segment : path) {
        const std::size_t sentence = work.syllables[work.states[segment.state].syllable]->sentence;
        if (shares.empty() || shares.back().first != sentence) shares.emplace_back(sentence, std::vector<StateSegment>());
        shares.back().second.push_back(segment);
    }
    return shares;
}

// How much better, per frame, the sentence's speech fits the best sequence of sounds than the
// sequence its text says: a phone loop against the forced path, on the same re-estimated models.
// The loop pays for each change of sound, so on the right text it gains little over the path; on
// a wrong text of the same length (two sentences swapped, another sentence) the path is forced
// through sounds that are not there. Unlike the fit against the other sentences, this needs none.
double text_fit_gap(const SentenceWork& work, const std::vector<StateSegment>& path, const EmissionScores& scores) {
    std::size_t first = 0, end = 0;
    bool has_speech = false;
    for (const auto& segment : path) {
        if (is_pause(work.states[segment.state].role)) continue;
        if (!has_speech) first = segment.first_frame;
        has_speech = true;
        end = segment.end_frame;
    }
    if (!has_speech || end <= first) return 0.0;
    double forced = 0.0;
    for (const auto& segment : path) {
        const int phone_class = work.states[segment.state].phone_class;
        const std::size_t segment_first = std::max(segment.first_frame, first);
        const std::size_t segment_end = std::min(segment.end_frame, end);
        for (std::size_t t = segment_first; t < segment_end; ++t) forced += scores.at(t, phone_class);
    }
    std::array<double, kPhoneClassCount> best{};
    for (std::size_t t = first; t < end; ++t) {
        const double leader = *std::max_element(best.begin(), best.end());
        for (int c = 0; c < kPhoneClassCount; ++c)
            best[static_cast<std::size_t>(c)] = std::max(best[static_cast<std::size_t>(c)], leader - kLoopSwitchPenalty) + scores.at(t, c);
    }
    const double free = *std::max_element(best.begin(), best.end());
    return (free - forced) / static_cast<double>(end - first);
}

// The path of a chain cut between its syllables into each sentence's first and second half
// (pauses go with the syllable before them): half h of the chain's j-th sentence is 2 j + h.
std::vector<std::vector<StateSegment>> split_in_halves(const SentenceWork& work, const std::vector<StateSegment>& path) {
    std::vector<std::size_t> half_of_syllable(work.syllables.size());
    std::size_t first = 0;
    std::size_t sentences = 0;
    for (; first < work.syllables.size(); ++sentences) {
        std::size_t end = first;
        while (end < work.syllables.size() && work.syllables[end]->sentence == work.syllables[first]->sentence) ++end;
        const std::size_t second_half = first + (end - first + 1) / 2;
        for (std::size_t i = first; i < end; ++i) half_of_syllable[i] = 2 * sentences + (i < second_half ? 0 : 1);
        first = end;
    }
    std::vector<std::vector<StateSegment>> halves(2 * sentences);
    for (const auto& segment : path) halves[half_of_syllable[work.states[segment.state].syllable]].push_back(segment);
    return halves;
}

// text_fit_gap of each half of each sentence of a chain, scored with models learned from the rest of the
// recording only (leave one out); an empty half gives minus infinity. Models re-estimated on a
// recording fit whatever text shaped them, and on a file of a sentence or two a wrong text shapes
// most of them; models that never saw these frames cannot bend to it. `half_estimators` holds the
// two halves' shares of `whole`; `scores` is overwritten (an hour's scores are 19 MB: no second
// buffer).
std::vector<double> held_out_fit_gaps(const SentenceWork& work, const std::vector<std::vector<StateSegment>>& halves,
                                      const std::vector<float>& observations, const ModelEstimator& whole,
                                      const std::vector<ModelEstimator>& half_estimators, EmissionScores& scores) {
    std::vector<double> gaps(halves.size(), -std::numeric_limits<double>::infinity());
    std::vector<float> half_observations;
    for (std::size_t h = 0; h < halves.size(); ++h) {
        if (halves[h].empty()) continue;
        ModelEstimator rest = whole;
        rest.subtract(half_estimators[h]);
        // Only the half's own frames are scored: a chain of sentences run together is long.
        const std::size_t first = halves[h].front().first_frame;
        const std::size_t end = halves[h].back().end_frame;
        half_observations.assign(observations.begin() + static_cast<std::ptrdiff_t>(first * kObservationCount),
                                 observations.begin() + static_cast<std::ptrdiff_t>(end * kObservationCount));
        rest.estimate(kReestimatedWeight).score(half_observations, end - first, scores);
        std::vector<StateSegment> shifted = halves[h];
        for (auto& segment : shifted) {
            segment.first_frame -= first;
            segment.end_frame -= first;
        }
        gaps[h] = text_fit_gap(work, shifted, scores);
    }
    return gaps;
}

std::vector<AlignedStretch> stretches_of(const SentenceWork& work, const std::vector<StateSegment>& path) {
    std::vector<AlignedStretch> stretches;
    for (const auto& segment : path) {
        const PhoneState& state = work.states[segment.state];
        const bool is_pause_state = is_pause(state.role);
        const std::size_t syllable = work.syllable_indices[state.syllable];
        const std::size_t first = work.searched.first_frame + segment.first_frame;
        const std::size_t end = work.searched.first_frame + segment.end_frame;
        if (!stretches.empty() && stretches.back().is_pause == is_pause_state && stretches.back().syllable == syllable) {
            stretches.back().end_frame = end;
        } else {
            stretches.push_back({first, end, is_pause_state, syllable});
        }
    }
    return stretches;
}

// Frames from the first syllable's start to the last one's end of sentence `k` of `work` as
// aligned in `result`.
FrameSpan aligned_span(const Timeline& result, const SentenceWork& work, std::size_t k) {
    FrameSpan span{std::numeric_limits<std::size_t>::max(), 0};
    for (const std::size_t i : work.syllable_indices) {
        const Syllable& syllable = result.syllables[i];
        if (syllable.sentence != k) continue;
        span.first_frame = std::min(span.first_frame, static_cast<std::size_t>(std::lround(syllable.start_s / kFrameStepS)));
        span.end_frame = std::max(span.end_frame, static_cast<std::size_t>(std::lround(syllable.end_s / kFrameStepS)));
    }
    return span;
}

// The syllables of every sentence of `cut`, aligned sentence by sentence (neighbours that run on,
// together), and the checks that audio and transcript belong together.
Timeline align_cut(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                   const SentenceCut& cut, ProgressReporter& progress) {
    // Where sentences run together the cutter's spans are guesses: the syllables place them, and
    // the sentences' lengths are checked on where the syllables put them.
    std::vector<FrameSpan> spans = cut.spans;
    const bool has_blocks = std::find(cut.runs_on.begin(), cut.runs_on.end(), true) != cut.runs_on.end();
    if (!has_blocks) check_sentence_lengths(spans, loudness, transcript);

    std::vector<SentenceWork> work;
    std::size_t spoken_sentences = 0;
    bool continues_block = false;
    // One pass: the syllables come in sentence order (validate_transcript), and a sentence without
    // syllables has nothing to align.
    for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
        const std::size_t k = transcript.syllables[i].sentence;
        if (i == 0 || transcript.syllables[i - 1].sentence != k) {
            ++spoken_sentences;
            if (!continues_block) {
                work.emplace_back();
                work.back().first_sentence = k;
                work.back().speech = spans[k];
            }
            SentenceWork& block = work.back();
            block.end_sentence = k + 1;
            block.speech = {std::min(block.speech.first_frame, spans[k].first_frame), std::max(block.speech.end_frame, spans[k].end_frame)};
            continues_block = cut.runs_on[k];
        }
        work.back().syllables.push_back(&transcript.syllables[i]);
        work.back().syllable_indices.push_back(i);
    }
    // Edges reach into the pauses around the sentence, at most halfway to its neighbours.
    for (std::size_t w = 0; w < work.size(); ++w) {
        const FrameSpan& speech = work[w].speech;
        const std::size_t lower = w == 0 ? 0 : (work[w - 1].speech.end_frame + speech.first_frame) / 2;
        const std::size_t upper =
            w + 1 == work.size() ? track.frame_count : (speech.end_frame + work[w + 1].speech.first_frame + 1) / 2;
        work[w].searched.first_frame = std::max(lower, speech.first_frame > kEdgeFrames ? speech.first_frame - kEdgeFrames : 0);
        // A sentence that ends in a room's tail is searched only a little past the voice's end, and
        // its vowels are scaled to the voiced part: the tail is not speech to spread them over.
        const std::size_t voiced_end = end_before_tail(track, speech.first_frame, speech.end_frame);
        work[w].ends_in_tail = voiced_end + kRoomTailFrames <= speech.end_frame;
        work[w].searched.end_frame =
            std::min(upper, voiced_end < speech.end_frame ? voiced_end + kTailEdgeFrames : speech.end_frame + kEdgeFrames);
        work[w].states = build_phone_chain(work[w].syllables, work[w].searched.length(),
                                           speech_frames(loudness, {speech.first_frame, voiced_end}));
    }

    Timeline result = transcript;
    result.duration_s = track.duration_s;
    std::vector<double> fits(spans.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<double> fit_gaps(spans.size(), 0.0);
    std::vector<double> held_out_gaps(spans.size(), 0.0);
    // check_own_fit's gaps and check_syllable_lengths' spreads: files of one or two sentences only.
    std::vector<double> own_fit_gaps(spans.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<double> length_spreads(spans.size(), std::numeric_limits<double>::quiet_NaN());
    // What the last re-estimation learned, in all and from each half of each sentence (per chain).
    ModelEstimator whole_estimator;
    std::vector<std::vector<ModelEstimator>> half_estimators;
    AcousticModel model = AcousticModel::hand_set();
    const int passes = 1 + kReestimationRounds;
    const double alignment_share = 1.0 - kReadingShare - kCuttingShare;
    std::vector<float> observations;
    EmissionScores scores;
    ViterbiWorkspace workspace;
    for (int pass = 0; pass < passes; ++pass) {
        const bool is_last = pass + 1 == passes;
        const bool is_last_estimate = pass + 2 == passes;
        ModelEstimator estimator;
        if (is_last_estimate) half_estimators.assign(work.size(), {});
        for (std::size_t w = 0; w < work.size(); ++w) {
            const SentenceWork& sentence = work[w];
            observe(track, loudness, sentence.searched, observations);
            model.score(observations, sentence.searched.length(), scores);
            // The hand-set models only start the re-estimation: on a sentence long enough to be
            // searched in windows (a transcript without punctuation), their weak evidence lets the
            // open-ended windows slip a syllable now and then, which adds up over an hour; its
            // first minutes teach the models every sound many times over.
            const std::vector<StateSegment> path =
                viterbi_align(sentence.states, scores, workspace, pass == 0 ? kBootstrapFrames : scores.frame_count);
            if (path.empty()) {
                throw AlignmentError(describe_sentence(sentence.first_sentence, sentence.speech, transcript) + ": its " +
                                     std::to_string(sentence.syllables.size()) +
                                     " syllables do not fit in so short a stretch of speech; check the transcript");
            }
            if (is_last) {
                place_syllables(sentence, path, scores, track, result);
                const bool is_block = sentence.end_sentence > sentence.first_sentence + 1;
                for (const auto& [k, share] : split_by_sentence(sentence, path)) {
                    if (is_block) spans[k] = aligned_span(result, sentence, k);
                    fits[k] = speech_fit(sentence, share, scores);
                    fit_gaps[k] = text_fit_gap(sentence, share, scores);
                }
                // In a room every sound rings into the next, and a right text's halves gap up to
                // 0.85 (bench/ reverb): there the check would refuse one right sentence in six.
                // With three sentences or more, check_text_fit and check_fit compare each with
                // the others, which holds better than this absolute limit.
                // In a chain, models re-estimated on it fit its sentences' texts as they would in a
                // file of one or two: the halves of each are checked the same way.
                if (!sentence.ends_in_tail && (spoken_sentences <= kMaxHeldOutCheckSentences || is_block)) {
                    const auto halves = split_in_halves(sentence, path);
                    const auto gaps = held_out_fit_gaps(sentence, halves, observations, whole_estimator,
                                                        half_estimators[w], scores);
                    for (std::size_t h = 0; h < halves.size(); ++h) {
                        if (halves[h].empty()) continue;
                        const std::size_t k = sentence.syllables[sentence.states[halves[h].front().state].syllable]->sentence;
                        held_out_gaps[k] = std::max(held_out_gaps[k], gaps[h]);
                    }
                }
                // Where a sentence ends in a room's tail a right text gaps up to 0.07 and spreads its
                // syllables' lengths up to 0.79 (bench/ reverb), as much as a wrong text: there
                // check_own_fit and check_syllable_lengths would refuse right texts.
                const bool is_own_model = !sentence.ends_in_tail && spoken_sentences <= kMaxHeldOutCheckSentences;
                for (const auto& [k, share] : split_by_sentence(sentence, path)) {
                    const auto stretches = stretches_of(sentence, share);
                    if (is_own_model) {
                        own_fit_gaps[k] = fit_gaps[k];
                        length_spreads[k] = syllable_length_spread(stretches);
                    }
                    check_path(stretches, loudness, k, spans[k], transcript);
                }
            }
            else {
                estimator.add(observations, sentence.states, path);
                if (is_last_estimate) {
                    const auto halves = split_in_halves(sentence, path);
                    half_estimators[w].assign(halves.size(), ModelEstimator());
                    for (std::size_t h = 0; h < halves.size(); ++h) half_estimators[w][h].add(observations, sentence.states, halves[h]);
                }
            }
            progress.report(kReadingShare + kCuttingShare +
                                alignment_share * (pass + static_cast<double>(w + 1) / static_cast<double>(work.size())) / passes,
                            "syllables");
        }
        if (!is_last) model = estimator.estimate(kReestimatedWeight);
        if (is_last_estimate) whole_estimator = std::move(estimator);
    }
    if (has_blocks) check_sentence_lengths(spans, loudness, transcript);
    check_text_fit(fit_gaps, spans, transcript);
    check_held_out_fit(held_out_gaps, spans, transcript);
    check_own_fit(own_fit_gaps, spans, transcript);
    check_syllable_lengths(length_spreads, spans, transcript);
    check_fit(fits, spans, transcript);

    for (std::size_t k = 0; k < result.sentences.size(); ++k) {
        const auto first = std::find_if(result.syllables.begin(), result.syllables.end(),
                                        [&](const Syllable& s) { return s.sentence == k; });
        if (first == result.syllables.end()) {
            const double at = static_cast<double>(spans[k].first_frame) * kFrameStepS;
            result.sentences[k].start_s = result.sentences[k].end_s = at;
            continue;
        }
        const auto last = std::find_if(result.syllables.rbegin(), result.syllables.rend(),
                                       [&](const Syllable& s) { return s.sentence == k; });
        result.sentences[k].start_s = first->start_s;
        result.sentences[k].end_s = last->end_s;
    }
    return result;
}

// align_cut, where a sentence end that ran on keeps its chain only if the chain's syllables move
// it out of the pause the cutter chose and put that pause where the text has one (a comma's): a
// sentence end they leave in its pause confirms the cut, and one they move off a pause the text
// does not account for is a wrong text's doing. Then the sentences are aligned apart again, as
// the checks know them best.
Timeline align_confirmed(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                         const SentenceCut& cut, const std::vector<bool>& is_spoken, ProgressReporter& progress) {
    Timeline result = align_cut(track, loudness, transcript, cut, progress);
    SentenceCut confirmed = cut;
    for (const auto& [k, next] : spoken_neighbours(is_spoken)) {
        // Too few pauses: the cutter chose none for this end, and the chain is all there is.
        const bool has_cut_pause = cut.spans[k].end_frame <= cut.spans[next].first_frame;
        if (cut.runs_on[k] && has_cut_pause &&
            !(moves_sentence_end(cut, result, k, next) && is_cut_pause_in_text(cut, result, k, next)))
            confirmed.runs_on[k] = false;
    }
    if (confirmed.runs_on == cut.runs_on) return result;
    return align_cut(track, loudness, transcript, confirmed, progress);
}

Timeline align_track(const FeatureTrack& track, const Timeline& transcript, const AlignOptions& options,
                     ProgressReporter& progress) {
    const LoudnessProfile loudness = measure_loudness(track);
    if (loudness.speech_end_frame <= loudness.speech_first_frame)
        throw AlignmentError("no speech found in the " + format_fixed(track.duration_s, 2) +
                             " s of audio: nothing rises above its noise floor");
    const SentenceCut cut = cut_sentences(track, loudness, transcript, options);
    progress.report(kReadingShare + kCuttingShare, "sentences");
    const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
    const auto spoken_sentences = static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true));
    const std::size_t stretches = loudness.pauses.size() + 1;
    Timeline result;
    try {
        result = align_confirmed(track, loudness, transcript, cut, is_spoken, progress);
    } catch (const AlignmentError& error) {
        // Fewer stretches of speech than sentences: either sentences run together or the
        // transcript has one the audio lacks; the first is tried, and the message tells of both.
        if (options.sentence_cut == SentenceCutMode::automatic && stretches < spoken_sentences)
            throw AlignmentError("the transcript has " + std::to_string(spoken_sentences) +
                                 " spoken sentences but the audio has only " + std::to_string(stretches) +
                                 " stretches of speech between pauses, and run together they do not fit it either: " +
                                 error.what());
        // A sentence end cut at a pause inside a sentence (speech run together, whose only pauses
        // are a comma's) squeezes one sentence and stretches the next until a check refuses them.
        // Aligned as one block, the syllables find the ends; a transcript that does not match the
        // audio fails there too, and the first, sentence-by-sentence, account of it is kept. Where
        // the pauses do single the sentence ends out (and in the caller's own cut, Algorithm 3.1),
        // the cut stands and so does the refusal.
        if (!cut.is_in_doubt || block_count(cut, transcript) == 1) throw;
        SentenceCut block = cut;
        std::fill(block.runs_on.begin(), block.runs_on.end(), true);
        try {
            result = align_cut(track, loudness, transcript, block, progress);
        } catch (const AlignmentError&) {
            throw error;
        }
        // Syllables that end every sentence in the pause it was cut at confirm the cut, and a
        // sentence end moved off a pause the text does not account for is a wrong text's doing:
        // either way it was the text, not the cut, that the checks refused.
        bool has_moved_end = false;
        for (const auto& [k, next] : spoken_neighbours(is_spoken)) {
            if (!moves_sentence_end(cut, result, k, next)) continue;
            if (!is_cut_pause_in_text(cut, result, k, next)) throw error;
            has_moved_end = true;
        }
        if (!has_moved_end) throw error;
    }
    progress.report(1.0, "syllables");
    return result;
}

Timeline align_source(AudioSource& source, const Timeline& transcript, const AlignOptions& options,
                      const ProgressCallback& callback) {
    validate_transcript(transcript);
    ProgressReporter progress(callback);
    progress.report(0.0, "reading");
    const FeatureTrack track =
        analyze_audio(source, [&](double fraction) { progress.report(kReadingShare * fraction, "reading"); });
    return align_track(track, transcript, options, progress);
}

}  // namespace

struct SpeechAligner::Impl {
    AlignOptions options;
};

SpeechAligner::SpeechAligner(AlignOptions options) : impl_(std::make_unique<Impl>()) {
    if (!(options.c1 >= 0.5 && options.c1 <= 1.0))
        throw InvalidArgument("c1", "expected 0.5..1 (Algorithm 3.1 step 3), found " + format_shortest(options.c1));
    if (!(options.c2 >= 1.0 && options.c2 <= 1.5))
        throw InvalidArgument("c2", "expected 1..1.5 (Algorithm 3.1 step 4), found " + format_shortest(options.c2));
    if (options.sentence_cut != SentenceCutMode::automatic && options.sentence_cut != SentenceCutMode::first_pause)
        throw InvalidArgument("sentence_cut", "unknown mode " + std::to_string(static_cast<int>(options.sentence_cut)));
    if (options.sentence_cut == SentenceCutMode::first_pause &&
        !(std::isfinite(options.first_pause_start_s) && std::isfinite(options.first_pause_end_s) &&
          options.first_pause_start_s >= 0.0 && options.first_pause_end_s > options.first_pause_start_s))
        throw InvalidArgument("first_pause", "expected 0 <= start < end in seconds, found " +
                                                 format_shortest(options.first_pause_start_s) + ".." +
                                                 format_shortest(options.first_pause_end_s));
    impl_->options = options;
}

SpeechAligner::~SpeechAligner() = default;
SpeechAligner::SpeechAligner(SpeechAligner&&) noexcept = default;
SpeechAligner& SpeechAligner::operator=(SpeechAligner&&) noexcept = default;

const AlignOptions& SpeechAligner::options() const { return impl_->options; }

Timeline SpeechAligner::align(const AudioView& audio, const Timeline& transcript, const ProgressCallback& progress) const {
    const auto source = open_audio_view(audio);
    return align_source(*source, transcript, impl_->options, progress);
}

Timeline SpeechAligner::align_file(const std::string& audio_path, const Timeline& transcript,
                                   const ProgressCallback& progress) const {
    validate_transcript(transcript);
    const auto source = open_audio_file(audio_path);
    try {
        return align_source(*source, transcript, impl_->options, progress);
    } catch (const AlignmentError& error) {
        // Name the audio: the times in the message are in this file.
        throw AlignmentError(audio_path + ": " + error.what());
    }
}

}  // namespace v0
}  // namespace talkface
