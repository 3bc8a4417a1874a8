// SpeechAligner: audio -> features (streamed) -> sentence utterances -> per-sentence HSMM
// alignment, re-estimated on the recording (thesis chapter 3, SPEC "Alignment").
#include "talkface/speech_aligner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "audio/audio_source.hpp"
#include "common/number_format.hpp"
#include "common/order_statistics.hpp"
#include "speech/acoustic_model.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/alignment_confidence.hpp"
#include "speech/dropout_concealment.hpp"
#include "speech/frame_features.hpp"
#include "speech/given_spans_alignment.hpp"
#include "speech/hsmm.hpp"
#include "speech/late_reverb.hpp"
#include "speech/latin_only_text.hpp"
#include "speech/lenient_chain.hpp"
#include "speech/line_among_voices.hpp"
#include "speech/phone_chain.hpp"
#include "speech/room_closures.hpp"
#include "speech/run_together.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "speech/syllable_placement.hpp"
#include "speech/text_fit.hpp"
#include "speech/tone_contour.hpp"
#include "talkface/errors.hpp"
#include "text/unread_transcript.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using namespace detail;

// SPEC "Alignment": a first pass on hand-set models, then three rounds re-estimated on the audio
// (the first pass's paths give the first round's models, the third round's the final pass's).
constexpr int kReestimationRounds = 3;
// Files of at most this many sentences get the leave-one-out check (held_out_fit_gaps).
constexpr std::size_t kMaxHeldOutCheckSentences = 2;
// A room's sentence's tone gap (SentenceMetrics::tone_gap) is measured in files of at least this
// many spoken sentences, the tones learned mostly from the others' syllables (in a file of one or
// two a wrong text's own syllables teach them), and from this many of its syllables judged.
constexpr std::size_t kMinToneWitnessSentences = 3;
constexpr std::size_t kMinToneWitnessSyllables = 3;
// How much of a long sentence the first pass, on hand-set models, aligns: two minutes.
constexpr std::size_t kBootstrapFrames = 12000;
// Shares of the job's progress as planned: reading and features, cutting, the alignment passes. The
// bar's last kWorkAgainShare is left to the work done again, which no plan foresees
// (ProgressReporter).
constexpr double kReadingShare = 0.45;
constexpr double kCuttingShare = 0.05;
constexpr double kWorkAgainShare = 0.05;
constexpr double kPlannedShare = 1.0 - kWorkAgainShare;
constexpr double kProgressStep = 0.002;

// Thrown where check_text_fit refuses a sentence of a room's file of kMinToneWitnessSentences or
// more and the pitch was not measured: with it the sentence's tones may witness for its text
// (align_source reads the recording again). Not an AlignmentError: no refusal's handler takes it.
struct ToneWitnessWanted {};

// The bar: the job's progress as planned (reading, cutting, the alignment passes, up to
// kPlannedShare), and work done again, which reports from lower once more: the cut aligned again
// (kept to the text's pauses, with nasal releases, its sentence ends confirmed, as one block), the
// alignment made again without its checks (CheckMode::warn), the recording read again (with the
// pitch, at another phase). How much of that comes is known only as it comes, so each such piece
// fills half of the bar still left: the bar moves while the callback is asked, and reaches 1.0
// only when the job is done (session 28: the planned alignment ended at 1.0, and the bar stood
// there through the work done again).
class ProgressReporter {
public:
    explicit ProgressReporter(const ProgressCallback& callback) : callback_(callback) {}

    // `fraction` of the job as planned, in `stage`: asked at most every kProgressStep of a stage.
    void report(double fraction, const char* stage) {
        if (!callback_) return;
        if (fraction < planned_fraction_) {
            // Work done again begins: the bar stands where it is for this report, and the ones
            // after it move it through half of what is left.
            again_from_ = fraction;
            again_base_ = bar_;
            again_scale_ = 0.5 * (1.0 - bar_) / (kPlannedShare - fraction);
            planned_fraction_ = fraction;
            stage_ = stage;
            return;
        }
        if (stage == stage_ && fraction < planned_fraction_ + kProgressStep) return;
        planned_fraction_ = fraction;
        stage_ = stage;
        bar_ = std::min(again_base_ + (fraction - again_from_) * again_scale_, kBarBeforeDone);
        ask(bar_);
    }

    // The job is done: the bar at 1.0, in the alignment's last stage.
    void report_done() {
        if (!callback_) return;
        stage_ = "syllables";
        bar_ = 1.0;
        ask(bar_);
    }

private:
    // The most the bar shows before report_done: reports are double and may round up to 1.0.
    static constexpr double kBarBeforeDone = 1.0 - 1e-9;

    void ask(double bar) {
        if (!callback_(bar, stage_))
            throw Cancelled(std::string("alignment cancelled by the progress callback while ") + stage_ +
                            " at " + format_fixed(100.0 * bar, 1) + "%");
    }

    const ProgressCallback& callback_;
    const char* stage_ = nullptr;
    double planned_fraction_ = -1.0;
    double bar_ = 0.0;
    // Where the work done last began again: the planned fraction it began at, the bar then, and how
    // far the bar moves per planned fraction (1 until work is done again).
    double again_from_ = 0.0;
    double again_base_ = 0.0;
    double again_scale_ = 1.0;
};

// The passes over the chains that share the bar's alignment part: kReestimationRounds of
// estimation, as many again in a room on its features without the ringing (late_reverb.hpp), which
// take as long, and the final one.
int alignment_passes(bool is_reestimated_dry) {
    return 1 + kReestimationRounds * (is_reestimated_dry ? 2 : 1);
}

// Progress after chain `w` of `count` in pass `pass` of `passes` (alignment_passes).
void report_pass(ProgressReporter& progress, int pass, int passes, std::size_t w, std::size_t count) {
    const double alignment_share = kPlannedShare - kReadingShare - kCuttingShare;
    progress.report(kReadingShare + kCuttingShare +
                        alignment_share * (pass + static_cast<double>(w + 1) / static_cast<double>(count)) / passes,
                    "syllables");
}

// The features of `source` (analyze_audio, after the samples `read_first` already read from it),
// its reading reported as the job's first kReadingShare.
FeatureTrack read_features(AudioSource& source, ProgressReporter& progress, bool with_pitch,
                           std::size_t skipped_samples, const std::vector<float>& read_first = {}) {
    return analyze_audio(
        source, [&](double fraction) { progress.report(kReadingShare * fraction, "reading"); }, with_pitch,
        skipped_samples, read_first);
}

