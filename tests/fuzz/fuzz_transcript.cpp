// Any bytes as a transcript: either talkface::Error (not an internal one), or a transcript that
// keeps its contract (transcript_contract.hpp).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"
#include "transcript_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    talkface::Timeline transcript;
    try {
        transcript = talkface::read_transcript(std::string_view(reinterpret_cast<const char*>(data), size));
    } catch (const talkface::Error& error) {
        if (error.code() == talkface::ErrorCode::internal) std::abort();
        return 0;
    }
    check_transcript_contract(transcript);
    return 0;
}
