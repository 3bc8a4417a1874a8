#include "text/transcript_encoding.hpp"

#include <iconv.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <optional>
#include <vector>

#include "common/utf8.hpp"
#include "talkface/errors.hpp"
#include "text/code_points.hpp"
#include "text/reading_tables.hpp"

namespace talkface::detail {

namespace {

// Where a conversion stopped: the byte offset in the input, and the text converted before it.
struct StoppedAt {
    std::size_t offset = 0;
    std::string text_before;
};

struct Converted {
    std::string text;
    std::optional<StoppedAt> stopped;  // set when the bytes are not text in the encoding
};

class Iconv {
public:
    explicit Iconv(const std::string& encoding) : handle_(iconv_open("UTF-8", encoding.c_str())) {}
    ~Iconv() {
        if (is_open()) iconv_close(handle_);
    }
    Iconv(const Iconv&) = delete;
    Iconv& operator=(const Iconv&) = delete;
    bool is_open() const { return handle_ != reinterpret_cast<iconv_t>(-1); }

    Converted convert(std::string_view bytes) {
        Converted result;
        std::vector<char> out(4096);
        // iconv's input is not const in its signature, though it only reads it.
        char* in = const_cast<char*>(bytes.data());
        std::size_t in_left = bytes.size();
        while (in_left > 0) {
            char* out_at = out.data();
            std::size_t out_left = out.size();
            const std::size_t done = iconv(handle_, &in, &in_left, &out_at, &out_left);
            result.text.append(out.data(), static_cast<std::size_t>(out_at - out.data()));
            if (done != static_cast<std::size_t>(-1)) break;
            if (errno == E2BIG) continue;
            // EILSEQ: not a character of the encoding; EINVAL: the bytes end inside one.
            result.stopped = StoppedAt{bytes.size() - in_left, result.text};
            return result;
        }
        char* out_at = out.data();
        std::size_t out_left = out.size();
        iconv(handle_, nullptr, nullptr, &out_at, &out_left);  // a stateful encoding's closing bytes
        result.text.append(out.data(), static_cast<std::size_t>(out_at - out.data()));
        return result;
    }

private:
    iconv_t handle_;
};

std::string lowercase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::string byte_name(unsigned char byte) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    return std::string("0x") + kDigits[byte >> 4] + kDigits[byte & 0x0F];
}

// Line and column (1-based, in characters) just after `text`.
std::pair<int, int> end_position(const std::string& text) {
    int line = 1;
    int column = 1;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const auto byte = static_cast<unsigned char>(text[k]);
        if (byte == '\n') {
            ++line;
            column = 1;
        } else if ((byte & 0xC0U) != 0x80U) {
            ++column;
        }
    }
    return {line, column};
}

// An encoding a Chinese transcript not in UTF-8 is likely saved in, and who saves it so.
struct LegacyEncoding {
    const char* name;  // as iconv and --encoding take it
    const char* who;
};

constexpr LegacyEncoding kLegacyEncodings[] = {
    {"gb18030",
     "Simplified Chinese, as Windows in mainland China saves \"ANSI\" text; GBK and GB2312 are parts of it"},
    {"big5", "Traditional Chinese, as Windows in Taiwan and Hong Kong saves \"ANSI\" text"},
    {"utf-16le", "UTF-16 without its byte order mark"},
    {"utf-16be", "UTF-16, big endian, without its byte order mark"},
};

// How well a reading of the bytes looks like a Chinese text: the mean cost of its characters that
// are not ASCII, each Han character's the phrase list's (-ln P, common ones cheap), punctuation a
// common character's, anything else (symbols, other scripts, control characters) twice a
// character the list lacks. A wrong encoding reads the bytes as rare characters or symbols.
struct Reading {
    const LegacyEncoding* encoding = nullptr;
    std::string text;
    double mean_cost = 0.0;
    double han_share = 0.0;  // of the characters that are not ASCII
};

std::optional<Reading> chinese_reading(const LegacyEncoding& encoding, std::string_view bytes) {
    Iconv converter(encoding.name);
    if (!converter.is_open()) return std::nullopt;
    Converted converted = converter.convert(bytes);
    if (converted.stopped) return std::nullopt;
    const auto& tables = reading_tables();
    const double unknown = tables.unknown_character_cost();
    std::vector<CodePoint> code_points;
    try {
        code_points = decode_utf8(converted.text, "<reading>");
    } catch (const ParseError&) {
        return std::nullopt;
    }
    double cost = 0.0;
    std::size_t wide = 0;
    std::size_t han = 0;
    for (const CodePoint& c : code_points) {
        const bool is_control =
            (c.value < 0x20 && c.value != '\t' && c.value != '\n' && c.value != '\r') || c.value == 0x7F;
        if (c.value < 0x80 && !is_control) continue;
        ++wide;
        if (tables.has_readings(c.text)) {
            const auto word = tables.word(c.text);
            cost += word ? word->cost : unknown;
            ++han;
        } else if ((c.value >= 0x3000 && c.value <= 0x303F) || (c.value >= 0xFF01 && c.value <= 0xFF5E) ||
                   (c.value >= 0x2010 && c.value <= 0x2027)) {
            cost += unknown / 4;
        } else {
            cost += 2 * unknown;
        }
    }
    if (wide == 0) return std::nullopt;
    return Reading{&encoding, std::move(converted.text), cost / static_cast<double>(wide),
                   static_cast<double>(han) / static_cast<double>(wide)};
}