void validate_transcript(const Timeline& transcript) {
    if (transcript.syllables.empty())
        throw InvalidArgument("transcript", "no syllables to align (" + detail::describe_unread_transcript(transcript) + ")");
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

// A chain's best path on `scores`; with `marginals`, over all frames, with its EntryMaxMarginals.
// \throws talkface::AlignmentError if its syllables do not fit in its stretch of speech.
std::vector<StateSegment> align_chain(const SentenceChain& chain, const EmissionScores& scores,
                                      ViterbiWorkspace& workspace, std::size_t stop_frame,
                                      const Timeline& transcript, EntryMaxMarginals* marginals = nullptr) {
    std::vector<StateSegment> path =
        marginals ? viterbi_align_with_marginals(chain.states, scores, workspace, *marginals)
                  : viterbi_align(chain.states, scores, workspace, stop_frame);
    if (path.empty()) {
        throw AlignmentError(describe_sentence(chain.first_sentence, chain.speech, transcript) + ": its " +
                             syllable_count(chain.syllables.size()) + (chain.syllables.size() == 1 ? " does" : " do") +
                             " not fit in so short a stretch of speech; check the transcript");
    }
    return path;
}

// What the re-estimation learned: the models of the last round, and what its last round saw in
// all and from each half of each sentence (per chain), for the leave-one-out check; and each
// chain's path in the last round, on the round before's models, whose disagreement with the final
// pass's path lowers a syllable's confidence (syllable_steadiness); and how far the last round's
// paths speak through their closures (typical_closure_run_on), read before any chain is measured.
struct Reestimation {
    AcousticModel model = AcousticModel::hand_set();
    ModelEstimator whole;
    std::vector<std::vector<ModelEstimator>> halves;
    std::vector<std::vector<StateSegment>> last_paths;
    double closure_run_on = 0.0;
};

// SPEC "Alignment": a first pass on the hand-set models, then kReestimationRounds rounds of
// models re-estimated on the paths of every chain, reported as passes `first_pass` on of `passes`.
Reestimation reestimate(const FeatureTrack& track, const LoudnessProfile& loudness,
                        const Timeline& transcript, const std::vector<SentenceChain>& chains,
                        ProgressReporter& progress, int first_pass, int passes) {
    Reestimation learned;
    std::vector<float> observations;
    EmissionScores scores;
    ViterbiWorkspace workspace;
    std::vector<double> closure_run_on;
    for (int pass = 0; pass < kReestimationRounds; ++pass) {
        const bool is_last_estimate = pass + 1 == kReestimationRounds;
        ModelEstimator estimator;
        if (is_last_estimate) {
            learned.halves.assign(chains.size(), {});
            learned.last_paths.reserve(chains.size());
        }
        for (std::size_t w = 0; w < chains.size(); ++w) {
            const SentenceChain& chain = chains[w];
            observe(track, loudness, chain.searched, observations);
            learned.model.score(observations.data(), chain.searched.length(), scores);
            // The hand-set models only start the re-estimation: on a sentence long enough to be
            // searched in windows (a transcript without punctuation), their weak evidence lets the
            // open-ended windows slip a syllable now and then, which adds up over an hour; its
            // first minutes teach the models every sound many times over.
            const auto path =
                align_chain(chain, scores, workspace, pass == 0 ? kBootstrapFrames : scores.frame_count, transcript);
            estimator.add(observations, chain.states, path);
            if (is_last_estimate) {
                const auto halves = split_in_halves(chain, path);
                learned.halves[w].assign(halves.size(), ModelEstimator());
                for (std::size_t h = 0; h < halves.size(); ++h) learned.halves[w][h].add(observations, chain.states, halves[h]);
                learned.last_paths.push_back(path);
                add_closure_run_on(chain, path, scores, closure_run_on);
            }
            report_pass(progress, first_pass + pass, passes, w, chains.size());
        }
        learned.model = estimator.estimate(kReestimatedWeight);
        if (is_last_estimate) learned.whole = std::move(estimator);
    }
    learned.closure_run_on = typical_closure_run_on(std::move(closure_run_on));
    return learned;
}

// How far the text fits of a recording of `spoken_sentences` forgive a stop's closure spoken
// through (text_fit_gap), as far as the recording's own closures are spoken through
// (learned.closure_run_on, the typical closure frame's run-on). At a fast pace a stop after a vowel
// is said with no silence before its burst, and the frame or two the path must give its closure
// sound like the vowel run on: scored as silence, each cost a right text 5-15 per frame (bench/
// espeak-ng fast, dev26's dialogue), and a line of six to nine syllables with three or four stops
// after speech (我就带了2块钱, 12点整开抢！) gapped 0.19-0.40 in its passage and was refused. Where
// the typical closure is spoken through (a run-on above 0: most closure frames sound more like the
// sound before them than silence) the speaker does not close, and every closure is forgiven
// wholly: forgiven only up to the typical run-on, a dense line's closures, which run on further,
// still refused 8 of the 12 such passages (bench/README.md, session 32 (dialog2)). In a room
// (`in_room`) the ringing, not the speaker, runs every closure on by about the room's own amount,
// the typical run-on, and only that is forgiven: a wrong text's closure forced onto a vowel runs on
// further (wholly forgiven there, the person's wrong passages in h-reverb were caught 43 -> 38).
// A speaker who keeps most closures silent (gcin-voice's speaker 3) has a typical run-on of 0 and
// keeps every closure's evidence. In a file of one or two sentences the models are learned from
// the sentence's own path and fit a wrong text's sounds as well as a right one's, all but the
// silence learned from the pauses around it: a closure where the speech has none is the evidence
// left (espeak-ng's 好啊 with the text 請進, tests/data/speech: a gap of 0.28, nearly all of it 進's
// closure after 請's ng), and its paths are too few to tell how the speaker speaks. There it stays
// silent.
double forgiven_closure_run_on(const Reestimation& learned, std::size_t spoken_sentences, bool in_room) {
    if (spoken_sentences <= kMaxHeldOutCheckSentences) return 0.0;
    if (in_room || learned.closure_run_on <= 0.0) return learned.closure_run_on;
    return std::numeric_limits<double>::infinity();
}

// The final pass over one chain, on the re-estimated models: its syllables placed in `result`
// (with `other_frames`, where other searches of it place them, weighing in on their confidences), what the
// checks judge of each of its sentences measured into `metrics` (a closure spoken through forgiven up to
// `forgiven_run_on`), and its path checked (check_path) when `is_checked`.
void measure_chain(const SentenceChain& chain, std::size_t w, const std::vector<StateSegment>& path,
                   const std::vector<std::vector<SyllableFrames>>& other_frames,
                   const std::vector<float>& observations, const Reestimation& learned,
                   std::size_t spoken_sentences, double forgiven_run_on, const FeatureTrack& track,
                   const LoudnessProfile& loudness, const Timeline& transcript, EmissionScores& scores,
                   ViterbiWorkspace& workspace, Timeline& result, std::vector<SyllableEvidence>& evidence,
                   std::vector<FrameSpan>& spans, std::vector<SentenceMetrics>& metrics, bool is_checked) {
    place_syllables(chain, w, path, other_frames, scores, track, result, evidence);
    for (const auto& [k, share] : split_by_sentence(chain, path)) {
        if (chain.is_block()) spans[k] = aligned_span(result, chain, k);
        metrics[k].fit = speech_fit(chain, share, scores);
        metrics[k].fit_gap = text_fit_gap(chain, share, scores, forgiven_run_on);
    }
    // Where a sentence ends in a room's tail a right text gaps up to 0.07 and spreads its syllables'
    // lengths up to 0.79 (bench/ reverb), as much as a wrong text: there check_own_fit and
    // check_syllable_lengths would refuse right texts. check_path judges on `scores` of the whole
    // recording's models, before held_out_fit_gaps overwrites them.
    const bool is_own_model = !chain.ends_in_tail && spoken_sentences <= kMaxHeldOutCheckSentences;
    const double margin = is_own_model ? order_margin(chain, path, scores, workspace) : std::numeric_limits<double>::quiet_NaN();
    // Alone in its file, a sentence's speech after its last syllable is judged against generic
    // speech: beside another sentence it would take that one's start.
    if (is_own_model && spoken_sentences == 1)
        metrics[chain.syllables.back()->sentence].unspoken_tail_frames = unspoken_tail_frames(chain, scores, workspace);
    for (const auto& [k, share] : split_by_sentence(chain, path)) {
        metrics[k].order_margin = margin;
        const auto stretches = stretches_of(chain, share);
        if (is_own_model) {
            metrics[k].own_fit_gap = metrics[k].fit_gap;
            metrics[k].length_spread = syllable_length_spread(stretches);
        }
        if (is_checked) check_path(stretches, loudness, scores, chain.searched.first_frame, k, spans[k], transcript);
    }
    // In a room every sound rings into the next, and a right text's halves gap up to 0.85 (bench/
    // reverb): there the check would refuse one right sentence in six. With three sentences or
    // more, check_text_fit and check_fit compare each with the others, which holds better than this
    // absolute limit. In a chain, models re-estimated on it fit its sentences' texts as they would
    // in a file of one or two: the halves of each are checked the same way.
    if (!chain.ends_in_tail && (spoken_sentences <= kMaxHeldOutCheckSentences || chain.is_block())) {
        const auto halves = split_in_halves(chain, path);
        const auto gaps = held_out_fit_gaps(chain, halves, observations, learned.whole, learned.halves[w],
                                            scores, forgiven_run_on);
        for (std::size_t h = 0; h < halves.size(); ++h) {
            if (halves[h].empty()) continue;
            const std::size_t k = chain.syllables[chain.states[halves[h].front().state].syllable]->sentence;
            metrics[k].held_out_gap = std::max(metrics[k].held_out_gap, gaps.halves[h]);
            if (h % 2 == 1) metrics[k].held_out_end_gap = std::max(0.0, gaps.halves[h]);
        }
        // The typical syllable's gap, of the whole sentence and of its second half: one noisy
        // stretch (a note of music, a squeezed syllable) rules a half's gap but not its median.
        std::vector<std::vector<double>> whole_gaps(metrics.size()), end_gaps(metrics.size());
        for (std::size_t h = 0; h < halves.size(); ++h) {
            std::size_t previous = chain.syllables.size();
            for (const auto& segment : halves[h]) {
                const std::size_t i = chain.states[segment.state].syllable;
                if (i == previous || !std::isfinite(gaps.syllables[i])) continue;
                previous = i;
                const std::size_t k = chain.syllables[i]->sentence;
                whole_gaps[k].push_back(gaps.syllables[i]);
                if (h % 2 == 1) end_gaps[k].push_back(gaps.syllables[i]);
            }
        }
        for (std::size_t k = 0; k < metrics.size(); ++k) {
            if (whole_gaps[k].empty()) continue;
            metrics[k].held_out_median = mean_median(whole_gaps[k]);
            metrics[k].held_out_last_is_worst =
                whole_gaps[k].back() >= *std::max_element(whole_gaps[k].begin(), whole_gaps[k].end());
            if (!end_gaps[k].empty()) metrics[k].held_out_end_median = mean_median(end_gaps[k]);
        }
    }
}

// Each sentence runs from its first syllable's start to its last one's end; one without
// syllables is an instant where the cut put it.
void set_sentence_times(const std::vector<FrameSpan>& spans, Timeline& result) {
    for (std::size_t k = 0; k < result.sentences.size(); ++k) {
        const auto first = std::find_if(result.syllables.begin(), result.syllables.end(),
                                        [&](const Syllable& s) { return s.sentence == k; });
        if (first == result.syllables.end()) {
            const double at = frame_time_s(spans[k].first_frame);
            result.sentences[k].start_s = result.sentences[k].end_s = at;
            continue;
        }
        const auto last = std::find_if(result.syllables.rbegin(), result.syllables.rend(),
                                       [&](const Syllable& s) { return s.sentence == k; });
        result.sentences[k].start_s = first->start_s;
        result.sentences[k].end_s = last->end_s;
    }
}

// A room's recording without its ringing (late_reverb.hpp), where the syllables given out are
// placed: its features, the models re-estimated on them, and a chain's observations and scores.
struct DryRoom {
    FeatureTrack track;
    Reestimation learned;
    std::vector<float> observations;
    EmissionScores scores;
};

// One alignment of a cut's sentences, before the checks judge it.
struct CutAlignment {
    Timeline result;
    // In a room (room_closures.hpp), the syllables placed again with the closures ringing, on the
    // features without the room's ringing (late_reverb.hpp): given out in the end, while every
    // check reads `result`, the silent closures' placement on the recorded features.
    std::optional<Timeline> room_result;
    std::vector<FrameSpan> spans;
    std::vector<SentenceMetrics> metrics;
    // A final path gave a pause the text does not mark more than kMaxUnmarkedPauseFrames, in a
    // chain whose text marks pauses (keep_pauses_to_marks).
    bool has_long_unmarked_pause = false;
};

// Whether `path` holds a pause the text does not mark longer than kMaxUnmarkedPauseFrames, where
// the chain's text marks some.
bool has_long_unmarked_pause(const SentenceChain& chain, const std::vector<StateSegment>& path) {
    if (!has_marked_pause(chain.states)) return false;
    return std::any_of(path.begin(), path.end(), [&](const StateSegment& segment) {
        return chain.states[segment.state].role == StateRole::short_pause &&
               segment.end_frame - segment.first_frame > kMaxUnmarkedPauseFrames;
    });
}

// The sum of the sentences' text fit gaps (text_fit_gap): the lower, the better the syllables fit
// the audio, each alignment judged on the models it re-estimated.
double total_fit_gap(const CutAlignment& aligned) {
    double sum = 0.0;
    for (const auto& metrics : aligned.metrics) sum += metrics.fit_gap;
    return sum;
}

// The sentences whose text fits their speech so much worse than free sounds do that check_text_fit
// would refuse them (kMaxTextFitGap); empty if none.
std::vector<std::size_t> poorly_fitting(const std::vector<SentenceMetrics>& metrics) {
    std::vector<std::size_t> poor;
    for (std::size_t k = 0; k < metrics.size(); ++k)
        if (metrics[k].fit_gap > kMaxTextFitGap) poor.push_back(k);
    return poor;
}

// Per chain, per syllable, its tone_gaps (tone_contour.hpp) on the chains' `plain_paths`: the shape
// of each syllable's final against the tones of every chain's syllables.
std::vector<std::vector<double>> tone_gaps_of_chains(const std::vector<SentenceChain>& chains,
                                                     const std::vector<std::vector<StateSegment>>& plain_paths,
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
            frames.first_frame = std::min(frames.first_frame, chains[w].searched.first_frame + segment.first_frame);
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
            shapes.push_back(frames.first_frame < frames.end_frame ? tone_shape(track, frames.first_frame, frames.end_frame, reference_hz)
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

// Each sentence's SentenceMetrics::tone_gap on the chains' `paths`: the mean of its syllables' tone
// gaps, where at least kMinToneWitnessSyllables were judged.
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

// What lenient alignment measures of a chain on its plain path (the chain aligned without
// leniency) before its lenient pass: the chain's scores, each syllable's fit and frames on that
// path, and its held-out gap (lenient_chain.hpp), empty where the chain has no plain path; and its
// syllables' tone gaps (tone_gaps_of_chains), read on the plain paths of every chain.
struct LenientEvidence {
    EmissionScores scores;
    std::vector<double> plain_fits;
    std::vector<SyllableFrames> plain_frames;
    std::vector<double> held_out_gaps;
    std::vector<double> tone_gaps;
};

// Lenient alignment's evidence, chain by chain: every chain's plain path first, for the tones of
// the whole recording, and with it what the lenient pass judges its skips by; each chain's scores
// are kept for that pass, not measured twice. `observations` and `workspace` are scratch.
std::vector<LenientEvidence> measure_lenient_evidence(
    const FeatureTrack& track, const LoudnessProfile& loudness, const std::vector<SentenceChain>& chains,
    const Reestimation& learned, std::vector<float>& observations, ViterbiWorkspace& workspace) {
    std::vector<LenientEvidence> lenient_evidence;
    std::vector<std::vector<StateSegment>> plain_paths;
    for (std::size_t w = 0; w < chains.size(); ++w) {
        observe(track, loudness, chains[w].searched, observations);
        LenientEvidence& found = lenient_evidence.emplace_back();
        learned.model.score(observations.data(), chains[w].searched.length(), found.scores);
        plain_paths.push_back(
            viterbi_align(chains[w].states, found.scores, workspace, found.scores.frame_count));
        // A text with more syllables than the speech holds may have no plain path: no fits.
        const auto& plain = plain_paths.back();
        if (plain.empty()) continue;
        found.plain_fits = fits_on_path(chains[w], plain, found.scores);
        found.plain_frames = frames_on_path(chains[w], plain);
        // Each syllable's held-out gap on the plain path (lenient_chain.hpp judges skips and
        // grows mismatches by it): models re-estimated on a wrong text learn its sounds from
        // the speech that does not say them, those learned without its half have not.
        // Closures scored as silence: lenient_chain.cpp's limits on these gaps were set so.
        EmissionScores held_out_scores;
        found.held_out_gaps = held_out_fit_gaps(chains[w], split_in_halves(chains[w], plain), observations,
                                                learned.whole, learned.halves[w], held_out_scores, 0.0)
                                  .syllables;
    }
    std::vector<std::vector<double>> tone_gaps = tone_gaps_of_chains(chains, plain_paths, track);
    for (std::size_t w = 0; w < chains.size(); ++w) lenient_evidence[w].tone_gaps = std::move(tone_gaps[w]);
    return lenient_evidence;
}

// The final pass over plain chain `w` made lenient (lenient_chain.hpp) on what `found` measured on its
// plain path, its syllables placed in `result` and their evidence in `evidence`; `last_path` is
// the plain chain's path in the last round of re-estimation. `found`'s scores are given back.
void place_lenient_chain(const SentenceChain& plain_chain, std::size_t w, LenientEvidence& found,
                         const std::vector<StateSegment>& last_path, ViterbiWorkspace& workspace,
                         const Timeline& transcript, const FeatureTrack& track,
                         const LoudnessProfile& loudness, Timeline& result,
                         std::vector<SyllableEvidence>& evidence) {
    EmissionScores& chain_scores = found.scores;
    const std::vector<bool> is_heard_otherwise = heard_otherwise(found.held_out_gaps, found.tone_gaps);
    SentenceChain chain = lenient_chain(plain_chain, is_heard_otherwise);
    auto path = align_chain(chain, chain_scores, workspace, chain_scores.frame_count, transcript);
    // Each round forbids at least one more skip or generic stretch: it ends. Rival shares
    // are measured only for the syllables a path skips (50 small searches each).
    std::vector<double> rival_shares;
    for (;;) {
        add_rival_shares(chain, path, found.plain_frames, chain_scores, rival_shares);
        const auto skips = unsupported_skips(chain, path, found.plain_fits, rival_shares, found.held_out_gaps,
                                             is_heard_otherwise);
        const auto generic = short_generic(chain, path, found.plain_frames);
        if (skips.empty() && generic.empty()) break;
        forbid_skips(chain, skips);
        forbid_states(chain, generic);
        path = align_chain(chain, chain_scores, workspace, chain_scores.frame_count, transcript);
    }
    // The other searches whose starts weigh in (syllable_steadiness), as for a plain chain:
    // the lenient chain searched again with the sounds weighing less, and, where the path
    // takes the text whole (no mismatch), the same without the landmarks' bonus and the
    // last round's path of the plain chain, the same text on the models one round older.
    // Beside a mismatch the plain path is another reading of the speech (the text said
    // whole), not an opinion on the lenient one; and generic speech has no duration prior
    // of a syllable's, so without the landmarks its edges wander with the sounds light
    // and move the right syllables beside it (tests/speech/lenient_test.cpp: 里 after the
    // word the transcript lacks).
    std::vector<std::vector<SyllableFrames>> other_frames = {
        light_search(chain, chain_scores, workspace, kLenientLightSoundsWeight, true)};
    if (takes_text_whole(chain, path)) {
        other_frames.push_back(
            light_search(chain, chain_scores, workspace, kLenientLightSoundsWeight, false));
        other_frames.push_back(frames_on_path(plain_chain, last_path));
    }
    place_lenient(chain, w, path, other_frames, found.held_out_gaps, chain_scores, track, loudness, result,
                  evidence);
    // Its scores are not needed again: the memory goes back chain by chain.
    chain_scores = EmissionScores();
}

// Each syllable of `chain`'s start sureness and far start share on `path` (alignment_confidence.hpp),
// from the path search's `marginals`, into its `evidence`.
void set_start_evidence(const SentenceChain& chain, const std::vector<StateSegment>& path,
                        const EntryMaxMarginals& marginals, std::vector<SyllableEvidence>& evidence) {
    const std::vector<double> sureness = start_sureness(chain, path, marginals);
    const std::vector<double> far = far_start_share(chain, path, marginals);
    for (std::size_t local = 0; local < sureness.size(); ++local) {
        evidence[chain.syllable_indices[local]].sureness = sureness[local];
        evidence[chain.syllable_indices[local]].far_start = far[local];
    }
}

// Chain `w` placed in a room with its closures ringing (let_closures_ring), its syllables into
// `room_result` and their evidence into `room_evidence`: on `dry`'s features and models where the
// room's ringing was taken off (late_reverb.hpp), else on the recorded ones, whose scores of the
// chain `scores` holds. `last_path` is the placing models' last round's path of the plain chain.
void place_in_room(const SentenceChain& plain_chain, std::size_t w, DryRoom* dry,
                   const std::vector<StateSegment>& last_path, const FeatureTrack& placed_track,
                   const LoudnessProfile& loudness, const Timeline& transcript, EmissionScores& scores,
                   ViterbiWorkspace& workspace, EntryMaxMarginals& room_marginals, Timeline& room_result,
                   std::vector<SyllableEvidence>& room_evidence) {
    EmissionScores& room_scores = dry ? dry->scores : scores;
    if (dry) {
        observe(dry->track, loudness, plain_chain.searched, dry->observations);
        dry->learned.model.score(dry->observations.data(), plain_chain.searched.length(), room_scores);
    }
    SentenceChain ringing = plain_chain;
    let_closures_ring(ringing.states);
    const auto room_path =
        align_chain(ringing, room_scores, workspace, room_scores.frame_count, transcript, &room_marginals);
    const std::vector<std::vector<SyllableFrames>> room_other_frames = {
        light_search(ringing, room_scores, workspace, kLightSoundsWeight, true),
        light_search(ringing, room_scores, workspace, kLightSoundsWeight, false),
        frames_on_path(plain_chain, last_path)};
    place_syllables(ringing, w, room_path, room_other_frames, room_scores, placed_track, room_result,
                    room_evidence);
    set_start_evidence(ringing, room_path, room_marginals, room_evidence);
}

// The chains of `cut`'s sentences on `spans` (group_chains) in their search spans, their states set
// as align_chains' flags ask.
std::vector<SentenceChain> chains_to_align(const FeatureTrack& track, const LoudnessProfile& loudness,
                                           const Timeline& transcript, const SentenceCut& cut,
                                           const std::vector<FrameSpan>& spans, bool is_lenient,
                                           bool is_kept_to_marks, bool is_nasal_release_allowed) {
    std::vector<SentenceChain> chains = group_chains(transcript, cut, spans);
    set_search_spans(track, loudness, chains);
    // Lenient alignment's prices of a skipped syllable and of generic speech were set against the
    // duration priors at weight 1 (lenient_chain.cpp, bench/ lenient_bench.py): it keeps them so.
    if (is_lenient)
        for (auto& chain : chains)
            for (auto& state : chain.states) state.duration_weight = 1.0;
    if (is_kept_to_marks)
        for (auto& chain : chains) keep_pauses_to_marks(chain.states);
    if (is_nasal_release_allowed)
        for (auto& chain : chains) let_closures_after_nasals_be_skipped(chain.states);
    return chains;
}

// In a room whose ringing was measured (`room_ringing`), the recording without it (late_reverb.hpp)
// and models re-estimated on it, reported as the passes after the first re-estimation's of
// `passes`: the syllables given out are placed there, where a quiet onset after a vowel is no
// longer the vowel ringing on. Every check judges the recorded features: on the dry ones a wrong
// text fits its speech about as well as a right one (bench/README.md Sessions 24 and 25).
std::optional<DryRoom> dry_room(const FeatureTrack& track, const LoudnessProfile& loudness,
                                const Timeline& transcript, const std::vector<SentenceChain>& chains,
                                const std::optional<RoomRinging>& room_ringing, ProgressReporter& progress,
                                int passes) {
    if (!room_ringing) return std::nullopt;
    DryRoom dry;
    dry.track = without_late_ringing(track, *room_ringing);
    dry.learned = reestimate(dry.track, loudness, transcript, chains, progress, kReestimationRounds, passes);
    return dry;
}

// The final pass's scratch, reused chain by chain (a chain's observations and scores, the path
// search's tables and its start's marginals, as given out and in a room), and what it gathers of
// each syllable for its confidence (set_confidences): as given out and, in a room, as placed with
// the closures ringing.
struct FinalPass {
    FinalPass(std::size_t syllables, bool in_room)
        : evidence(syllables), room_evidence(in_room ? syllables : 0) {}
    std::vector<float> observations;
    EmissionScores scores;
    ViterbiWorkspace workspace;
    EntryMaxMarginals marginals, room_marginals;
    std::vector<SyllableEvidence> evidence, room_evidence;
};

// Chain `w`'s final pass on the re-estimated models `learned` (measure_chain, checked when
// `is_checked`): its syllables, sentences' spans and metrics into `aligned`, their evidence into
// `pass`, and its path into `checked_path` when the tones' witness reads it. In a room
// (aligned.room_result) the chain is also placed with its closures ringing (place_in_room), on
// `dry`'s features and models where the room's ringing was taken off, else on the recorded ones.
void align_final_chain(const SentenceChain& chain, std::size_t w, const FeatureTrack& track,
                       const LoudnessProfile& loudness, const Timeline& transcript,
                       const Reestimation& learned, DryRoom* dry, std::size_t spoken_sentences,
                       bool is_checked, FinalPass& pass, CutAlignment& aligned,
                       std::vector<StateSegment>* checked_path) {
    observe(track, loudness, chain.searched, pass.observations);
    learned.model.score(pass.observations.data(), chain.searched.length(), pass.scores);
    // In a room the syllables given out are those placed with the closures ringing, with their
    // confidences (align_cut): the confidences of this placement, which the checks read, are
    // read by nothing, and the searches that weigh them are left out (the start's marginals,
    // those with the sounds lighter: 6% of a room's instructions, bench/README.md Session 28).
    const bool is_given_out = !aligned.room_result;
    const auto path = align_chain(chain, pass.scores, pass.workspace, pass.scores.frame_count, transcript,
                                  is_given_out ? &pass.marginals : nullptr);
    aligned.has_long_unmarked_pause = aligned.has_long_unmarked_pause || has_long_unmarked_pause(chain, path);
    if (checked_path) *checked_path = path;
    // The last round's path, and the searches again with the sounds weighing less, with and
    // without the landmarks' bonus: where they start a syllable elsewhere, the sounds did not
    // hold it there.
    std::vector<std::vector<SyllableFrames>> other_frames;
    if (is_given_out)
        other_frames = {light_search(chain, pass.scores, pass.workspace, kLightSoundsWeight, true),
                        light_search(chain, pass.scores, pass.workspace, kLightSoundsWeight, false),
                        frames_on_path(chain, learned.last_paths[w])};
    // Before measure_chain, which leaves held-out models' scores in `scores`.
    if (aligned.room_result)
        place_in_room(chain, w, dry, (dry ? dry->learned : learned).last_paths[w], dry ? dry->track : track,
                      loudness, transcript, pass.scores, pass.workspace, pass.room_marginals,
                      *aligned.room_result, pass.room_evidence);
    measure_chain(chain, w, path, other_frames, pass.observations, learned, spoken_sentences,
                  forgiven_closure_run_on(learned, spoken_sentences, aligned.room_result.has_value()), track,
                  loudness, transcript, pass.scores, pass.workspace, aligned.result, pass.evidence,
                  aligned.spans, aligned.metrics, is_checked);
    if (is_given_out) set_start_evidence(chain, path, pass.marginals, pass.evidence);
}

// The syllables of every sentence of `cut`, aligned sentence by sentence (neighbours that run on,
// together), and, when `is_checked`, check_path on each path; when `is_lenient`, the final pass on
// lenient chains (lenient_chain.hpp). With `is_kept_to_marks`, keep_pauses_to_marks on every chain;
// with `is_nasal_release_allowed`, let_closures_after_nasals_be_skipped on every chain. In a room
// (is_room), each chain is also placed with its closures ringing (let_closures_ring) into
// `room_result`, on the features without the room's ringing (late_reverb.hpp) and models
// re-estimated on them.
CutAlignment align_chains(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                          const SentenceCut& cut, ProgressReporter& progress, bool is_checked, bool is_lenient,
                          bool is_kept_to_marks, bool is_nasal_release_allowed) {
    CutAlignment aligned;
    // Where sentences run together the cutter's spans are guesses: the syllables place them, and
    // the sentences' lengths are checked on where the syllables put them.
    aligned.spans = cut.spans;
    std::vector<SentenceChain> chains =
        chains_to_align(track, loudness, transcript, cut, aligned.spans, is_lenient, is_kept_to_marks,
                        is_nasal_release_allowed);
    const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
    const auto spoken_sentences = static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true));

    // Lenient alignment places its syllables on chains of its own (lenient_chain.hpp). The room is
    // read before the first re-estimation, so that the bar gives the second its own share.
    const bool in_room = !is_lenient && is_room(chains);
    const std::optional<RoomRinging> room_ringing =
        in_room ? measure_room_ringing(track, chains) : std::nullopt;
    const int passes = alignment_passes(room_ringing.has_value());
    const Reestimation learned = reestimate(track, loudness, transcript, chains, progress, 0, passes);
    aligned.result = transcript;
    aligned.result.duration_s = track.duration_s;
    if (in_room) aligned.room_result = aligned.result;
    std::optional<DryRoom> dry =
        dry_room(track, loudness, transcript, chains, room_ringing, progress, passes);
    aligned.metrics.assign(aligned.spans.size(), SentenceMetrics());
    FinalPass pass(transcript.syllables.size(), aligned.room_result.has_value());
    // The checks' paths of a room's chains, for the tones' witness.
    const bool is_tone_witnessed = aligned.room_result && is_checked &&
                                   spoken_sentences >= kMinToneWitnessSentences && !track.pitch.empty();
    std::vector<std::vector<StateSegment>> checked_paths(is_tone_witnessed ? chains.size() : 0);
    std::vector<LenientEvidence> lenient_evidence;
    if (is_lenient)
        lenient_evidence =
            measure_lenient_evidence(track, loudness, chains, learned, pass.observations, pass.workspace);
    for (std::size_t w = 0; w < chains.size(); ++w) {
        if (is_lenient)
            place_lenient_chain(chains[w], w, lenient_evidence[w], learned.last_paths[w], pass.workspace,
                                transcript, track, loudness, aligned.result, pass.evidence);
        else
            align_final_chain(chains[w], w, track, loudness, transcript, learned, dry ? &*dry : nullptr,
                              spoken_sentences, is_checked, pass, aligned,
                              is_tone_witnessed ? &checked_paths[w] : nullptr);
        report_pass(progress, passes - 1, passes, w, chains.size());
    }
    if (is_tone_witnessed) set_tone_gaps(chains, checked_paths, track, aligned.metrics);
    set_confidences(pass.evidence, is_lenient, aligned.result);
    if (aligned.room_result) set_confidences(pass.room_evidence, false, *aligned.room_result);
    return aligned;
}

// An alignment's syllables as the checks read them, on the silent closures' paths (`checked`), and,
// in a room, as they are given out, placed with the closures ringing (`in_room`, room_closures.hpp):
// the room's paths fit a wrong text as well as the right one, so that the confirmation of a cut
// (align_confirmed) and the block retry (align_track) read only the silent closures' placement.
struct AlignedTimelines {
    Timeline checked;
    std::optional<Timeline> in_room;
};

// The syllables of every sentence of `cut` (align_chains), and, when `is_checked`, the checks
// that audio and transcript belong together.
//
// A second pass keeps the text's pauses where it marks them: a sentence that slides a syllable or
// a phrase on gives the audio's pauses to the wrong places, a comma's to the pause between two
// sentences and that one to a pause inside a word (bench/ Session 12: 牛奶，吃 and 開車 of one
// passage, each placement scoring nearly alike, and re-estimation keeping the first pass's). Where
// an alignment gives a pause the text does not mark more than kMaxUnmarkedPauseFrames, it is made
// again with such pauses kept short, and whichever fits the audio better is kept (their sentences'
// text fit gaps): a speaker who did stop where the text marks nothing keeps that pause.
//
// A third pass lets a stop after a nasal release from the nasal's closure: a sentence whose text
// fits so poorly that check_text_fit would refuse it may be a right one whose path slipped a
// syllable where the speaker made no silence before a stop (天都, n + d: the tongue already closed
// for the n), and kept every later syllable on its successor's closure (bench/ Session 14; every
// such refusal of a person's right text since session 11). It is aligned again with the closure
// after a nasal skippable in every chain (the models learned on those paths too), and the new
// alignment kept if the poorly fitting sentences then fit their texts as well as free sounds do
// and, in a file of one or two sentences (whose models its own path shaped), within a right text's
// gap on models learned from the rest of the recording (fits_as_well_as_free_sounds,
// alignment_checks.hpp). Skippable everywhere and always, such closures lost held-out passages
// that are one slip from another place (sessions 11-13); here only an alignment the check would
// refuse is made again, and no other passage of any corpus moves.
AlignedTimelines align_cut(const FeatureTrack& track, const LoudnessProfile& loudness,
                           const Timeline& transcript, const SentenceCut& cut, ProgressReporter& progress,
                           bool is_checked, bool is_lenient) {
    const bool has_blocks = std::find(cut.runs_on.begin(), cut.runs_on.end(), true) != cut.runs_on.end();
    if (!has_blocks && is_checked) check_sentence_lengths(cut.spans, track, loudness, transcript);
    CutAlignment aligned = align_chains(track, loudness, transcript, cut, progress, is_checked, is_lenient, false, false);
    bool is_kept_to_marks = false;
    if (aligned.has_long_unmarked_pause) {
        try {
            CutAlignment kept = align_chains(track, loudness, transcript, cut, progress, is_checked, is_lenient, true, false);
            if (total_fit_gap(kept) < total_fit_gap(aligned)) {
                aligned = std::move(kept);
                is_kept_to_marks = true;
            }
        } catch (const AlignmentError&) {
            // No path keeps every pause the text does not mark short, or one a check refuses: the
            // first alignment stands.
        }
    }
    if (const auto poor = poorly_fitting(aligned.metrics); !poor.empty()) {
        try {
            CutAlignment released =
                align_chains(track, loudness, transcript, cut, progress, is_checked, is_lenient, is_kept_to_marks, true);
            if (fits_as_well_as_free_sounds(released.metrics, poor)) aligned = std::move(released);
        } catch (const AlignmentError&) {
            // A check refuses the new paths: the alignment before stands, for the checks to judge.
        }
    }
    const std::vector<FrameSpan>& spans = aligned.spans;
    const std::vector<SentenceMetrics>& metrics = aligned.metrics;
    Timeline& result = aligned.result;
    if (is_checked) {
        if (has_blocks) check_sentence_lengths(spans, track, loudness, transcript);
        try {
            check_text_fit(metrics, spans, transcript);
        } catch (const AlignmentError&) {
            const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
            if (aligned.room_result && track.pitch.empty() &&
                static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true)) >=
                    kMinToneWitnessSentences)
                throw ToneWitnessWanted();
            throw;
        }
        check_held_out_fit(metrics, spans, transcript, result.warnings);
        check_unspoken_tail(metrics, spans, transcript);
        check_own_fit(metrics, spans, transcript);
        check_syllable_lengths(metrics, spans, transcript);
        check_fit(metrics, spans, transcript);
        check_missing_text(result, track, loudness, result.warnings);
    }
    set_sentence_times(spans, result);
    AlignedTimelines timelines{std::move(result), std::nullopt};
    if (aligned.room_result) {
        Timeline in_room = timelines.checked;
        for (std::size_t i = 0; i < in_room.syllables.size(); ++i) {
            const Syllable& placed = aligned.room_result->syllables[i];
            Syllable& syllable = in_room.syllables[i];
            syllable.start_s = placed.start_s;
            syllable.final_start_s = placed.final_start_s;
            syllable.end_s = placed.end_s;
            syllable.confidence = placed.confidence;
        }
        set_sentence_times(spans, in_room);
        timelines.in_room = std::move(in_room);
    }
    return timelines;
}

