// Key frames for an animated attribute (thesis 6.3.2, keyframes encoding): where linear
// interpolation between a few of a track's frames stays within a tolerance of every frame.
#ifndef TALKFACE_RENDER_KEY_FRAMES_HPP
#define TALKFACE_RENDER_KEY_FRAMES_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace talkface::detail {

// One numeric attribute of a layer (drawing.hpp), followed through every frame.
struct Track {
    std::size_t width = 0;            // numbers per frame
    std::vector<float> numbers;       // width numbers per frame, frame after frame
    bool varies = false;
};

// Records one attribute's numbers frame after frame, cheaply while they hold still: frame 0's
// numbers are kept apart, and the track only starts at the first frame that differs from them
// (frame 0's numbers standing in for every frame before it). Both animation encoders that choose
// key frames from drawn frames (keyframes_encoder.hpp, lottie_layer_encoder.hpp) record with it.
class TrackRecorder {
public:
    // Frame 0's numbers, which fix the width.
    void start(std::vector<double> first_numbers);
    // The numbers of frame `frame` (>= 1), as wide as frame 0's; `expected_frames` reserves room
    // once the track starts.
    void add(const std::vector<double>& numbers, std::size_t frame, std::size_t expected_frames);
    // The next frame is the same as the one before.
    void repeat();
    const std::vector<double>& first() const { return first_; }
    std::size_t width() const { return first_.size(); }
    const Track& track() const { return track_; }

private:
    std::vector<double> first_;
    Track track_;
};

// The key frames of one attribute: where they stand on the frame axis, and their numbers.
struct KeyFrames {
    std::vector<double> positions;  // in frames, rising from 0 to the last frame
    Track values;                   // one row of the track's width per key
};

// Key frames for linear interpolation within `tolerances` (one per number of a frame) of every
// one of `frame_count` frames of `track`; the first and the last frame are keys.
KeyFrames choose_key_frames(const Track& track, std::size_t frame_count,
                            const std::vector<double>& tolerances);

// What linear interpolation between `keys` shows at each of `frame_count` frames (a track of every
// frame, as wide as the keys).
Track interpolated(const KeyFrames& keys, std::size_t frame_count);

// The keyTimes of `keys` over `frame_count` frames.
std::string key_times_of(const KeyFrames& keys, std::size_t frame_count);

// Seconds as SMIL clock values: milliseconds are finer than any frame.
std::string clock_value(double seconds);

}  // namespace talkface::detail

#endif
