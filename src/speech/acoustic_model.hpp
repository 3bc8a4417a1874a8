// Emission models of the phone classes (SPEC "Alignment": knowledge starts it, the utterance
// finishes it): hand-set Gaussians on three noise-adjusted features for the first pass, then
// per-class diagonal Gaussians on MFCC and deltas re-estimated on the recording itself.
#ifndef TALKFACE_SPEECH_ACOUSTIC_MODEL_HPP
#define TALKFACE_SPEECH_ACOUSTIC_MODEL_HPP

#include <array>
#include <cstddef>
#include <vector>

#include "speech/frame_features.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// Columns of an observation.
enum ObservationColumn : int {
    kCepstrum1 = 0,           // MFCC c1..c12 (c0 duplicates the loudness)
    kLoudness = 12,           // energy above the noise floor / the sentence's speech level
    kTilt = 13,               // (high band - low band), each above its floor, / speech level
    kLowBand = 14,            // low band above its floor / the sentence's low-band level
    kDeltaCepstrum1 = 15,     // deltas of c1..c12
    kDeltaLoudness = 27,
    kObservationCount = 28,
};

// Observations of frames [span.first_frame, span.end_frame), frame-major, into `observations`
// (its capacity is reused from sentence to sentence).
void observe(const FeatureTrack& track, const LoudnessProfile& loudness, const FrameSpan& span,
             std::vector<float>& observations);

// Acoustic scale of the re-estimated 28-dimensional model against the duration priors: its
// log-likelihoods are ~10 times those of the three-feature model for the same evidence.
constexpr double kReestimatedWeight = 0.2;

class AcousticModel {
public:
    // The first pass's model: hand-set Gaussians on loudness, tilt and low band only.
    static AcousticModel hand_set();

    // Scores `frame_count` frames of observations (kObservationCount floats a frame) from
    // `observations` on: a stretch of a longer track is scored where it lies, not copied.
    void score(const float* observations, std::size_t frame_count, EmissionScores& scores) const;

private:
    std::vector<int> columns_;  // which observation columns the model uses
    std::vector<double> mean_;  // class-major, columns_.size() per class
    std::vector<double> inverse_variance_;
    std::array<double, kPhoneClassCount> log_norm_{};
    double weight_ = 1.0;       // acoustic scale against the duration priors
    friend class ModelEstimator;
};

// Sums of the frames Viterbi gave each class, over every sentence of a pass.
class ModelEstimator {
public:
    ModelEstimator();
    void add(const std::vector<float>& observations, const std::vector<PhoneState>& states,
             const std::vector<StateSegment>& path);
    // Takes out what `part` added (its frames were added here too).
    void subtract(const ModelEstimator& part);
    // Diagonal Gaussians on all columns; a class with few frames leans on its broad group
    // (silence, obstruents, sonorants), and a class never seen takes the group's.
    AcousticModel estimate(double weight) const;

private:
    std::array<double, kPhoneClassCount> count_{};
    std::vector<double> sum_;
    std::vector<double> sum_squares_;
};

}  // namespace talkface::detail

#endif