// align_cut, where a sentence end that ran on keeps its chain only if the chain's syllables move
// it out of the pause the cutter chose and put that pause where the text has one (a comma's): a
// sentence end they leave in its pause confirms the cut, and one they move off a pause the text
// does not account for is a wrong text's doing. Then the sentences are aligned apart again, as
// the checks know them best.
AlignedTimelines align_confirmed(const FeatureTrack& track, const LoudnessProfile& loudness,
                                 const Timeline& transcript, const SentenceCut& cut,
                                 const std::vector<bool>& is_spoken, ProgressReporter& progress,
                                 bool is_checked, bool is_lenient) {
    AlignedTimelines aligned = align_cut(track, loudness, transcript, cut, progress, is_checked, is_lenient);
    SentenceCut confirmed = cut;
    for (const auto& [k, next] : spoken_neighbours(is_spoken)) {
        // Too few pauses: the cutter chose none for this end, and the chain is all there is.
        const bool has_cut_pause = cut.spans[k].end_frame <= cut.spans[next].first_frame;
        if (cut.runs_on[k] && has_cut_pause &&
            !(moves_sentence_end(cut, aligned.checked, k, next) &&
              is_cut_pause_in_text(cut, aligned.checked, k, next)))
            confirmed.runs_on[k] = false;
    }
    if (confirmed.runs_on == cut.runs_on) return aligned;
    return align_cut(track, loudness, transcript, confirmed, progress, is_checked, is_lenient);
}

