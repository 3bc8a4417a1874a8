#include "speech/frame_features.hpp"

#include <samplerate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "audio/audio_source.hpp"
#include "common/internal_error.hpp"
#include "common/number_format.hpp"
#include "speech/changing_spectrum.hpp"
#include "speech/dropout_finder.hpp"
#include "speech/power_spectrum.hpp"
#include "speech/xorshift.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

constexpr std::size_t kBlockFrames = 8192;
constexpr double kMostReservedS = 3600.0;
constexpr std::size_t kFftSize = PowerSpectrum::kSize;
constexpr std::size_t kBins = PowerSpectrum::kBins;
// Below this peak (-80 dBFS) there is no speech to align, only dither or digital silence.
constexpr float kSilentPeak = 1e-4f;
// Dither (standard deviation: 0.3 of a 16-bit step, about -100 dBFS) added to every sample of the
// frame whose spectrum's shape (the cepstra) is taken, as a recording's own noise floor would be
// (Kaldi dithers the same way). Digital silence (a synthesizer's closures, speech joined by an
// editor, a codec's muted bands) otherwise gives frames of one constant cepstrum, which the silence
// class learns as a spike: a path that holds the faintest sound there loses to one that does not,
// and a right text is refused for the free sounds fitting it better (bench/ r-clean: 7 of 18
// passages). The band levels are taken of the frame as it is: dithered, they moved the floors the
// loudness profile measures, and a right short line padded with silence was refused (bench/
// short_lines_bench.py).
constexpr float kDitherStep = 0.3f / 32768.0f;
// A DC offset is followed with a time constant of 10 s (one frame's mean moves it by a
// thousandth): a recorder's offset holds for the whole recording, and speech's own slow swings
// (a voiced stretch's mean) move it little. It is removed from 0.02 of full scale up. A voice's
// own waveform is lopsided: espeak-ng's means 0.0006-0.0017 over a passage, more over its first
// block, and 0.016 over tests/data/speech/short_line.flac; taken off at 1e-3, it made
// two_sentences.wav's right text refused ("does not sound like its text"), though espeak-ng's
// corpus gained (median 9.1 -> 8.2 ms on clean). An offset of 0.1 aligned as well as none (bench/
// sweep); 0.3 did not.
constexpr float kOffsetStep = static_cast<float>(kHopSamples) / kAnalysisRateHz / 10.0f;
constexpr float kOffsetFloor = 0.02f;

// A clipped voice (a recorder's gain far too high, a phone held at the mouth): its loud frames lie
// at full scale, and their levels are the clip's, not the voice's: at +40 dB a passage's speech
// frames span 18 dB from the 5th to the 95th percentile of level, 36 dB unclipped, and the first
// pass's model (loudness, tilt, low band) told vowels from weak consonants by it. A frame with at
// least kClippedShareToRestore of its samples in runs of kClipRunSamples or more at kClipLevel
// has its band levels raised by the level a voice clipped at that share had
// (restored_gain_db). No voice of the corpora lies at kClipLevel for more than 67 of a window's
// 400 samples (speaker 3's loudest syllables), so none is touched.
constexpr float kClipLevel = 0.98f;
constexpr std::size_t kClipRunSamples = 3;
constexpr double kClippedShareToRestore = 0.25;
constexpr double kMostClippedShare = 0.98;  // where the gain stops growing (37 dB)

// The share of the window's samples that lie in runs of kClipRunSamples or more at kClipLevel.
double clipped_share(const float* samples) {
    // Nearly every frame has no sample at the clip: a count the compiler vectorizes tells it in a
    // tenth of the runs' scan.
    std::size_t at_clip = 0;
    for (std::size_t i = 0; i < kWindowSamples; ++i) at_clip += std::fabs(samples[i]) >= kClipLevel ? 1 : 0;
    if (at_clip < kClipRunSamples) return 0.0;
    std::size_t clipped = 0, run = 0;
    for (std::size_t i = 0; i <= kWindowSamples; ++i) {
        if (i < kWindowSamples && std::fabs(samples[i]) >= kClipLevel) {
            ++run;
            continue;
        }
        if (run >= kClipRunSamples) clipped += run;
        run = 0;
    }
    return static_cast<double>(clipped) / kWindowSamples;
}

