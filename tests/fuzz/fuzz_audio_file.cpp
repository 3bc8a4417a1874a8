// Any bytes as an audio file, read and analysed as the aligner reads one (libsndfile: WAV with PCM or
// GSM 06.10, FLAC, Ogg; else FFmpeg: MP3, M4A, Opus, a video's sound track): either talkface::Error,
// or a positive rate and finite samples and features to the end; and searched for a second recording
// joined to it, as a refusal of its text searches it.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/joined_copy.hpp"
#include "speech/frame_features.hpp"
#include "talkface/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // The readers take a path: each input goes to a file of this process's own.
    static const std::string path =
        (std::filesystem::temp_directory_path() / ("talkface_fuzz_audio_" + std::to_string(getpid()))).string();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    // The search a refusal asks for (speech_aligner.cpp): any bytes, to their end.
    if (const auto joined = talkface::detail::describe_joined_copy(path);
        joined && joined->description.empty())
        std::abort();
    try {
        const auto source = talkface::detail::open_audio_file(path);
        if (source->sample_rate_hz() <= 0 || source->frame_count() == 0) std::abort();
        std::vector<float> block(4096);
        while (const std::size_t got = source->read(block.data(), block.size())) {
            if (got > block.size()) std::abort();
            for (std::size_t i = 0; i < got; ++i)
                if (!std::isfinite(block[i])) std::abort();
        }
        // Read again as the aligner reads it: up to its first sound (read_first_sound, which refuses
        // a silent file), then the analysis, which sizes its buffers by the length the header states,
        // which a damaged header makes huge (a FLAC's sample count threw bad_alloc).
        auto again = talkface::detail::open_audio_file(path);
        const auto first = talkface::detail::read_first_sound(*again);
        const std::size_t skipped = talkface::detail::silence_to_skip(first, again->sample_rate_hz());
        if (first.held.empty()) {
            auto found = again->first_reading();
            again.reset();
            again = talkface::detail::open_audio_file(path);
            again->take_first_reading(std::move(found));
        }
        const talkface::detail::FeatureTrack track =
            talkface::detail::analyze_audio(*again, {}, false, skipped, first.held);
        for (const float value : track.values)
            if (!std::isfinite(value)) std::abort();
    } catch (const talkface::Error&) {
    }
    std::remove(path.c_str());
    return 0;
}