// The start of a reading for a message: from its first character that is not ASCII, a line's
// worth, line breaks shown as spaces.
std::string preview(const std::string& text) {
    constexpr std::size_t kCharacters = 24;
    const auto first = std::find_if(text.begin(), text.end(), [](char c) { return (c & 0x80) != 0; });
    std::string out;
    std::size_t characters = 0;
    for (auto at = first; at != text.end() && characters <= kCharacters; ++at) {
        const auto byte = static_cast<unsigned char>(*at);
        if ((byte & 0xC0U) != 0x80U && ++characters > kCharacters) {
            out += "...";
            break;
        }
        out += byte < 0x20 ? ' ' : *at;
    }
    return out;
}

// What the bytes that are not UTF-8 read as: the encodings in which they are mostly Chinese
// characters, likeliest first.
std::string legacy_readings(std::string_view bytes) {
    constexpr double kLeastHanShare = 0.6;
    std::vector<Reading> readings;
    for (const LegacyEncoding& encoding : kLegacyEncodings) {
        auto reading = chinese_reading(encoding, bytes);
        if (reading && reading->han_share >= kLeastHanShare) readings.push_back(std::move(*reading));
    }
    std::stable_sort(readings.begin(), readings.end(),
                     [](const Reading& a, const Reading& b) { return a.mean_cost < b.mean_cost; });
    if (readings.empty()) {
        return "nor GB18030, Big5 or UTF-16 Chinese; save the transcript as UTF-8, or name its encoding "
               "(--transcript-encoding)";
    }
    std::string out = "it reads as ";
    for (std::size_t k = 0; k < readings.size(); ++k) {
        if (k > 0) out += k + 1 == readings.size() ? ", less likely as " : ", then as ";
        out += std::string(readings[k].encoding->name) + " (" + readings[k].encoding->who + "): \"" +
               preview(readings[k].text) + "\"";
    }
    return out + "; name the encoding (--transcript-encoding " + readings.front().encoding->name +
           ", TranscriptOptions::encoding) or save the transcript as UTF-8";
}

bool is_utf8_name(const std::string& name) {
    return name.empty() || name == "utf-8" || name == "utf8";
}

}  // namespace

std::string transcript_utf8(std::string_view bytes, const std::string& encoding, const std::string& source) {
    const std::string name = lowercase(encoding);
    // UTF-8's mark names UTF-8, whatever encoding is named. find_utf8_fault steps over the mark and
    // counts a fault's byte offset from the file's start, so one check serves the marked text and
    // the unmarked; checked after the mark was dropped, the offset fell 3 short of the byte in the
    // file (found by fuzz_transcript_encoding, bench/README.md Session 30).
    const bool is_marked_utf8 = bytes.substr(0, kUtf8Mark.size()) == kUtf8Mark;
    if (is_marked_utf8 || (is_utf8_name(name) && !has_byte_order_mark(bytes))) {
        if (const auto fault = find_utf8_fault(bytes)) {
            const std::string byte = byte_name(static_cast<unsigned char>(bytes[fault->offset]));
            throw ParseError(
                source, fault->line, fault->column, "byte offset " + std::to_string(fault->offset),
                is_marked_utf8
                    ? "not UTF-8, though it starts with UTF-8's byte order mark (the byte " + byte +
                          " starts no character): the file is damaged there, or was joined "
                          "from texts saved in other encodings"
                    : "not UTF-8 (the byte " + byte + " starts no character); " + legacy_readings(bytes));
        }
        return std::string(bytes.substr(is_marked_utf8 ? kUtf8Mark.size() : 0));
    }
    if (has_byte_order_mark(bytes)) return utf8_from_marked_text(bytes, source);
    Iconv converter(name);
    if (!converter.is_open()) {
        throw InvalidArgument("encoding",
                              "\"" + encoding +
                                  "\" is not an encoding this system's iconv knows (iconv -l lists "
                                  "them); a Chinese transcript's are gb18030, big5, big5-hkscs, "
                                  "utf-16le, utf-16be");
    }
    Converted converted = converter.convert(bytes);
    if (converted.stopped) {
        const auto [line, column] = end_position(converted.stopped->text_before);
        const std::size_t offset = converted.stopped->offset;
        const std::string what = offset < bytes.size()
                                     ? "the byte " + byte_name(static_cast<unsigned char>(bytes[offset])) +
                                           " starts no character of it"
                                     : "the file ends inside a character";
        throw ParseError(source, line, column, "byte offset " + std::to_string(offset),
                         "not " + encoding + " (" + what + "); " + legacy_readings(bytes));
    }
    return std::move(converted.text);
}

}  // namespace talkface::detail
