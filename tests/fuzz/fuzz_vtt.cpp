// Any bytes as WebVTT subtitles timing a fixed transcript (fuzz_timing_file.hpp says what must hold).
#include "fuzz_timing_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzz_timing_file(data, size, "vtt");
}
