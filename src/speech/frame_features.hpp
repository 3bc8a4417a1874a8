// Per-frame features of the speech (10 ms hop, 25 ms window at 16 kHz), computed while the audio
// streams in, so that samples are never all held: an hour is 360 000 frames of floats.
#ifndef TALKFACE_SPEECH_FRAME_FEATURES_HPP
#define TALKFACE_SPEECH_FRAME_FEATURES_HPP

#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "speech/dropout_finder.hpp"
#include "speech/pitch_track.hpp"

namespace talkface::detail {

class AudioSource;

constexpr int kAnalysisRateHz = 16000;
constexpr double kFramesPerSecond = 100.0;
constexpr double kFrameStepS = 1.0 / kFramesPerSecond;  // the double nearest 0.01, as the literal is
// Frame t's analysis window: the kWindowSamples samples of the kAnalysisRateHz stream from
// t * kHopSamples - kWindowLeadSamples on (zeros before the stream starts), centred on its 10 ms.
constexpr std::size_t kHopSamples = 160;
constexpr std::size_t kWindowSamples = 400;
constexpr std::size_t kWindowLeadSamples = (kWindowSamples - kHopSamples) / 2;
// Added to every power before its logarithm is taken, so that digital silence reads -100 dB (in
// the dB columns) rather than minus infinity.
constexpr double kFeatureEnergyFloor = 1e-10;
// The power a dB column's level stands for, to sum bands or frames and take the level again.
inline double db_to_power(double db) {
    return std::pow(10.0, db / 10.0);
}
// The level of a power, as the dB columns read it (kFeatureEnergyFloor added where a power may be 0).
inline double power_to_db(double power) {
    return 10.0 * std::log10(power);
}
// A frame whose level (any dB column: the whole band or part of it) is at most this holds no sound,
// only digital silence: exact zeros read -100 dB, while a frame of zeros but one sample of a single
// 16-bit step reads -66 dB (the whole band; -69 dB in held_music's 300-5000 Hz) where the window
// weighs it fully and -88 dB (-90 dB) at the window's ends, which weigh it 0.08. So this tells
// exact zeros, and float samples far below a 16-bit step, from any recorded sound. The sentence
// cutter measures levels over the frames above it; held_music judges their changes.
constexpr float kDigitalSilenceDb = -99.0f;

// When frame `frame` starts, as reported to the caller: divided rather than multiplied by
// kFrameStepS, since 357 * 0.01 is 3.5700000000000003 and 357 / 100.0 the double nearest 3.57,
// which a timeline's JSON then prints as 3.57.
constexpr double frame_time_s(std::size_t frame) { return static_cast<double>(frame) / kFramesPerSecond; }

// The edges of the bands the level columns measure (kEnergyDb, kLowBandDb, kMidBandDb,
// kHighBandDb): the whole band up to the analysis rate's Nyquist; the low band from under a man's
// lowest fundamental (85 Hz) through the first formant: voicing, nasals; the mid band up to where
// frication starts, the high band above it. Each band's edges are read at the FFT bins within them.
constexpr double kWholeBandLowHz = 60.0;
constexpr double kWholeBandHighHz = kAnalysisRateHz / 2.0;
constexpr double kLowBandLowHz = 80.0;
constexpr double kLowBandHighHz = 900.0;   // the mid band's low edge
constexpr double kMidBandHighHz = 2500.0;  // the high band's low edge

// The top of the band where a voice's fundamental lies (FeatureTrack::fundamental_share): a man's
// 85-180 Hz, a woman's 165-255 Hz, and the telephone band's lower edge.
constexpr double kFundamentalTopHz = 300.0;
// A recording whose FeatureTrack::fundamental_share is under this lacks the voice's fundamental (a
// telephone band): under 300 Hz lie 0.26-0.53 of the low band's power of the person's and the v-
// voices' recordings, 0.013-0.047 of the phone kinds' (bench/ p-*).
constexpr double kNarrowbandFundamentalShare = 0.1;

// The mel bands behind the cepstra, 100-7600 Hz (the cepstra keep kCepstrumCount of their DCT).
constexpr int kMelFilters = 24;
constexpr double kMelLowHz = 100.0;
constexpr double kMelHighHz = 7600.0;

// The edges of the mel bands, Hz: band m rises from edge m to its peak at edge m + 1 and falls to
// edge m + 2 (i in 0..kMelFilters + 1).
double mel_edge_hz(std::size_t i);

// The DCT's basis over the mel bands: cepstrum c is the sum over bands m of this times the band's log
// level (frame_features' cepstra; mel_cepstrum.hpp goes back to the bands with it).
double mel_cepstrum_cosine(std::size_t c, std::size_t m);

// Columns of a feature frame.
enum FeatureColumn : int {
    kCepstrum0 = 0,  // MFCC c0..c12
    kCepstrumCount = 13,
    kEnergyDb = kCepstrumCount,  // whole band (kWholeBandLowHz up), dB re full scale
    kLowBandDb,                  // kLowBandLowHz-kLowBandHighHz: voicing, nasals
    kMidBandDb,                  // kLowBandHighHz-kMidBandHighHz
    kHighBandDb,                 // kMidBandHighHz up: frication (up to 3400 Hz survives a telephone band)
    kPeakAmplitude,              // largest |sample| of the frame's 10 ms: Algorithm 3.1's "volume"
    kChangeBandDb,               // the band where a voice's changes are measured (changing_spectrum.hpp)
    kChangingDb,                 // the power in it that changes
    kLineShare,                  // the whole band's power share within kLineHalfBins of its strongest bin
    kLineBin,                    // that bin (31.25 Hz apart): where a steady tone lies (steady_tone.hpp)
    kZeroCrossings,              // the share of the window's neighbouring samples whose signs differ
    kFeatureCount,
};

// A sine's power, through the 25 ms Hamming window zero-padded to 512 points, lies within 2 bins
// of its strongest one (the window's main lobe): kLineShare is 1 for a steady tone.
constexpr std::size_t kLineHalfBins = 2;

// Frame t covers [t, t + 1) * kFrameStepS of the audio; its analysis window is centred there.
struct FeatureTrack {
    std::vector<float> values;  // frame-major, kFeatureCount per frame
    std::size_t frame_count = 0;
    double duration_s = 0.0;
    float peak_amplitude = 0.0f;  // of the whole input, before resampling
    // Per frame, the voice's pitch (pitch_track.hpp), where analyze_audio was asked for it; else empty.
    std::vector<PitchFrame> pitch;
    // Where the stream lost packets (dropout_finder.hpp), in order: conceal_dropouts' to draw over.
    std::vector<Dropout> dropouts;
    // The share of the low band's power (kLowBandDb's, summed over the whole recording)
    // under kFundamentalTopHz, where a voice's fundamental lies: a telephone band (300-3400 Hz) takes
    // it out (count_nuclei, alignment_checks.hpp). 1 where analyze_audio did not measure it.
    double fundamental_share = 1.0;