// How much louder, in dB, a voice was than it reads once clipped with `share` of its samples at
// the clip. A voice's samples lie about as a Laplace distribution does (many near 0, a long tail):
// the clip lies c scales out where P(|x| > c) = exp(-c) = share, and the clipped power over the
// whole, E[min(x^2, c^2)] / E[x^2], is 1 - (1 + c) exp(-c).
double restored_gain_db(double share) {
    share = std::min(share, kMostClippedShare);
    const double clip = -std::log(share);
    return -10.0 * std::log10(1.0 - (1.0 + clip) * share);
}

double hz_to_mel(double hz) { return 2595.0 * std::log10(1.0 + hz / 700.0); }
double mel_to_hz(double mel) { return 700.0 * (std::pow(10.0, mel / 2595.0) - 1.0); }

// frame[i] = samples[i] * window[i] over kWindowSamples samples; restrict, so that the compiler, which
// could not tell the three apart, vectorizes it.
void apply_window(const float* __restrict samples, const float* __restrict window, float* __restrict frame) {
    for (std::size_t i = 0; i < kWindowSamples; ++i) frame[i] = samples[i] * window[i];
}

// A uniform draw in [-0.5, 0.5) from the top 24 bits of a xorshift64 state (`top24` = state >> 40):
// exact in float, whether converted from 64 or from 32 bits.
inline float centred_uniform(std::uint32_t top24) { return static_cast<float>(top24) * (1.0f / 16777216.0f) - 0.5f; }

// frame[i] = (samples[i] + dither_i) * window[i], dither_i = (u(first[i]) + u(second[i])) * scale:
// the same operations in the same order as one draw after another, on numbers drawn beforehand,
// so that the compiler vectorizes the float part (restrict, as apply_window).
void apply_dithered_window(const float* __restrict samples, const std::uint32_t* __restrict first,
                           const std::uint32_t* __restrict second, float scale, const float* __restrict window,
                           float* __restrict frame) {
    for (std::size_t i = 0; i < kWindowSamples; ++i)
        frame[i] = (samples[i] + (centred_uniform(first[i]) + centred_uniform(second[i])) * scale) * window[i];
}

// Two frames' draws are made at once (xorshift.hpp).
constexpr std::size_t kLanes = 2;

// From one frame's first dither state to the next frame's: 2 draws a sample. Made by the compiler.
constexpr XorshiftJump kDitherJump(2 * kWindowSamples);

// Streams 16 kHz samples into feature frames; frame t's window is centred on t * kHopSamples + kHopSamples / 2.
class FrameAnalyzer {
public:
    FrameAnalyzer(FeatureTrack& track, bool with_pitch) : track_(track), with_pitch_(with_pitch) {
        for (std::size_t i = 0; i < kWindowSamples; ++i)
            window_[i] = static_cast<float>(
                0.54 - 0.46 * std::cos(2.0 * M_PI * static_cast<double>(i) / (kWindowSamples - 1)));
        std::array<double, kMelFilters + 2> edges_bin{};
        for (std::size_t i = 0; i < edges_bin.size(); ++i)
            edges_bin[i] = mel_edge_hz(i) * kFftSize / kAnalysisRateHz;
        for (int m = 0; m < kMelFilters; ++m) {
            auto& weights = mel_weights_[static_cast<std::size_t>(m)];
            weights.fill(0.0f);
            const double left = edges_bin[static_cast<std::size_t>(m)];
            const double centre = edges_bin[static_cast<std::size_t>(m) + 1];
            const double right = edges_bin[static_cast<std::size_t>(m) + 2];
            for (std::size_t k = 0; k < kBins; ++k) {
                const double bin = static_cast<double>(k);
                double w = 0.0;
                if (bin > left && bin <= centre) w = (bin - left) / (centre - left);
                else if (bin > centre && bin < right) w = (right - bin) / (right - centre);
                weights[k] = static_cast<float>(w);
            }
            const auto m_index = static_cast<std::size_t>(m);
            mel_first_bin_[m_index] = static_cast<std::size_t>(std::max(0.0, std::floor(left)));
            mel_end_bin_[m_index] = std::min(kBins, static_cast<std::size_t>(std::ceil(right)) + 1);
        }
        for (int c = 0; c < kCepstrumCount; ++c)
            for (int m = 0; m < kMelFilters; ++m)
                dct_[static_cast<std::size_t>(c)][static_cast<std::size_t>(m)] = static_cast<float>(
                    mel_cepstrum_cosine(static_cast<std::size_t>(c), static_cast<std::size_t>(m)));
        // The first window reaches kWindowLeadSamples before time 0.
        pending_.assign(kWindowLeadSamples, 0.0f);
    }

