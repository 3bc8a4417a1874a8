// Rhubarb Lip Sync 1.14's JSON cues (its README, "JSON format"), byte for byte as Rhubarb lays them
// out: metadata.soundFile (absolute, non-ASCII as \u escapes of UTF-16, as Rhubarb escapes it) and
// metadata.duration, then one mouthCues item per line. Lossy as the TSV is.
#include <cstdint>
#include <string>

#include "timing/export_writers.hpp"
#include "timing/rhubarb_cues.hpp"

namespace talkface::detail {

namespace {

void append_u_escape(std::string& out, unsigned code) {
    static const char kHex[] = "0123456789abcdef";
    out += "\\u";
    for (int shift = 12; shift >= 0; shift -= 4) out += kHex[(code >> shift) & 0xF];
}

// Rhubarb escapes by UTF-16 unit: quote, backslash and \b \f \n \r \t by name, every other unit
// below 0x20 or from 0x80 as \uXXXX. Bytes that are not UTF-8 become U+FFFD.
std::string rhubarb_json_string(const std::string& text) {
    std::string out;
    for (std::size_t k = 0; k < text.size();) {
        const auto byte = static_cast<unsigned char>(text[k]);
        std::uint32_t code = byte;
        std::size_t length = 1;
        if (byte >= 0x80) {
            length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : byte >= 0xC0 ? 2 : 0;
            bool is_valid = length != 0 && k + length <= text.size();
            if (is_valid) {
                code = byte & (0x7F >> length);
                for (std::size_t j = 1; j < length; ++j) {
                    const auto next = static_cast<unsigned char>(text[k + j]);
                    is_valid = is_valid && (next & 0xC0) == 0x80;
                    code = (code << 6) | (next & 0x3F);
                }
            }
            if (!is_valid) {
                code = 0xFFFD;
                length = 1;
            }
        }
        k += length;
        switch (code) {
            case '"': out += "\\\""; continue;
            case '\\': out += "\\\\"; continue;
            case '\b': out += "\\b"; continue;
            case '\f': out += "\\f"; continue;
            case '\n': out += "\\n"; continue;
            case '\r': out += "\\r"; continue;
            case '\t': out += "\\t"; continue;
            default: break;
        }
        if (code < 0x20 || code >= 0x80) {
            if (code >= 0x10000) {
                append_u_escape(out, 0xD800 + ((code - 0x10000) >> 10));
                append_u_escape(out, 0xDC00 + ((code - 0x10000) & 0x3FF));
            } else {
                append_u_escape(out, code);
            }
        } else {
            out += static_cast<char>(code);
        }
    }
    return out;
}

}  // namespace

std::string rhubarb_json(const ExportInput& input) {
    const std::vector<RhubarbCue> cues = rhubarb_cues(input);
    std::string json = "{\n  \"metadata\": {\n";
    json += "    \"soundFile\": \"" + rhubarb_json_string(absolute_audio_path(input.audio_path)) + "\",\n";
    json += "    \"duration\": " + rhubarb_seconds(cues.back().end_cs) + "\n  },\n  \"mouthCues\": [\n";
    for (std::size_t k = 0; k < cues.size(); ++k) {
        if (k > 0) json += ",\n";
        json += "    { \"start\": " + rhubarb_seconds(cues[k].start_cs) + ", \"end\": " + rhubarb_seconds(cues[k].end_cs) +
                ", \"value\": \"" + cues[k].letter + "\" }";
    }
    return json + "\n  ]\n}\n";
}

}  // namespace talkface::detail
