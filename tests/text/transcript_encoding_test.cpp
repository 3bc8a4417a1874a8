// A transcript file's bytes in the encodings people save them in: a byte order mark's Unicode read
// as it says, a named legacy encoding converted, and bytes that are not UTF-8 refused with the
// encodings that would read them, never guessed into text.
#include <doctest/doctest.h>

#include <iconv.h>

#include <string>

#include "talkface/errors.hpp"
#include "text/transcript_encoding.hpp"

using talkface::detail::transcript_utf8;

namespace {

const std::string kSimplified = "长期下来，伤害不断累积。\n银行很好。\n";
const std::string kTraditional = "長期下來，傷害不斷累積。\n銀行很好。\n";

// `text` (UTF-8) in `encoding`, by iconv.
std::string encoded(const std::string& text, const char* encoding) {
    iconv_t converter = iconv_open(encoding, "UTF-8");
    REQUIRE(converter != reinterpret_cast<iconv_t>(-1));
    std::string out(text.size() * 4 + 8, '\0');
    char* in = const_cast<char*>(text.data());
    std::size_t in_left = text.size();
    char* out_at = out.data();
    std::size_t out_left = out.size();
    REQUIRE(iconv(converter, &in, &in_left, &out_at, &out_left) != static_cast<std::size_t>(-1));
    iconv_close(converter);
    out.resize(out.size() - out_left);
    return out;
}

std::string message_of(const std::string& bytes, const std::string& encoding = "") {
    try {
        transcript_utf8(bytes, encoding, "story.txt");
    } catch (const talkface::Error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_SUITE("transcript encoding") {
    TEST_CASE("UTF-8 is read as it is, with or without its mark") {
        CHECK(transcript_utf8(kSimplified, "", "s") == kSimplified);
        CHECK(transcript_utf8("\xEF\xBB\xBF" + kSimplified, "", "s") == kSimplified);
        CHECK(transcript_utf8(kSimplified, "UTF-8", "s") == kSimplified);
    }

    TEST_CASE("UTF-16 and UTF-32 with a byte order mark, either byte order, whatever encoding is named") {
        for (const char* encoding : {"UTF-16LE", "UTF-16BE", "UTF-32LE", "UTF-32BE"}) {
            CAPTURE(encoding);
            const std::string mark = encoded("\xEF\xBB\xBF", encoding);
            CHECK(transcript_utf8(mark + encoded(kTraditional, encoding), "", "s") == kTraditional);
            CHECK(transcript_utf8(mark + encoded(kTraditional, encoding), "gb18030", "s") == kTraditional);
        }
    }

    TEST_CASE("a named legacy encoding is converted") {
        CHECK(transcript_utf8(encoded(kSimplified, "GB18030"), "gb18030", "s") == kSimplified);
        CHECK(transcript_utf8(encoded(kSimplified, "GBK"), "GBK", "s") == kSimplified);
        CHECK(transcript_utf8(encoded(kTraditional, "BIG5"), "big5", "s") == kTraditional);
        CHECK(transcript_utf8(encoded(kTraditional, "UTF-16LE"), "utf-16le", "s") == kTraditional);
    }

    TEST_CASE("bytes that are not UTF-8 are refused, naming the encoding that reads them, likeliest first") {
        const std::string gbk = message_of(encoded(kSimplified, "GB18030"));
        CHECK(gbk.find("story.txt:1:1: byte offset 0: not UTF-8") == 0);
        CHECK(gbk.find("it reads as gb18030 (Simplified Chinese") != std::string::npos);
        CHECK(gbk.find("\"长期下来，伤害不断累积。 银行很好。 \"") != std::string::npos);
        CHECK(gbk.find("--transcript-encoding gb18030") != std::string::npos);
        const std::string big5 = message_of(encoded(kTraditional, "BIG5"));
        CHECK(big5.find("it reads as big5 (Traditional Chinese") != std::string::npos);
        CHECK(big5.find("\"長期下來") != std::string::npos);
        const std::string utf16 = message_of(encoded(kSimplified, "UTF-16LE"));
        CHECK(utf16.find("it reads as utf-16le") != std::string::npos);
    }

    TEST_CASE("bytes after UTF-8's mark that are not UTF-8 are refused, naming their byte in the file") {
        // The mark is 3 bytes, "小朋友。" 12, then 0xFF: byte 15 of the file, column 5.
        const std::string message = message_of("\xEF\xBB\xBF小朋友。\xFF\xFE abc\n");
        CHECK(
            message.find("story.txt:1:5: byte offset 15: not UTF-8, though it starts with UTF-8's byte order "
                         "mark (the byte 0xFF starts no character)") == 0);
    }

    TEST_CASE("the place where UTF-8 stops is named by line and column") {
        const std::string bytes = "第一行。\n第二" + encoded("行", "GB18030") + "。\n";
        const std::string message = message_of(bytes);
        CHECK(message.find("story.txt:2:3: byte offset ") == 0);
    }

    TEST_CASE("bytes not in a named encoding, and a name iconv lacks, are refused") {
        const std::string message = message_of("\x81", "big5");
        CHECK(message.find("story.txt:1:1: byte offset 0: not big5") == 0);
        CHECK_THROWS_AS(transcript_utf8("abc", "no-such-encoding", "s"), talkface::InvalidArgument);
        CHECK(message_of("\xFF\xFF\xFF").find("nor GB18030, Big5 or UTF-16 Chinese") != std::string::npos);
    }
}