    void push(const float* samples, std::size_t count) {
        if (samples_in_ == 0 && count > 0) {
            double sum = 0.0;
            for (std::size_t i = 0; i < count; ++i) sum += samples[i];
            offset_ = static_cast<float>(sum / static_cast<double>(count));
        }
        pending_.insert(pending_.end(), samples, samples + count);
        samples_in_ += count;
        std::size_t start = 0;
        while (pending_.size() - start >= kWindowSamples) {
            analyze_frame(&pending_[start]);
            start += kHopSamples;
        }
        pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(start));
    }

    // Pads with zeros so that every 10 ms of input has its frame.
    void finish() {
        const std::size_t wanted = (samples_in_ + kHopSamples - 1) / kHopSamples;
        while (track_.frame_count < wanted) {
            pending_.resize(std::max(pending_.size(), kWindowSamples), 0.0f);
            analyze_frame(pending_.data());
            pending_.erase(pending_.begin(), pending_.begin() + kHopSamples);
        }
        changing_.finish();
        if (low_band_power_ > 0.0) track_.fundamental_share = fundamental_power_ / low_band_power_;
    }

private:
    // Triangular noise (the sum of two uniform draws of xorshift64) of kDitherStep's standard
    // deviation: the same sequence on every run, cheap enough for every sample. Frame by frame, in
    // order, sample i takes draws 2i and 2i + 1 of its frame's 2 kWindowSamples. The steps of one sequence
    // follow each other, but a frame's first state is a fixed linear map of the frame before's
    // (kDitherJump), so two frames' draws are made at once, side by side (xorshift.hpp), and
    // apply_dithered_window() turns them into floats four at a time: the same numbers as one draw
    // after another, for 0.19 G instructions instead of 0.29 G in the 3 minutes (bench/README.md,
    // session 13).
    // This frame's draws: [0] the first of each sample's two, [1] the second.
    const std::array<std::array<std::uint32_t, kWindowSamples>, 2>& take_dither_draws() {
        if (next_lane_ == kLanes) {
            draw_two_frames();
            next_lane_ = 0;
        }
        return lane_draws_[next_lane_++];
    }

    void draw_two_frames() {
        dither_state_ = detail::draw_two_frames<FastXorshiftPair>(dither_state_, kDitherJump, lane_draws_);
    }
    // Each draw is uniform in [-0.5, 0.5) (variance 1/12); two of them have variance 1/6.
    static constexpr float kDitherScale = 2.449489743f * kDitherStep;  // sqrt(6)

    // The frame less the recording's DC offset, where it has one: a cheap recorder's offset is no
    // sound, but it leaks through the window into the lowest bands (the energy band starts at 60
    // Hz, inside the window's main lobe) and lifts every frame's peak, so that pauses read nearly
    // as loud as speech (bench/ sweep: an offset of 0.3 of full scale, a person's passage refused
    // as "does not sound like its text"). The offset is followed slowly (kOffsetStep),
    // from the mean of the first block, so that speech's own low notes are not taken for it, as
    // they are by a frame's own mean (Kaldi's remove_dc_offset: a sung passage of bench/'s m-sung
    // was refused with it). Below kOffsetFloor it is left alone, and the features are the
    // samples' own, bit for bit.
    const float* without_offset(const float* samples) {
        float sum = 0.0f;
        for (std::size_t i = 0; i < kWindowSamples; ++i) sum += samples[i];
        offset_ += kOffsetStep * (sum / static_cast<float>(kWindowSamples) - offset_);
        if (std::fabs(offset_) < kOffsetFloor) return samples;
        // A frame of one value throughout is digital silence, whatever the value: it stays silent.
        const bool is_constant = std::all_of(samples, samples + kWindowSamples, [&](float v) { return v == samples[0]; });
        for (std::size_t i = 0; i < kWindowSamples; ++i) centred_[i] = is_constant ? 0.0f : samples[i] - offset_;
        return centred_.data();
    }

    void analyze_frame(const float* raw_samples) {
        const float* samples = without_offset(raw_samples);
        const std::size_t hop_start = kWindowLeadSamples;
        float peak = 0.0f;
        for (std::size_t i = hop_start; i < hop_start + kHopSamples; ++i) peak = std::max(peak, std::fabs(samples[i]));
        // frame_ past kWindowSamples stays zero: the window zero-padded to the FFT's size.
        apply_window(samples, window_.data(), frame_.data());
        spectrum_.compute(frame_.data(), power_.data());
        // The spectrum's shape (the cepstra) is taken of the dithered frame; its levels (the bands
        // the loudness profile and the checks read) of the frame as it is.
        const auto& draws = take_dither_draws();
        apply_dithered_window(samples, draws[0].data(), draws[1].data(), kDitherScale, window_.data(), frame_.data());
        spectrum_.compute(frame_.data(), dithered_power_.data());

        auto band_power = [&](double low_hz, double high_hz) {
            const auto first = static_cast<std::size_t>(std::ceil(low_hz * kFftSize / kAnalysisRateHz));
            const auto last = std::min(kBins - 1, static_cast<std::size_t>(high_hz * kFftSize / kAnalysisRateHz));
            double sum = 0.0;
            for (std::size_t k = first; k <= last; ++k) sum += power_[k];
            return sum;
        };
        auto power_db = [](double power) {
            return static_cast<float>(power_to_db(power + kFeatureEnergyFloor));
        };
        auto band_db = [&](double low_hz, double high_hz) { return power_db(band_power(low_hz, high_hz)); };
        const double low_band_power = band_power(kLowBandLowHz, kLowBandHighHz);
        fundamental_power_ += band_power(kLowBandLowHz, kFundamentalTopHz);
        low_band_power_ += low_band_power;
        std::array<float, kFeatureCount> row{};
        std::array<float, kMelFilters> log_mel{};
        for (std::size_t m = 0; m < kMelFilters; ++m) {
            double sum = 0.0;
            for (std::size_t k = mel_first_bin_[m]; k < mel_end_bin_[m]; ++k)
                sum += static_cast<double>(mel_weights_[m][k]) * dithered_power_[k];
            log_mel[m] = static_cast<float>(std::log(sum + kFeatureEnergyFloor));
        }
        for (std::size_t c = 0; c < kCepstrumCount; ++c) {
            float sum = 0.0f;
            for (std::size_t m = 0; m < kMelFilters; ++m) sum += dct_[c][m] * log_mel[m];
            row[c] = sum;
        }
        const double whole_band_power = band_power(kWholeBandLowHz, kWholeBandHighHz);
        row[kEnergyDb] = power_db(whole_band_power);
        row[kLowBandDb] = power_db(low_band_power);
        row[kMidBandDb] = band_db(kLowBandHighHz, kMidBandHighHz);
        row[kHighBandDb] = band_db(kMidBandHighHz, kWholeBandHighHz);
        row[kPeakAmplitude] = peak;
        if (const double share = clipped_share(samples); share >= kClippedShareToRestore) {
            const auto gain_db = static_cast<float>(restored_gain_db(share));
            for (const int column : {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb}) row[column] += gain_db;
        }
        set_line(whole_band_power, row);
        row[kZeroCrossings] = zero_crossing_share(samples);
        track_.values.insert(track_.values.end(), row.begin(), row.end());
        ++track_.frame_count;
        changing_.push(power_.data());
        if (with_pitch_) {
            // Each frame's window ends a hop after the one before's: its last hop is new.
            const bool is_first = track_.pitch.empty();
            track_.pitch.push_back(pitch_.push(is_first ? samples : samples + kWindowSamples - kHopSamples, is_first ? kWindowSamples : kHopSamples));
        }
    }

    // A voice's voiced sound puts its power in the low harmonics and crosses zero a few times a
    // period; a noise spread over the band crosses it far more often (the voicing a quiet end
    // is told from a coder's comfort noise by, sentence_chains.cpp).
    static float zero_crossing_share(const float* samples) {
        std::size_t crossings = 0;
        for (std::size_t i = 1; i < kWindowSamples; ++i)
            crossings += (samples[i] < 0.0f) != (samples[i - 1] < 0.0f);
        return static_cast<float>(crossings) / static_cast<float>(kWindowSamples - 1);
    }

    // kLineShare and kLineBin of the frame's power (not dithered), over the whole band, as kEnergyDb;
    // `band` is that band's power, which kEnergyDb summed (the same bins in the same order).
    void set_line(double band, std::array<float, kFeatureCount>& row) const {
        constexpr auto first = static_cast<std::size_t>(
            (static_cast<std::size_t>(kWholeBandLowHz) * kFftSize + kAnalysisRateHz - 1) / kAnalysisRateHz);
        constexpr std::size_t last = kBins - 1;
        std::size_t strongest = first;
        for (std::size_t k = first; k <= last; ++k)
            if (power_[k] > power_[strongest]) strongest = k;
        double line = 0.0;
        for (std::size_t k = std::max(first, strongest - std::min(strongest, kLineHalfBins)); k <= std::min(last, strongest + kLineHalfBins); ++k)
            line += power_[k];
        row[kLineShare] = band > 0.0 ? static_cast<float>(line / band) : 0.0f;
        row[kLineBin] = static_cast<float>(strongest);
    }

    FeatureTrack& track_;
    bool with_pitch_ = false;
    PitchTracker pitch_;
    ChangingSpectrum changing_{track_};
    std::uint64_t dither_state_ = 0x9E3779B97F4A7C15ull;
    std::array<std::array<std::array<std::uint32_t, kWindowSamples>, 2>, kLanes> lane_draws_{};  // two frames' draws
    std::size_t next_lane_ = kLanes;  // the lane the next frame takes; kLanes: none drawn yet
    std::vector<float> pending_;
    std::size_t samples_in_ = 0;
    double fundamental_power_ = 0.0;  // FeatureTrack::fundamental_share's, summed over the frames so far
    double low_band_power_ = 0.0;
    std::array<float, kWindowSamples> window_{};
    float offset_ = 0.0f;                   // the recording's DC offset as followed so far
    std::array<float, kWindowSamples> centred_{};  // a frame less the offset
    std::array<float, kFftSize> frame_{};
    PowerSpectrum spectrum_;
    std::array<float, kBins> power_{};
    std::array<float, kBins> dithered_power_{};
    std::array<std::array<float, kBins>, kMelFilters> mel_weights_{};
    std::array<std::size_t, kMelFilters> mel_first_bin_{};  // each filter's non-zero bins
    std::array<std::size_t, kMelFilters> mel_end_bin_{};
    std::array<std::array<float, kMelFilters>, kCepstrumCount> dct_{};
};

