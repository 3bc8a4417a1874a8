// A recording joined to a copy of itself, told by its decoded sound (issue 13, "Bad input"): where
// no header recurs in its bytes (an MP3 with neither an ID3 nor a Xing tag, as sox writes it, is
// frames and nothing else), the second copy's sound is the first's again, sample for sample, from
// its first frames on (the decoder's state is the first copy's there: a frame's overlap and an
// MP3's bit reservoir reach one frame back). No recording of a voice repeats itself exactly.
#ifndef TALKFACE_AUDIO_REPEATED_SOUND_HPP
#define TALKFACE_AUDIO_REPEATED_SOUND_HPP

#include <cstddef>
#include <optional>
#include <string>

namespace talkface::detail {

// Where a recording repeats, in frames at its rate: from `repeat_frame` to the end of the file its
// sound is the sound from `original_frame` on again, and no longer than the distance between them
// (a sound that repeats at a shorter distance is periodic: a tone, not a copy).
struct RepeatedSound {
    int sample_rate_hz = 0;
    std::size_t original_frame = 0;
    std::size_t repeat_frame = 0;
};

// The repeat of the file at `path` as its reader decodes it, or nullopt: its first 0.1 s of sound
// past its first frames found again later and then compared to the file's end, which decodes the
// file once and its second half once more. Asked only where a refusal is to say why (joined_copy.hpp).
std::optional<RepeatedSound> repeated_sound(const std::string& path);

}  // namespace talkface::detail

#endif
