// Dropouts (issue 13): where a stream lost packets (a call, a network recorder, a Bluetooth link),
// its decoder writes exact zeros for 5-100 ms in the middle of the sound. The features of the frames
// there read digital silence, and the syllables either side were taken to its edges, as to a closure
// (bench/README.md, sweep, sessions 17-18). A dropout is told from a closure by its edges: the sound
// is cut, not faded. A voice faded into a closure (a synthesizer's, an editor's join) reaches its
// zeros at a few hundredths of its level; a dropout cuts a wave mid-swing.
#ifndef TALKFACE_SPEECH_DROPOUT_FINDER_HPP
#define TALKFACE_SPEECH_DROPOUT_FINDER_HPP

#include <array>
#include <cstddef>
#include <vector>

namespace talkface::detail {

// Samples [first_sample, end_sample) of the 16 kHz stream are exact zeros and the sound around
// them is cut.
struct Dropout {
    std::size_t first_sample = 0;
    std::size_t end_sample = 0;
};

// A run of zeros is a dropout when it lasts kShortestDropoutSamples to kLongestDropoutSamples (5-100
// ms: a lost packet or a few; shorter runs are a quiet wave's own zero samples, longer ones a pause
// an editor muted) and on each side the kCutSamples next to it (0.25 ms) reach kCutShare of the
// loudest sample of the kSideSamples next to it (20 ms), and on one side kCleanCutShare. A 10 ms fade
// out reaches 0.025 there: of the 1645 runs of zeros in speaker 3's clean passages, closures after a
// fade, none passes; of 38 dropouts inside speech in the sweep's passages and the test clips, 28 do
// (bench/README.md, session 17; the others cut a wave near its zero crossing on both sides: 0.25 ms
// is 0.16 of a 100 Hz period).
constexpr std::size_t kShortestDropoutSamples = 80;
constexpr std::size_t kLongestDropoutSamples = 1600;
constexpr std::size_t kCutSamples = 4;
constexpr std::size_t kSideSamples = 320;
constexpr float kCutShare = 0.05f;
constexpr float kCleanCutShare = 0.1f;

struct CodecPause;

// `dropouts` of a stream at `rate_hz` but for those that meet a stretch of `pauses`: the zeros read
// in place of a codec's pause frames are a pause its encoder heard, not lost sound, and an encoder
// hears one inside a stop's closure too (espeak-ng's closure before 究 jiu1 in AMR-NB at 4.75 kb/s,
// one 20 ms frame of them, cut on both sides by the codec's ringing: drawn over, the closure
// filled and the syllable came 40 ms late; bench/README.md, sweep sessions 18-19).
std::vector<Dropout> outside_codec_pauses(std::vector<Dropout> dropouts,
                                          const std::vector<CodecPause>& pauses, int rate_hz);

// Finds the dropouts of a 16 kHz stream as it is pushed, holding only the last kSideSamples of it.
class DropoutFinder {
public:
    void push(const float* samples, std::size_t count);
    // The dropouts found, in order; a run whose sound after it ended with the stream is judged on
    // what there was.
    std::vector<Dropout> finish();

private:
    // A run of zeros of a dropout's length, waiting for the sound after it.
    struct Candidate {
        Dropout run;
        float before_cut = 0.0f;   // the loudest of the kCutSamples before the run
        float before_side = 0.0f;  // ... of the kSideSamples before it
        float after_cut = 0.0f;
        float after_side = 0.0f;
        std::size_t after_seen = 0;
    };
    void judge(const Candidate& candidate);
    void end_run();

    // |sample| of the stream's last kHistory samples, the next one to go at next_: the sound
    // before a run still there when the run reaches kShortestDropoutSamples.
    static constexpr std::size_t kHistory = kSideSamples + kShortestDropoutSamples;
    std::array<float, kHistory> history_{};
    std::size_t next_ = 0;
    std::size_t samples_in_ = 0;
    std::size_t run_first_ = 0;
    std::size_t run_length_ = 0;
    float run_before_cut_ = 0.0f;
    float run_before_side_ = 0.0f;
    std::vector<Candidate> waiting_;
    std::vector<Dropout> found_;
};

}  // namespace talkface::detail

#endif
