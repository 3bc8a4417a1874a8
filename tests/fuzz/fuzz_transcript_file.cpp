// Any bytes as a transcript file (load_transcript): text in any encoding, subtitles, a TextGrid.
// The first byte picks the encoding named (none, GB18030, Big5, UTF-16 LE), the rest is the file.
// Either talkface::Error (not an internal one), or a transcript that keeps its contract
// (transcript_contract.hpp).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"
#include "timing/transcript_file.hpp"
#include "transcript_contract.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const kEncodings[] = {"", "gb18030", "big5", "utf-16le"};
    talkface::TranscriptOptions options;
    options.encoding = kEncodings[data[0] % 4];
    options.keep_directions = (data[0] & 4U) != 0;
    talkface::Timeline transcript;
    try {
        transcript = talkface::detail::read_transcript_file(
            std::string_view(reinterpret_cast<const char*>(data + 1), size - 1), options, "<fuzz>");
    } catch (const talkface::Error& error) {
        if (error.code() == talkface::ErrorCode::internal) std::abort();
        return 0;
    }
    check_transcript_contract(transcript);
    return 0;
}