// `given_spans` empty: the sentences cut as options.sentence_cut says; else where they say.
// `loudness` is the track's (conceal_dropouts).
Timeline align_track(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                     const AlignOptions& options, const std::vector<GivenSpan>& given_spans,
                     ProgressReporter& progress, bool is_checked) {
    if (loudness.speech_end_frame <= loudness.speech_first_frame)
        throw AlignmentError("no speech found in the " + format_fixed(track.duration_s, 2) +
                             " s of audio: nothing rises above its noise floor");
    const bool is_given = !given_spans.empty();
    const SentenceCut cut = is_given ? given_sentence_cut(track, loudness, transcript, given_spans)
                                     : cut_sentences(track, loudness, transcript, options);
    progress.report(kReadingShare + kCuttingShare, "sentences");
    const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
    const auto spoken_sentences = static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true));
    const std::size_t stretches = loudness.pauses.size() + 1;
    AlignedTimelines result;
    try {
        result = align_confirmed(track, loudness, transcript, cut, is_spoken, progress, is_checked, options.lenient);
    } catch (const AlignmentError& error) {
        // Fewer stretches of speech than sentences: either sentences run together or the
        // transcript has one the audio lacks; the first is tried, and the message tells of both.
        if (!is_given && options.sentence_cut == SentenceCutMode::automatic && stretches < spoken_sentences)
            throw AlignmentError("the transcript has " + std::to_string(spoken_sentences) +
                                 " spoken sentences but the audio has only " + std::to_string(stretches) +
                                 " stretches of speech between pauses, and run together they do not fit it either: " +
                                 error.what());
        // A sentence end cut at a pause inside a sentence (speech run together, whose only pauses
        // are a comma's) squeezes one sentence and stretches the next until a check refuses them.
        // Aligned as one block, the syllables find the ends; a transcript that does not match the
        // audio fails there too, and the first, sentence-by-sentence, account of it is kept. Where
        // the pauses do single the sentence ends out (and in the caller's own cut, Algorithm 3.1),
        // the cut stands and so does the refusal, as it does for given spans.
        if (!cut.is_in_doubt || block_count(cut, transcript) == 1) throw;
        SentenceCut block = cut;
        std::fill(block.runs_on.begin(), block.runs_on.end(), true);
        try {
            result = align_cut(track, loudness, transcript, block, progress, is_checked, options.lenient);
        } catch (const AlignmentError&) {
            throw error;
        }
        // Syllables that end every sentence in the pause it was cut at confirm the cut, and a
        // sentence end moved off a pause the text does not account for is a wrong text's doing:
        // either way it was the text, not the cut, that the checks refused.
        bool has_moved_end = false;
        for (const auto& [k, next] : spoken_neighbours(is_spoken)) {
            if (!moves_sentence_end(cut, result.checked, k, next)) continue;
            if (!is_cut_pause_in_text(cut, result.checked, k, next)) throw error;
            has_moved_end = true;
        }
        if (!has_moved_end) throw error;
    }
    // Noise a gain lifted before the first words, or a line among quieter voices, its text passed
    // on the speech the profile finds: its syllables placed after the noise or on the line alone,
    // where the checks pass it there too.
    if (!is_given && !options.lenient && options.sentence_cut == SentenceCutMode::automatic) {
        if (const auto lifted = loudness_after_lifted_lead_in(track, loudness)) {
            try {
                result = align_confirmed(track, *lifted, transcript,
                                         cut_sentences(track, *lifted, transcript, options), is_spoken,
                                         progress, is_checked, options.lenient);
            } catch (const AlignmentError&) {
                // Refused after the noise: the placement the checks passed stands.
            }
        } else if (const auto line = line_cut_among_voices(loudness, transcript, cut)) {
            try {
                result = align_cut(track, loudness, transcript, *line, progress, is_checked, options.lenient);
            } catch (const AlignmentError&) {
                // Refused on the line alone: the placement the checks passed stands.
            }
        }
    }
    return result.in_room ? std::move(*result.in_room) : std::move(result.checked);
}

