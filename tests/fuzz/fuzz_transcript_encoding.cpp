// Any bytes as a transcript file's bytes, turned into UTF-8 (transcript_utf8): a byte order mark's
// UTF-8, UTF-16 or UTF-32, an encoding named (the first byte picks none, GB18030, Big5 or UTF-16 LE,
// as fuzz_transcript_file's does, so the two share their seeds), else UTF-8 or the guess among
// encodings a refusal names. The decoders alone, without the readings and the written forms after
// them: a campaign on them builds in minutes. Either talkface::Error (not an internal one), or text
// that is UTF-8 throughout.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "talkface/errors.hpp"
#include "text/code_points.hpp"
#include "text/transcript_encoding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const kEncodings[] = {"", "gb18030", "big5", "utf-16le"};
    std::string text;
    try {
        text = talkface::detail::transcript_utf8(
            std::string_view(reinterpret_cast<const char*>(data + 1), size - 1), kEncodings[data[0] % 4],
            "<fuzz>");
    } catch (const talkface::Error& error) {
        if (error.code() == talkface::ErrorCode::internal) std::abort();
        return 0;
    }
    if (talkface::detail::find_utf8_fault(text)) std::abort();
    return 0;
}
