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

// The key frames of one attribute: where they stand on the frame axis, and their numbers.
struct KeyFrames {
    std::vector<double> positions;  // in frames, rising from 0 to the last frame
    Track values;                   // one row of the track's width per key
};

// Key frames for linear interpolation within `tolerances` (one per number of a frame) of every
// one of `frame_count` frames of `track`; the first and the last frame are keys.
KeyFrames choose_key_frames(const Track& track, std::size_t frame_count,
                            const std::vector<double>& tolerances);

// The keyTimes of `keys` over `frame_count` frames.
std::string key_times_of(const KeyFrames& keys, std::size_t frame_count);

// Seconds as SMIL clock values: milliseconds are finer than any frame.
std::string clock_value(double seconds);

}  // namespace talkface::detail

#endif