// AlignOptions::check: refuse, as the checks find; warn, the alignment the checks refused made
// again without them, and their finding kept in its warnings; off, no checks at all. Lenient
// alignment reports what does not match in place of the checks.
Timeline align_checked(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                       const AlignOptions& options, const std::vector<GivenSpan>& given_spans,
                       ProgressReporter& progress) {
    if (options.lenient)
        return align_track(track, loudness, transcript, options, given_spans, progress, false);
    if (options.check != CheckMode::warn)
        return align_track(track, loudness, transcript, options, given_spans, progress,
                           options.check == CheckMode::refuse);
    try {
        return align_track(track, loudness, transcript, options, given_spans, progress, true);
    } catch (const AlignmentError& error) {
        Timeline result = align_track(track, loudness, transcript, options, given_spans, progress, false);
        result.warnings.push_back(std::string("the transcript may not match the audio (aligned anyway, check mode warn): ") +
                                  error.what());
        return result;
    }
}

// How much sound a damaged file must have lost before a refusal names the damage first: about a
// syllable. A refusal after a smaller loss (a damaged AAC packet, 20-60 ms) is the transcript's
// own, and the loss is said after it.
constexpr double kLostAudioNamedFirstS = 0.2;

// The aligner's refusal `error` with what the file's reader found: the sound it lost (`lost`, described;
// "" where none) named first where it is about a syllable or more (lost_s), after the refusal where it is
// less, and its `notes` (" (the file: ...)", or "") at the end.
AlignmentError refusal_of_file(const AlignmentError& error, const std::string& lost, double lost_s,
                               const std::string& notes) {
    if (lost.empty()) return AlignmentError(error.what() + notes);
    if (lost_s < kLostAudioNamedFirstS)
        return AlignmentError(std::string(error.what()) + " (the file is also damaged: " + lost + ")" + notes);
    return AlignmentError("the file is damaged: " + lost +
                          " (read as silence: the speech there is lost), and the rest cannot be aligned "
                          "without it; --lenient (AlignOptions::lenient) aligns what it can and reports "
                          "the rest. The aligner found: " + error.what() + notes);
}