// Streaming sample-rate conversion to kAnalysisRateHz. libsamplerate's linear converter: the
// features are band energies over 25 ms, which its weak anti-aliasing does not move (bench/:
// stereo 44.1 kHz and 8 kHz telephone align as well as with the fastest sinc), at twice the speed
// the 500x real-time target needs.
class Resampler {
public:
    explicit Resampler(int input_rate_hz) : ratio_(static_cast<double>(kAnalysisRateHz) / input_rate_hz) {
        if (input_rate_hz == kAnalysisRateHz) return;
        int error = 0;
        state_ = src_new(SRC_LINEAR, 1, &error);
        if (state_ == nullptr) throw Error(ErrorCode::out_of_memory, std::string("libsamplerate: ") + src_strerror(error));
    }
    ~Resampler() {
        if (state_ != nullptr) src_delete(state_);
    }
    Resampler(const Resampler&) = delete;
    Resampler& operator=(const Resampler&) = delete;

    template <typename Sink>
    void process(const float* input, std::size_t count, bool is_last, Sink&& sink) {
        if (state_ == nullptr) {
            sink(input, count);
            return;
        }
        output_.resize(static_cast<std::size_t>(static_cast<double>(count) * ratio_) + 256);
        SRC_DATA data{};
        data.data_in = input;
        data.input_frames = static_cast<long>(count);
        data.src_ratio = ratio_;
        data.end_of_input = is_last ? 1 : 0;
        do {
            data.data_out = output_.data();
            data.output_frames = static_cast<long>(output_.size());
            if (const int error = src_process(state_, &data); error != 0)
                throw detail::internal_error(std::string("libsamplerate: ") + src_strerror(error));
            sink(output_.data(), static_cast<std::size_t>(data.output_frames_gen));
            data.data_in += data.input_frames_used;
            data.input_frames -= data.input_frames_used;
        } while (data.input_frames > 0 || (is_last && data.output_frames_gen > 0));
    }

private:
    double ratio_;
    SRC_STATE* state_ = nullptr;
    std::vector<float> output_;
};

}  // namespace