    float at(std::size_t frame, int column) const {
        return values[frame * kFeatureCount + static_cast<std::size_t>(column)];
    }
};

// Reads `source` to the end in blocks, resamples to kAnalysisRateHz and computes the features.
// `on_progress(fraction)` is called after each block (it may throw to cancel).
// \throws talkface::InvalidArgument naming the audio if it is silent; what the source throws.
// With `with_pitch`, FeatureTrack::pitch too. FeatureTrack::dropouts are found as the samples stream by.
// `skipped_samples` of the kAnalysisRateHz stream are left out first: the frames fall that much
// later against the recording (its times are then earlier by skipped_samples / kAnalysisRateHz).
// Where nothing was read first, the source skips most of them unread (silence_passed_by_seeking)
// if it can; else they are read and dropped.
// `read_first`: samples already read from `source` (read_first_sound's), taken before what it
// reads on.
FeatureTrack analyze_audio(AudioSource& source, const std::function<void(double)>& on_progress,
                           bool with_pitch = false, std::size_t skipped_samples = 0,
                           const std::vector<float>& read_first = {});

// What read_first_sound read of a recording up to its first sound.
struct FirstSound {
    // The samples read, for analyze_audio's `read_first`, where they are kMostHeldSilenceS or less
    // of the recording; else empty, and the caller reads the recording again from its start.
    std::vector<float> held;
    // The source's frames before the block that holds the first sound, all of them silent.
    std::size_t silent_frames = 0;
};

// Reads `source` up to its first block (as analyze_audio reads it) that holds a sample loud enough
// for speech, so that a silent recording is refused in the time it takes to read it, in one
// block's memory, without its features: a 10-hour silent WAV took 302 s and 496 MB to be refused
// (bench/README.md, Session 27), the features of its frames.
// \throws talkface::InvalidArgument naming the audio, as analyze_audio does, if it is silent.
FirstSound read_first_sound(AudioSource& source);

// The samples at kAnalysisRateHz, a whole number of frame hops, that a reading may leave out of
// the silence read_first_sound found before a recording's first sound: all of it but the last
// kMostHeldSilenceS, which the noise floor and the first pause are measured in. 10 hours of
// silence before a click were analysed whole (317 MB of features, minutes); 0 where it is held.
std::size_t silence_to_skip(const FirstSound& first, int sample_rate_hz);

// The silence read_first_sound holds for analyze_audio before it reads the recording again: a
// minute, 11 MB at 48 kHz.
constexpr double kMostHeldSilenceS = 60.0;

// Where analyze_audio, told to leave `skipped_samples` of the kAnalysisRateHz stream out, has the
// source skip_to() instead of reading and resampling them: `source_frames` of a source at
// `sample_rate_hz`, which are exactly `analysis_samples` of the stream (a whole number of the
// rates' common periods, so the frames keep their grid), kResamplerSettlingS before the skip's
// end, so that the resampler has settled on the silence by the first sample kept. {0, 0} where the
// skip is shorter than that.
struct SilencePassed {
    std::size_t source_frames = 0;
    std::size_t analysis_samples = 0;
};
SilencePassed silence_passed_by_seeking(std::size_t skipped_samples, int sample_rate_hz);

// The silence read and resampled before the first sample kept after a seek: libsamplerate's
// linear converter holds one sample of the past, and a second of the silence leaves it as a
// reading from the start leaves it, but for the silence's own level (under the silence bar).
constexpr double kResamplerSettlingS = 1.0;

}  // namespace talkface::detail

#endif