// The transcript aligned with `track` (of `loudness`), read from `open` with its first
// `skipped_samples` of the analysis stream left out (align_checked); where a room's sentence is to
// be refused and its pitch may witness for its text (ToneWitnessWanted), the recording is read
// again with the pitch and aligned again.
Timeline align_witnessed(const std::function<std::unique_ptr<AudioSource>()>& open, FeatureTrack& track,
                         const LoudnessProfile& loudness, std::size_t skipped_samples,
                         const Timeline& transcript, const AlignOptions& options,
                         const std::vector<GivenSpan>& given_spans, ProgressReporter& progress) {
    try {
        return align_checked(track, loudness, transcript, options, given_spans, progress);
    } catch (const ToneWitnessWanted&) {
        std::unique_ptr<AudioSource> source = open();
        track = read_features(*source, progress, true, skipped_samples);
        const LoudnessProfile again = conceal_dropouts(track);
        return align_checked(track, again, transcript, options, given_spans, progress);
    }
}

// Where the other readings of a recording start, in samples of the analysis stream: a
// quarter of a frame later and a quarter earlier (three quarters later), the two phases nearest
// the first reading's on either side.
constexpr std::size_t kOtherPhaseSkips[] = {kHopSamples / 4, 3 * kHopSamples / 4};