double mel_edge_hz(std::size_t i) {
    const double low_mel = hz_to_mel(kMelLowHz);
    const double high_mel = hz_to_mel(kMelHighHz);
    return mel_to_hz(low_mel + (high_mel - low_mel) * static_cast<double>(i) / (kMelFilters + 1));
}

double mel_cepstrum_cosine(std::size_t c, std::size_t m) {
    return std::cos(M_PI * static_cast<double>(c) * (static_cast<double>(m) + 0.5) / kMelFilters);
}

namespace {

// "silent: the loudest sample of its 36000 s is all zero; there is no speech to align", and what the
// source noted of its reading: samples that are not numbers, read as 0, leave a float file silent.
InvalidArgument silent_recording(const AudioSource& source, double duration_s, float peak) {
    const std::string level = peak > 0.0f ? format_fixed(20.0 * std::log10(peak), 1) + " dBFS" : "all zero";
    std::string message = "silent: the loudest sample of its " + format_fixed(duration_s, 3) + " s is " +
                          level + "; there is no speech to align";
    for (const std::string& note : source.notes()) message += " (the file: " + note + ")";
    return InvalidArgument(source.name(), message);
}

}  // namespace

FirstSound read_first_sound(AudioSource& source) {
    const auto most_held = static_cast<std::size_t>(kMostHeldSilenceS * source.sample_rate_hz());
    FirstSound first;
    std::vector<float> block(kBlockFrames);
    std::size_t frames_read = 0;
    float peak = 0.0f;
    bool is_held = true;
    for (;;) {
        const std::size_t count = source.read(block.data(), block.size());
        if (count == 0) break;
        first.silent_frames = frames_read;
        frames_read += count;
        const float block_peak =
            *std::max_element(block.begin(), block.begin() + static_cast<std::ptrdiff_t>(count),
                              [](float a, float b) { return std::fabs(a) < std::fabs(b); });
        peak = std::max(peak, std::fabs(block_peak));
        is_held = is_held && frames_read <= most_held;
        if (is_held)
            first.held.insert(first.held.end(), block.begin(),
                              block.begin() + static_cast<std::ptrdiff_t>(count));
        if (peak >= kSilentPeak) {
            if (!is_held) first.held.clear();
            return first;
        }
    }
    if (frames_read == 0) throw InvalidArgument(source.name(), "empty audio: no frames");
    throw silent_recording(source, static_cast<double>(frames_read) / source.sample_rate_hz(), peak);
}

