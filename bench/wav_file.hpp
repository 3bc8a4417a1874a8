// 16-bit PCM WAV files for the corpus generator (sox does every other format).
#ifndef TALKFACE_BENCH_WAV_FILE_HPP
#define TALKFACE_BENCH_WAV_FILE_HPP

#include <string>
#include <vector>

namespace talkface_bench {

struct MonoAudio {
    std::vector<float> samples;  ///< -1..1
    int sample_rate_hz = 0;
};

/// Writes mono 16-bit PCM, rounding and clipping to the 16-bit range.
/// \throws std::runtime_error naming `path` if it cannot be written.
void write_wav(const std::string& path, const MonoAudio& audio);

/// Reads a mono 16-bit PCM WAV (as sox writes it).
/// \throws std::runtime_error naming `path` if it is not one.
MonoAudio read_wav(const std::string& path);

}  // namespace talkface_bench

#endif