// The times of a reading that left `skipped_s` of the recording out, in that reading's terms: the
// caller's sentence spans and first pause moved earlier by it.
std::vector<GivenSpan> spans_after_skip(std::vector<GivenSpan> spans, double skipped_s) {
    for (GivenSpan& span : spans) {
        span.start_s = std::max(0.0, span.start_s - skipped_s);
        span.end_s = std::max(span.start_s, span.end_s - skipped_s);
    }
    return spans;
}
AlignOptions options_after_skip(AlignOptions options, double skipped_s) {
    if (options.sentence_cut == SentenceCutMode::first_pause) {
        options.first_pause_start_s = std::max(0.0, options.first_pause_start_s - skipped_s);
        options.first_pause_end_s =
            std::max(options.first_pause_start_s + kFrameStepS, options.first_pause_end_s - skipped_s);
    }
    return options;
}

// Calls `change` on each time `timeline` holds: its sentences', syllables' (their finals' too) and
// mismatches' edges, and its duration.
template <typename Change>
void change_times(Timeline& timeline, const Change& change) {
    for (Sentence& sentence : timeline.sentences) {
        change(sentence.start_s);
        change(sentence.end_s);
    }
    for (Syllable& syllable : timeline.syllables) {
        change(syllable.start_s);
        change(syllable.end_s);
        if (syllable.final_start_s) change(*syllable.final_start_s);
    }
    for (TextMismatch& mismatch : timeline.mismatches) {
        change(mismatch.start_s);
        change(mismatch.end_s);
    }
    change(timeline.duration_s);
}

// A timeline found on a reading that left `skipped_s` of the recording out, moved onto the
// recording's times.
void move_onto_recording(Timeline& timeline, double skipped_s) {
    change_times(timeline, [skipped_s](double& time_s) { time_s += skipped_s; });
}

// A timeline's times to the microsecond, where hours of silence were left out before them: a frame's
// 60.57 s moved by 10740 s read 10800.570000000002, where the reading of the whole file gives 10800.57.
void round_to_microseconds(Timeline& timeline) {
    change_times(timeline, [](double& time_s) { time_s = rounded(time_s, 6); });
}

