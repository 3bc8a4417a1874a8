// Damage that a PCM recording's samples show where its format holds no check (issue 13, "Bad
// input"): a WAV has no checksum, so a copy or a disk that changes its bytes leaves a file every
// reader opens and plays. Two damages leave marks no voice or microphone makes, and are told here:
// a changed high byte moves one sample far off the wave around it (a click one sample wide), and a
// block of bytes zeroed cuts the sound to exact digital zeros mid-wave, inside the sound (as an
// editor's silence over a word does, on purpose: the samples cannot tell them apart). Lossy and
// lossless codecs (FLAC, Ogg, MP3, AAC) check their frames or packets, and their readers say so.
#ifndef TALKFACE_AUDIO_PCM_DAMAGE_HPP
#define TALKFACE_AUDIO_PCM_DAMAGE_HPP

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace talkface::detail {

// A stretch of samples [first_frame, end_frame) the finder judged damaged.
struct DamagedSamples {
    std::size_t first_frame = 0;
    std::size_t end_frame = 0;
};

// A sample is a click when it lies kClickLeast (of full scale) or more off the line between its two
// neighbours, and kClickOverLocal times farther than any other sample within kLocalSeconds either
// side of it (its neighbours left out: a spike moves them half its own distance). Nothing a
// microphone hears stands so alone: a voice rings over several samples at each glottal pulse
// (espeak-ng's next-but-one samples as far off), a click is a burst of a few milliseconds (the short
// kinds' synthesized clicks: up to 8.4 times), a phone codec's transients up to 5.1 times (every
// corpus, bench/README.md session 34). A byte changed high in a 16-bit sample moves that sample
// alone, by 0.1 of full scale or more unless only its 4 lowest bits changed: 26 to 10^8 times
// farther than its surroundings in the person's recording of the sweep, but as little as 2 times
// in a loud voice's ringing, where it is not told. A run of exact zeros
// of kShortestZerosSeconds or more is cut into the sound when, on each side, the loudest of the
// kCutSeconds next to it reaches kCutShare of the loudest of the kSideSeconds next to it, and on one
// side kCleanCutShare (a fade to a pause reaches a few hundredths there, dropout_finder.hpp), and
// the loudest of each side reaches kSideShareOfPeak of the recording's loudest sample (-20 dB): a
// voice sounds on both sides. A music bed's drum whose tail is cut to zeros before its next stroke
// (the intro set's drums: 0.03-0.05 of their recording's peak before the zeros), a gate that shuts
// on a noise floor, lie lower; a block zeroed inside the person's speech of the sweep lies at 0.21.
// A run the sound ramps down into is no cut: the sample before it under kCutShare of its side's
// loudest, the one before that kRampSteepness times as far from zero or more (the line through the
// two meets zero within about a sample), and those before rising steadily away on the same side of
// zero for kRampSeconds, as espeak-ng ends a sound before each of its pauses (over about 0.45 ms at
// its 22.05 kHz, then starting the next sound abruptly; 36 of 144 of its files held such runs,
// bench/README.md session 45). A block zeroed where the wave happened to be falling to zero looks
// the same (1 of 37 blocks found in the person's speech), and is not told; the side after the zeros
// is not read so, where a wave rising from a crossing is as common and a synthesizer's sound starts
// abruptly.
constexpr float kClickLeast = 0.1f;
constexpr float kClickOverLocal = 10.0f;
constexpr double kLocalSeconds = 0.01;
constexpr double kShortestZerosSeconds = 0.005;
constexpr double kCutSeconds = 0.00025;
constexpr double kSideSeconds = 0.02;
constexpr float kCutShare = 0.05f;
constexpr float kCleanCutShare = 0.1f;
constexpr float kSideShareOfPeak = 0.1f;
constexpr double kRampSeconds = 0.0002;
constexpr float kRampSteepness = 1.8f;

// Finds clicks and cut zeros in a mono PCM stream as it is pushed, holding only the last
// 2 kSideSeconds of it. Samples within kSideSeconds of the stream's end are judged on what there is.
class PcmDamageFinder {
public:
    explicit PcmDamageFinder(int sample_rate_hz);
    void push(const float* mono, std::size_t count);
    // The stream goes on at `frame` (a seek): what lies between is not judged.
    void restart_at(std::size_t frame);
    // Judges what is left; then clicks() and cut_zeros() are whole.
    void finish();
    const std::vector<DamagedSamples>& clicks() const { return clicks_; }
    const std::vector<DamagedSamples>& cut_zeros() const { return cut_zeros_; }

private:
    void judge_up_to(std::size_t end_frame);
    bool is_click(std::size_t frame) const;
    void judge_zeros(std::size_t first_frame, std::size_t end_frame);
    float sample(std::size_t frame) const { return buffer_[frame - base_frame_]; }
    float loudest(std::size_t from_frame, std::size_t to_frame) const;
    // Whether the sound before a run of zeros starting at `first_zero` ramps down into it (see
    // kRampSeconds), against the loudest of that side.
    bool ramps_down_to(std::size_t first_zero, float side_loudest) const;

    std::size_t local_;
    std::size_t shortest_zeros_;
    std::size_t cut_;
    std::size_t side_;
    std::size_t ramp_;
    std::vector<float> buffer_;  // frames [base_frame_, base_frame_ + buffer_.size())
    std::size_t base_frame_ = 0;
    std::size_t next_frame_ = 0;  // the first frame not yet judged
    std::size_t zeros_first_ = 0;
    std::size_t zeros_length_ = 0;
    // The loudest of the side and of the cut before the run of zeros, taken as it reaches
    // shortest_zeros_: a long run outlasts what the buffer keeps.
    float zeros_before_side_ = 0.0f;
    float zeros_before_cut_ = 0.0f;
    bool zeros_before_ramps_ = false;
    // Runs cut on both sides and the quieter of their sides, judged against the recording's loudest
    // sample (peak_) once it is known, at the end.
    std::vector<std::pair<DamagedSamples, float>> cut_runs_;
    float peak_ = 0.0f;
    std::vector<DamagedSamples> clicks_;
    std::vector<DamagedSamples> cut_zeros_;
};

// The notes a reading gives of what `finder` found in a stream at `sample_rate_hz` (none, one or
// two): where the samples are damaged, in seconds, the first three of each kind and how many more.
std::vector<std::string> describe_pcm_damage(const PcmDamageFinder& finder, int sample_rate_hz);

}  // namespace talkface::detail

#endif
