// Checks on a Timeline, shared by the stages that read one (expression, animation).
#ifndef TALKFACE_TIMING_TIMELINE_CHECKS_HPP
#define TALKFACE_TIMING_TIMELINE_CHECKS_HPP

#include <cstddef>
#include <string>

#include "talkface/timeline.hpp"

namespace talkface::detail {

// "syllable 4 ("ma3", 1.200-1.500 s)": how messages name a syllable.
std::string describe_syllable(const Timeline& timeline, std::size_t index);

// Throws InvalidArgument naming the syllable whose times are not finite or negative, that ends
// before it starts, or that starts before the syllable before it; or naming the mismatch whose
// times are so, that stands for syllables past the last, or whose loudness leaves 0..1.
void check_timeline(const Timeline& timeline);

// Seconds with millisecond precision, as every message and export writes them.
std::string format_seconds(double seconds);

}  // namespace talkface::detail

#endif