// Aligns the whole of the recording `open` gives. A file its reader found damaged (sound it could
// not decode, read as silence in its place: LostAudio) gets a warning naming where, and a refusal
// says first that the sound there is lost, for the text is not what is wrong. What else the reader
// says of how it read the file (AudioSource::notes: a stale WAV header) is a warning too, and
// closes a refusal. A warning begins with the source's name() (only a file loses sound); a refusal
// does not, its callers name the audio as they name it. A transcript the checks cannot weigh
// (latin_only_text.hpp) is aligned with a warning that says so (in every check mode but off: no
// evidence against a text is no reason to refuse it, and a game's "OK!" is such a text); a silent
// recording is refused after its samples alone are read (read_first_sound), with no features.
//
// The voice's pitch is measured as the audio is read only for lenient alignment; where a room's
// sentence is to be refused and its pitch may witness for its text (ToneWitnessWanted), the
// recording is read again, from `open`, with the pitch, and aligned again: that costs a second
// reading only there (the pitch costs 9% more instructions on every recording, bench/README.md
// Session 19). The second reading is work done again on the bar (ProgressReporter).
//
// A refusal is a majority of three phases. Where the samples fall against the 10 ms frames moves
// a check's figures by up to 0.2 per frame and a path by a syllable, so a text near a check's
// limit was refused at one phase and aligned at the next, right and wrong alike (bench/README.md
// Session 21). With check mode refuse, a recording is also read a quarter of a frame later and a
// quarter earlier (kOtherPhaseSkips), until two of the three readings agree: a file of one or two
// spoken sentences always, and a longer one only where the first reading refuses, for a passage
// read three times would take three times as long. A refusal gives the first refusing reading's
// message (the phase-shifted readings name times up to 7.5 ms early); an alignment gives the
// first reading's timeline, or, where that refused, the first other one that aligned, its times
// moved onto the recording's (its warnings' words keep that reading's); the other readings are work
// done again on the bar (ProgressReporter). Refusing only where two phases refuse, never where one
// aligns, would pick the kinder of two draws and let wrong texts through (Session 20).
Timeline align_source(const std::function<std::unique_ptr<AudioSource>()>& open, const Timeline& transcript,
                      const AlignOptions& options, const std::vector<GivenSpan>& given_spans,
                      const ProgressCallback& callback) {
    validate_transcript(transcript);
    const std::optional<std::string> unconfirmable = describe_latin_only_text(transcript);
    ProgressReporter progress(callback);
    progress.report(0.0, "reading");
    std::unique_ptr<AudioSource> source = open();
    const FirstSound first = read_first_sound(*source);
    const std::size_t silence_skipped = silence_to_skip(first, source->sample_rate_hz());
    const double silence_skipped_s = static_cast<double>(silence_skipped) / kAnalysisRateHz;
    if (first.held.empty()) {
        // The reading that is kept seeks past the silence this one read: it notes the samples
        // that are not numbers, and the stretches lost to damage, this one found there.
        std::unique_ptr<AudioSource> again = open();
        again->take_first_reading(*source);
        source = std::move(again);
    }
    FeatureTrack track = read_features(*source, progress, options.lenient, silence_skipped, first.held);
    const LoudnessProfile loudness = conceal_dropouts(track);
    const std::string lost = describe_lost_audio(source->lost_audio());
    std::string notes;
    for (const std::string& note : source->notes()) notes += " (the file: " + note + ")";
    Timeline result;
    try {
        const bool is_voted = options.check == CheckMode::refuse && !options.lenient;
        std::optional<AlignmentError> first_refusal;
        try {
            result = align_witnessed(open, track, loudness, silence_skipped, transcript,
                                     options_after_skip(options, silence_skipped_s),
                                     spans_after_skip(given_spans, silence_skipped_s), progress);
            move_onto_recording(result, silence_skipped_s);
        } catch (const AlignmentError& refusal) {
            if (!is_voted) throw;
            first_refusal = refusal;
        }
        const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
        const bool is_short = static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(),
                                                                  true)) <= kMaxHeldOutCheckSentences;
        if (is_voted && (first_refusal || is_short)) {
            std::size_t refusals = first_refusal ? 1 : 0;
            std::size_t alignments = first_refusal ? 0 : 1;
            std::optional<AlignmentError> other_refusal;
            std::optional<Timeline> other_alignment;
            for (const std::size_t phase_skipped : kOtherPhaseSkips) {
                if (refusals >= 2 || alignments >= 2) break;
                const std::size_t skipped = silence_skipped + phase_skipped;
                const double skipped_s = static_cast<double>(skipped) / kAnalysisRateHz;
                std::unique_ptr<AudioSource> again = open();
                FeatureTrack other = read_features(*again, progress, !track.pitch.empty(), skipped);
                const LoudnessProfile other_loudness = conceal_dropouts(other);
                try {
                    Timeline found = align_witnessed(open, other, other_loudness, skipped, transcript,
                                                     options_after_skip(options, skipped_s),
                                                     spans_after_skip(given_spans, skipped_s), progress);
                    ++alignments;
                    if (!other_alignment) {
                        move_onto_recording(found, skipped_s);
                        other_alignment = std::move(found);
                    }
                } catch (const AlignmentError& refusal) {
                    ++refusals;
                    if (!other_refusal) other_refusal = refusal;
                }
            }
            if (refusals >= 2) throw first_refusal ? *first_refusal : *other_refusal;
            if (first_refusal) result = std::move(*other_alignment);
        }
    } catch (const AlignmentError& error) {
        if (silence_skipped > 0)
            notes += " (its times count from " + format_fixed(silence_skipped_s, 3) +
                     " s: the digital silence before the recording's first sound was left out)";
        if (lost.empty() && notes.empty()) throw;
        throw refusal_of_file(error, lost, lost_seconds(source->lost_audio()), notes);
    }
    if (!lost.empty())
        result.warnings.push_back(source->name() + ": the file is damaged: " + lost +
                                  "; read as silence there, the syllables after it keep their times");
    for (const std::string& note : source->notes()) result.warnings.push_back(source->name() + ": " + note);
    if (unconfirmable && options.check != CheckMode::off)
        result.warnings.push_back("the transcript cannot be checked against the audio: " + *unconfirmable);
    if (silence_skipped > 0) round_to_microseconds(result);
    progress.report_done();
    return result;
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
    if (options.check != CheckMode::refuse && options.check != CheckMode::warn && options.check != CheckMode::off)
        throw InvalidArgument("check", "unknown mode " + std::to_string(static_cast<int>(options.check)));
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
    return align_source([&] { return open_audio_view(audio); }, transcript, impl_->options, {}, progress);
}

Timeline SpeechAligner::align_file(const std::string& audio_path, const Timeline& transcript,
                                   const ProgressCallback& progress) const {
    validate_transcript(transcript);
    std::unique_ptr<AudioSource> first = open_audio_file(audio_path);
    try {
        return align_source([&] { return first ? std::move(first) : open_audio_file(audio_path); },
                            transcript, impl_->options, {}, progress);
    } catch (const AlignmentError& error) {
        // Name the audio: the times in the message are in this file.
        throw AlignmentError(audio_path + ": " + error.what());
    }
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

Timeline align_in_given_spans(const std::string& audio_path, const Timeline& transcript,
                              const std::vector<GivenSpan>& sentence_spans_s, const AlignOptions& options,
                              const ProgressCallback& progress) {
    validate_transcript(transcript);
    std::unique_ptr<AudioSource> first = open_audio_file(audio_path);
    const std::string name = first->name();
    try {
        return align_source([&] { return first ? std::move(first) : open_audio_file(audio_path); },
                            transcript, options, sentence_spans_s, progress);
    } catch (const AlignmentError& error) {
        throw AlignmentError(name + ": " + error.what());
    }
}

}  // namespace talkface::detail