std::size_t silence_to_skip(const FirstSound& first, int sample_rate_hz) {
    const double skipped_s = static_cast<double>(first.silent_frames) / sample_rate_hz - kMostHeldSilenceS;
    if (!first.held.empty() || skipped_s <= 0.0) return 0;
    return static_cast<std::size_t>(skipped_s * kAnalysisRateHz / kHopSamples) * kHopSamples;
}

SilencePassed silence_passed_by_seeking(std::size_t skipped_samples, int sample_rate_hz) {
    const auto rate_hz = static_cast<std::size_t>(sample_rate_hz);
    const std::size_t common = std::gcd(rate_hz, static_cast<std::size_t>(kAnalysisRateHz));
    const std::size_t step_frames = rate_hz / common;
    const std::size_t step_samples = kAnalysisRateHz / common;
    const auto margin_samples = static_cast<std::size_t>(kResamplerSettlingS * kAnalysisRateHz);
    if (skipped_samples <= margin_samples) return {};
    const std::size_t steps = (skipped_samples - margin_samples) / step_samples;
    return {steps * step_frames, steps * step_samples};
}

FeatureTrack analyze_audio(AudioSource& source, const std::function<void(double)>& on_progress,
                           bool with_pitch, std::size_t skipped_samples,
                           const std::vector<float>& read_first) {
    FeatureTrack track;
    // Room for the frames the source says it has, up to an hour's: a damaged header may promise
    // years (a FLAC's sample count, an MP3's frame count), and reserving them threw bad_alloc.
    const double promised_s = std::min(static_cast<double>(source.frame_count()) / source.sample_rate_hz(), kMostReservedS);
    track.values.reserve(static_cast<std::size_t>(promised_s / kFrameStepS + 2) * kFeatureCount);
    FrameAnalyzer analyzer(track, with_pitch);
    Resampler resampler(source.sample_rate_hz());
    std::vector<float> block(kBlockFrames);
    std::size_t frames_read = 0;
    float peak = 0.0f;
    DropoutFinder dropouts;
    std::size_t left_to_skip = skipped_samples;
    if (read_first.empty()) {
        const SilencePassed passed = silence_passed_by_seeking(skipped_samples, source.sample_rate_hz());
        if (passed.source_frames > 0 && source.skip_to(passed.source_frames)) {
            frames_read = passed.source_frames;
            left_to_skip -= passed.analysis_samples;
        }
    }
    auto sink = [&](const float* samples, std::size_t count) {
        const std::size_t skipped = std::min(left_to_skip, count);
        left_to_skip -= skipped;
        samples += skipped;
        count -= skipped;
        if (count == 0) return;
        analyzer.push(samples, count);
        dropouts.push(samples, count);
    };
    // What read_first_sound read goes in the blocks it was read in, so that the resampler and the
    // frames see what they would have seen.
    for (std::size_t at = 0; at < read_first.size(); at += kBlockFrames) {
        const std::size_t count = std::min(kBlockFrames, read_first.size() - at);
        for (std::size_t i = 0; i < count; ++i) peak = std::max(peak, std::fabs(read_first[at + i]));
        frames_read += count;
        resampler.process(read_first.data() + at, count, false, sink);
    }
    for (;;) {
        const std::size_t count = source.read(block.data(), block.size());
        for (std::size_t i = 0; i < count; ++i) peak = std::max(peak, std::fabs(block[i]));
        frames_read += count;
        resampler.process(block.data(), count, count == 0, sink);
        if (count == 0) break;
        if (on_progress)
            on_progress(std::min(1.0, static_cast<double>(frames_read) / static_cast<double>(source.frame_count())));
    }
    analyzer.finish();
    track.dropouts = outside_codec_pauses(dropouts.finish(), source.codec_pauses(), kAnalysisRateHz);
    track.peak_amplitude = peak;
    track.duration_s = std::max(0.0, static_cast<double>(frames_read) / source.sample_rate_hz() -
                                         static_cast<double>(skipped_samples) / kAnalysisRateHz);
    if (frames_read == 0) throw InvalidArgument(source.name(), "empty audio: no frames");
    if (!(peak >= kSilentPeak)) throw silent_recording(source, track.duration_s, peak);
    return track;
}

}  // namespace talkface::detail
