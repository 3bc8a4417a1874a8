#include "audio/audio_source.hpp"

#include <ogg/ogg.h>
#include <sndfile.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>

#include "audio/chained_stream.hpp"
#include "audio/ffmpeg_source.hpp"
#include "audio/pcm_damage.hpp"
#include "common/input_file.hpp"
#include "common/number_format.hpp"
#include "common/string_ends.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

std::string seconds_text(std::size_t frame, int sample_rate_hz) {
    return format_fixed(static_cast<double>(frame) / sample_rate_hz, 3) + " s";
}

// The data chunk's size as the header states it and as the file holds it.
struct DataBytes {
    std::size_t stated = 0;
    std::size_t present = 0;
};

// libsndfile shortens the frame count of a WAV/AIFF whose data chunk is cut off and only says so
// in its log ("data : 79912 (should be 19956)"): the header's promise, then what is there.
std::optional<DataBytes> data_bytes_if_truncated(SNDFILE* file) {
    char log[4096] = {};
    sf_command(file, SFC_GET_LOG_INFO, log, sizeof log);
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        constexpr std::string_view kDataLine = "data :", kShouldBe = "(should be";
        const std::size_t should_be = line.find(kShouldBe);
        if (!starts_with(line, kDataLine) || should_be == std::string::npos) continue;
        std::istringstream stated(line.substr(kDataLine.size())),
            present(line.substr(should_be + kShouldBe.size()));
        unsigned long long stated_bytes = 0, present_bytes = 0;
        if (stated >> stated_bytes && present >> present_bytes)
            return DataBytes{static_cast<std::size_t>(stated_bytes), static_cast<std::size_t>(present_bytes)};
    }
    return std::nullopt;
}

// A data size a writer leaves when it cannot seek back to fill in the real one (FFmpeg writing a
// WAV to a pipe states 0xFFFFFFFF, "as long as it goes"; some cap it at the signed maximum): no
// promise that the file broke, so the data is read to the end of the file, as libsndfile's frame
// count already says. (A size left at 0 gives no frames at all: see open_audio_file.)
bool is_placeholder_size(std::size_t stated_bytes) { return stated_bytes == 0xFFFFFFFFu || stated_bytes == 0x7FFFFFFFu; }

// The frames a cut-off data chunk promised: its stated bytes over a frame's bytes, or for a codec
// of blocks (GSM 06.10, ADPCM), whose frames have no size of their own, the frames present scaled
// by how much more the header states than the file holds.
std::size_t frames_promised_by(const SF_INFO& info, std::size_t frame_bytes, const DataBytes& data) {
    if (frame_bytes > 0) return data.stated / frame_bytes;
    if (data.present == 0) return 0;
    return static_cast<std::size_t>(std::ceil(static_cast<double>(info.frames) * static_cast<double>(data.stated) /
                                              static_cast<double>(data.present)));
}

std::size_t bytes_per_frame(const SF_INFO& info) {
    int sample_bytes = 0;
    switch (info.format & SF_FORMAT_SUBMASK) {
        case SF_FORMAT_PCM_S8: case SF_FORMAT_PCM_U8: case SF_FORMAT_ULAW: case SF_FORMAT_ALAW:
            sample_bytes = 1; break;
        case SF_FORMAT_PCM_16: sample_bytes = 2; break;
        case SF_FORMAT_PCM_24: sample_bytes = 3; break;
        case SF_FORMAT_PCM_32: case SF_FORMAT_FLOAT: sample_bytes = 4; break;
        case SF_FORMAT_DOUBLE: sample_bytes = 8; break;
        default: return 0;
    }
    return static_cast<std::size_t>(sample_bytes) * static_cast<std::size_t>(info.channels);
}

// The containers libsndfile reads, by their first bytes: WAV (RIFF, RIFX, RF64, BW64), Wave64,
// AIFF, AU, CAF and Ogg. FLAC goes to FFmpeg: after a damaged frame libsndfile's FLAC reader stops
// ("flac decoder lost sync": a scratch lost the rest of the recording), where FFmpeg's finds the next
// frame and keeps the time between as silence; FLAC is lossless, so both give the same samples.
// Everything else (MP3, M4A, video, and what is not audio at all) goes to FFmpeg too: libsndfile tries any unknown file as MP3 through mpg123, which prints "Illegal
// Audio-MPEG-Header" on stderr for bad input, and its MP3 length is an estimate from the first
// frame's bit rate (sox's MP3s at 22.05 and 44.1 kHz came out "truncated"); FFmpeg reads them to
// the real end and prints nothing (ffmpeg_source.cpp).
bool is_sndfile_container(const std::array<char, 12>& header) {
    const std::string_view start(header.data(), header.size());
    const bool is_iff = (start.substr(0, 4) == "RIFF" || start.substr(0, 4) == "RIFX" || start.substr(0, 4) == "RF64" ||
                         start.substr(0, 4) == "BW64") && start.substr(8, 4) == "WAVE";
    const bool is_aiff = start.substr(0, 4) == "FORM" && (start.substr(8, 4) == "AIFF" || start.substr(8, 4) == "AIFC");
    return is_iff || is_aiff || start.substr(0, 4) == "riff" || start.substr(0, 4) == ".snd" ||
           start.substr(0, 4) == "dns." || start.substr(0, 4) == "caff" || start.substr(0, 4) == "OggS";
}

// The length a FLAC's first metadata block states when it is a STREAMINFO of another length than
// the 34 bytes the format fixes, else nothing: FFmpeg's FLAC reader refused such a file as
// "Invalid data found", as if it were no audio.
std::optional<unsigned> wrong_streaminfo_length(const std::array<char, 12>& header) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(header[i]); };
    if (std::string_view(header.data(), 4) != "fLaC" || (byte(4) & 0x7F) != 0) return std::nullopt;
    const unsigned length = byte(5) << 16 | byte(6) << 8 | byte(7);
    if (length == 34) return std::nullopt;
    return length;
}

// A voice message as WeChat and QQ save it (.silk, often named .amr or .slk): "#!SILK_V3", after a
// byte 0x02 in WeChat's, then the frames of Skype's SILK codec, which FFmpeg has no decoder for
// (it decodes SILK only inside Opus). FFmpeg called it "Invalid data found when processing input".
bool is_silk_voice_message(const std::array<char, 12>& header) {
    const std::string_view start(header.data(), header.size());
    return start.substr(0, 9) == "#!SILK_V3" || start.substr(0, 10) == "\x02#!SILK_V3";
}

// Whether `bytes` are text: UTF-8 (a sequence cut off at their end allowed) with no control
// character but tab, line feed, carriage return and form feed.
bool is_text(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size();) {
        const auto byte = static_cast<unsigned char>(bytes[i]);
        if (byte < 0x80) {
            if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r' && byte != '\f') || byte == 0x7F)
                return false;
            ++i;
            continue;
        }
        const std::size_t length = byte >= 0xF0 && byte < 0xF5   ? 4
                                   : byte >= 0xE0                ? 3
                                   : byte >= 0xC2 && byte < 0xE0 ? 2
                                                                 : 0;
        if (length == 0 || byte >= 0xF5) return false;
        for (std::size_t k = 1; k < length && i + k < bytes.size(); ++k)
            if ((static_cast<unsigned char>(bytes[i + k]) & 0xC0) != 0x80) return false;
        i += length;
    }
    return true;
}

// What a text file given as the recording is: a web page (a download that failed, a link expired or
// a login asked, saves the server's HTML page under the recording's name) with its title, or other
// text (a transcript given as the recording) with its first line. FFmpeg called both "Invalid data"
// or "Invalid argument".
struct TextInstead {
    bool is_web_page = false;
    std::string words;  // the page's title, or the first line; empty if none
};

// Whether `bytes` open as a recording's container does, in letters ("RIFF", "fLaC", "OggS", "ID3"):
// a recording cut inside its first bytes is text by is_text's measure ("RIFF" alone), and is a
// recording cut short, not a text file. A prefix counts (a file of 2 bytes, "Og").
bool opens_as_container(std::string_view bytes) {
    for (const std::string_view signature : {"RIFF", "RIFX", "RF64", "BW64", "FORM", "fLaC", "OggS", "ID3",
                                             "#!AMR", "#!SILK_V3", ".snd", "caff", "wvpk", "MAC "})
        if (bytes.substr(0, signature.size()) == signature.substr(0, bytes.size())) return true;
    return false;
}

std::optional<TextInstead> text_instead_of_audio(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string start(4096, '\0');
    in.read(start.data(), static_cast<std::streamsize>(start.size()));
    start.resize(static_cast<std::size_t>(in.gcount()));
    if (start.empty() || !is_text(start) || opens_as_container(start)) return std::nullopt;
    std::string lower = start;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::size_t at = starts_with(lower, "\xef\xbb\xbf") ? 3 : 0;  // UTF-8's byte order mark
    while (at < lower.size() && std::isspace(static_cast<unsigned char>(lower[at]))) ++at;
    TextInstead text;
    text.is_web_page = lower.compare(at, 14, "<!doctype html") == 0 || lower.compare(at, 5, "<html") == 0;
    std::size_t from = at, to = start.find_first_of("\r\n", at);
    if (text.is_web_page) {
        const std::size_t open = lower.find("<title>"), close = lower.find("</title>");
        if (open == std::string::npos || close == std::string::npos || close < open) return text;
        from = open + 7;
        to = close;
    }
    constexpr std::size_t kLongestWords = 80;
    for (std::size_t i = from; i < std::min(to, start.size()) && text.words.size() < kLongestWords; ++i) {
        // Runs of white space (a page's line breaks and indents) as one space.
        const bool is_space = std::isspace(static_cast<unsigned char>(start[i])) != 0;
        if (is_space && (text.words.empty() || text.words.back() == ' ')) continue;
        text.words += is_space ? ' ' : start[i];
    }
    while (!text.words.empty() && text.words.back() == ' ') text.words.pop_back();
    return text;
}

// The refusal of a text file given as the recording.
ParseError text_refused(const std::string& path, const TextInstead& text) {
    const std::string said = text.words.empty() ? std::string() : ", \"" + text.words + "\"";
    if (text.is_web_page)
        return ParseError(path, 0, 0, "",
                          "a web page (HTML" + (said.empty() ? said : ", titled" + said.substr(1)) +
                              "), not audio: a download that failed saves the server's page under the "
                              "recording's name; download the recording again");
    return ParseError(path, 0, 0, "",
                      "a text file (its first line" +
                          (said.empty() ? std::string(" is empty") : said.substr(1)) +
                          "), not audio: is it the transcript, given as the recording?");
}

// Whether `bytes` hold a whole Ogg page (its CRC checked) anywhere.
bool holds_ogg_page(const char* bytes, std::size_t count) {
    ogg_sync_state sync;
    ogg_sync_init(&sync);
    char* buffer = ogg_sync_buffer(&sync, static_cast<long>(count));
    bool found = false;
    if (buffer != nullptr) {
        std::memcpy(buffer, bytes, count);
        ogg_sync_wrote(&sync, static_cast<long>(count));
        ogg_page page;
        for (long seek = 0; !found && (seek = ogg_sync_pageseek(&sync, &page)) != 0;) found = seek > 0;
    }
    ogg_sync_clear(&sync);
    return found;
}

// What a walk over an Ogg file's pages found damaged.
struct OggDamage {
    // The byte where the first damaged page begins (or the bytes that are no page).
    std::int64_t first_damaged_byte = 0;
    // The byte where a page begins whose header claims more bytes than the file holds (a scratch
    // in its segment table), with whole pages after it; -1 if none.
    std::int64_t overlong_page_byte = -1;
};

// Whether an Ogg file has a damaged page: bytes that are no page (libogg skips them to the next
// capture pattern, checking each page's CRC), a page missing from a stream's numbered sequence, or
// a page whose header claims more bytes than the file holds while whole pages follow it (libogg
// waits for the rest of it to the end of the file, as for a cut file's last page: the scratched
// file was called cut). libsndfile drops a damaged page and goes on with the next, and the time the
// page held vanishes: every syllable after a scratch came early, and the shortfall was called
// "truncated". FFmpeg's Ogg reader gives the pages after it their granule positions, and the gap
// is kept as silence (ffmpeg_source.cpp). A page cut off at the end, with nothing after it, is not
// damage here: open_audio_file says the file was cut. One pass over the file's bytes, no decoding.
std::optional<OggDamage> find_damaged_ogg_page(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) return std::nullopt;
    ogg_sync_state sync;
    ogg_sync_init(&sync);
    std::map<long, long> next_page_of_stream;
    OggDamage damage;
    bool damaged = false;
    std::int64_t walked_bytes = 0;  // bytes libogg has skipped or returned as pages
    constexpr long kChunkBytes = 1 << 16;
    while (!damaged) {
        char* buffer = ogg_sync_buffer(&sync, kChunkBytes);
        const std::size_t got = buffer ? std::fread(buffer, 1, kChunkBytes, file) : 0;
        if (got == 0) break;
        ogg_sync_wrote(&sync, static_cast<long>(got));
        ogg_page page;
        for (long seek = 0; !damaged && (seek = ogg_sync_pageseek(&sync, &page)) != 0;) {
            damage.first_damaged_byte = walked_bytes;
            walked_bytes += seek < 0 ? -seek : seek;
            if (seek < 0) {
                damaged = true;
                break;
            }
            const long serial = ogg_page_serialno(&page);
            const long number = ogg_page_pageno(&page);
            const auto next = next_page_of_stream.find(serial);
            // A stream's first page starts its count afresh: a second recording chained after the
            // first (chained_stream.hpp) may have its serial number (FFmpeg's, with -bitexact: 0).
            if (next != next_page_of_stream.end() && next->second != number && ogg_page_bos(&page) == 0)
                damaged = true;
            next_page_of_stream[serial] = number + 1;
        }
    }
    // At the end, libogg still holds the bytes of a page it waits for: whole pages after its start
    // say its header lied (a cut file's last page has none).
    const long waiting = sync.fill - sync.returned;
    if (!damaged && waiting > 4 && holds_ogg_page(reinterpret_cast<const char*>(sync.data) + sync.returned + 1,
                                                  static_cast<std::size_t>(waiting - 1))) {
        damaged = true;
        damage.first_damaged_byte = walked_bytes;
        damage.overlong_page_byte = walked_bytes;
    }
    ogg_sync_clear(&sync);
    std::fclose(file);
    if (!damaged) return std::nullopt;
    return damage;
}

std::uint64_t read_le32(const unsigned char* bytes) {
    return static_cast<std::uint64_t>(bytes[0]) | static_cast<std::uint64_t>(bytes[1]) << 8 |
           static_cast<std::uint64_t>(bytes[2]) << 16 | static_cast<std::uint64_t>(bytes[3]) << 24;
}

// An Ogg file's pages from its start, through libogg, read as libsndfile reads them: 4096 bytes at
// a time (vorbis_headers_refused takes its steps).
class OggPageReader {
public:
    explicit OggPageReader(const std::string& path) : file_(std::fopen(path.c_str(), "rb")) {
        ogg_sync_init(&sync_);
    }
    ~OggPageReader() {
        ogg_sync_clear(&sync_);
        if (file_ != nullptr) std::fclose(file_);
    }
    OggPageReader(const OggPageReader&) = delete;
    OggPageReader& operator=(const OggPageReader&) = delete;

    // 1 and the next page in `page`; -1 where bytes that are no page (or a page failing its check)
    // were skipped; 0 at the end of the file (or of what could be read).
    int next_page(ogg_page& page) {
        int found = 0;
        while ((found = ogg_sync_pageout(&sync_, &page)) == 0 && read_more()) {
        }
        return found;
    }
    // The first whole page, past any bytes that are no page; false if the file holds none.
    bool first_page(ogg_page& page) {
        int found = 0;
        while ((found = next_page(page)) < 0) {
        }
        return found == 1;
    }

private:
    bool read_more() {
        constexpr long kChunkBytes = 4096;  // libsndfile's
        char* buffer = ogg_sync_buffer(&sync_, kChunkBytes);
        const std::size_t got =
            file_ != nullptr && buffer != nullptr ? std::fread(buffer, 1, kChunkBytes, file_) : 0;
        ogg_sync_wrote(&sync_, static_cast<long>(got));
        return got > 0;
    }

    std::FILE* file_;
    ogg_sync_state sync_;
};

// Whether libsndfile (1.2.0) would refuse to open the Ogg file at `path` in a way that leaks: its
// first stream is Vorbis (its first page's first packet starts "\x01vorbis"), and that packet is
// not a beginning of stream, or states a Vorbis version other than 0, or the stream's two further
// header packets are not all there (the file ends first, or a page is missing among them).
// libsndfile's vorbis_read_header then returns its error before it sets the codec's close
// function, and the 5.8 KB that vorbis_info_init allocated are never freed (libsndfile issue #922;
// every failed open of such a file kept them). The same steps as its own, through libogg, so that
// a file it would open is never turned away here; a file refused here is refused by libsndfile
// too, and goes where libsndfile's refusal sends it (open_ogg_refused_by_sndfile).
bool vorbis_headers_refused(const std::string& path) {
    OggPageReader pages(path);
    ogg_page page;
    constexpr std::string_view kVorbisId = "\x01vorbis";
    if (!pages.first_page(page) || static_cast<std::size_t>(page.body_len) < kVorbisId.size() ||
        std::memcmp(page.body, kVorbisId.data(), kVorbisId.size()) != 0)
        return false;
    ogg_stream_state stream;
    ogg_stream_init(&stream, ogg_page_serialno(&page));
    ogg_packet packet;
    bool refused = false;
    if (ogg_stream_pagein(&stream, &page) == 0 && ogg_stream_packetout(&stream, &packet) == 1) {
        constexpr std::size_t kVersionEnd = 7 + 4;
        const bool has_version_0 = packet.bytes >= static_cast<long>(kVersionEnd) &&
                                   read_le32(packet.packet + kVorbisId.size()) == 0;
        refused = packet.b_o_s == 0 || !has_version_0;
        for (int packets = 0; !refused && packets < 2;) {
            const int paged = pages.next_page(page);
            refused = paged == 0;
            if (paged < 1) continue;
            ogg_stream_pagein(&stream, &page);
            for (int out = 0;
                 !refused && packets < 2 && (out = ogg_stream_packetout(&stream, &packet)) != 0;) {
                refused = out < 0;
                ++packets;
            }
        }
    }
    ogg_stream_clear(&stream);
    return refused;
}

// The channel count the Opus header of the Ogg file at `path` states (OpusHead, the first packet
// of its first page, its tenth byte: RFC 7845, 5.1); none where the first page holds no Opus header.
std::optional<int> opus_head_channels(const std::string& path) {
    OggPageReader pages(path);
    ogg_page page;
    constexpr std::string_view kOpusHead = "OpusHead";
    constexpr long kChannelsByte = 9;
    if (!pages.first_page(page) || page.body_len <= kChannelsByte ||
        std::memcmp(page.body, kOpusHead.data(), kOpusHead.size()) != 0)
        return std::nullopt;
    return page.body[kChannelsByte];
}

// A RIFF WAV's data chunk that goes on past the size its header states: the bytes stated and the
// bytes the file holds after the data's start, and the bytes a second of sound takes (the format
// chunk's average rate; 0 if it states none).
struct StaleDataSize {
    std::uint64_t stated_bytes = 0;
    std::uint64_t present_bytes = 0;
    std::uint64_t bytes_per_second = 0;
};

// A RIFF WAV whose data chunk goes on past the size its header states: a recorder that writes its
// header early and brings it up to date only now and then (or never, if it crashes) leaves a data
// size of part of the data, and libsndfile reads only that part (the rest of the speech was lost
// and the transcript blamed for it). Chunks may follow the data (LIST, cue, id3 ...): the data is
// taken as longer only when what follows its stated end is no chunk, a 4-character id of letters,
// digits, spaces or '_' with a size that fits in the file.
std::optional<StaleDataSize> data_past_stated_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    const auto file_bytes = static_cast<std::uint64_t>(in.tellg());
    const auto is_chunk_at = [&](std::uint64_t at) {
        unsigned char head[8];
        in.clear();
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(reinterpret_cast<char*>(head), 8)) return false;
        for (int i = 0; i < 4; ++i)
            if (!(std::isalnum(head[i]) || head[i] == ' ' || head[i] == '_')) return false;
        return at + 8 + read_le32(head + 4) <= file_bytes;
    };
    std::uint64_t at = 12;
    std::uint64_t bytes_per_second = 0;
    unsigned char head[8];
    unsigned char format[12];
    while (at + 8 <= file_bytes) {
        in.clear();
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(reinterpret_cast<char*>(head), 8)) return std::nullopt;
        const std::uint64_t size = read_le32(head + 4);
        const std::uint64_t end = at + 8 + size + (size & 1);
        // The format chunk's average bytes a second, at 8 of its 16 or more bytes.
        if (std::memcmp(head, "fmt ", 4) == 0 && size >= 16 && in.read(reinterpret_cast<char*>(format), 12))
            bytes_per_second = read_le32(format + 8);
        if (std::memcmp(head, "data", 4) == 0) {
            // A placeholder size (0, 0xFFFFFFFF) or one past the end of the file is libsndfile's
            // case already (read to the end, or called truncated).
            if (size == 0 || size >= 0x7FFFFFFFu || end + 8 > file_bytes) return std::nullopt;
            if (is_chunk_at(end) || (size & 1 && is_chunk_at(end - 1))) return std::nullopt;
            return StaleDataSize{size, file_bytes - (at + 8), bytes_per_second};
        }
        at = end;
    }
    return std::nullopt;
}

// The data chunks of a RIFF WAV, in order: their start (the byte after their header) and size.
// A WAV holds one; an editor that appends may write a second, which every reader skips (libsndfile
// read the first half of such a file, and its transcript was refused as not its speech). Stops at a
// placeholder size (0, 0xFFFFFFFF: the data runs to the end) or at a chunk past the end.
std::vector<std::pair<std::uint64_t, std::uint64_t>> wav_data_chunks(const std::string& path) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> chunks;
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return chunks;
    const auto file_bytes = static_cast<std::uint64_t>(in.tellg());
    unsigned char head[8];
    for (std::uint64_t at = 12; at + 8 <= file_bytes;) {
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(reinterpret_cast<char*>(head), 8)) break;
        const std::uint64_t size = read_le32(head + 4);
        const std::uint64_t end = at + 8 + size + (size & 1);
        if (std::memcmp(head, "data", 4) == 0) {
            if (size == 0 || size >= 0x7FFFFFFFu) break;
            chunks.emplace_back(at + 8, size);
        }
        if (end > file_bytes) break;
        at = end;
    }
    return chunks;
}

// A RIFF WAV that goes on past the end its RIFF header states, past its data too: the first byte
// no reader reads, the bytes from there to the file's end, the bytes a second of its sound takes
// (the format chunk's average rate; 0 if it states none), and whether those bytes open as a second
// WAV file.
struct BytesPastEnd {
    std::uint64_t first_byte = 0;
    std::uint64_t bytes = 0;
    std::uint64_t bytes_per_second = 0;
    bool is_second_wav = false;
};

// Two WAV files joined (a copy appended to itself, two recordings put together by `cat` or a
// careless upload) read as the first: its RIFF header states the first's size, and every reader
// stops there, silently (a transcript of both was refused as not the speech, one of the first
// aligned as if the file were whole). Nothing past the end where the stated size is a placeholder
// (0, 0xFFFFFFFF: a recorder that streams), or where what follows is one chunk that fills the rest
// of the file (a tag a program appended after the RIFF: no sound).
std::optional<BytesPastEnd> bytes_past_riff_end(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    const auto file_bytes = static_cast<std::uint64_t>(in.tellg());
    unsigned char head[8];
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(head), 8)) return std::nullopt;
    const std::uint64_t riff_size = read_le32(head + 4);
    if (riff_size == 0 || riff_size >= 0x7FFFFFFFu) return std::nullopt;
    BytesPastEnd past;
    past.first_byte = 8 + riff_size + (riff_size & 1);
    for (std::uint64_t at = 12; at + 8 <= file_bytes && at < past.first_byte;) {
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(reinterpret_cast<char*>(head), 8)) return std::nullopt;
        const std::uint64_t size = read_le32(head + 4);
        unsigned char format[12];
        if (std::memcmp(head, "fmt ", 4) == 0 && size >= 16 && in.read(reinterpret_cast<char*>(format), 12))
            past.bytes_per_second = read_le32(format + 8);
        at += 8 + size + (size & 1);
        if (std::memcmp(head, "data", 4) == 0) past.first_byte = std::max(past.first_byte, at);
    }
    if (past.first_byte + 8 > file_bytes) return std::nullopt;
    past.bytes = file_bytes - past.first_byte;
    in.clear();
    in.seekg(static_cast<std::streamoff>(past.first_byte));
    if (!in.read(reinterpret_cast<char*>(head), 8)) return std::nullopt;
    past.is_second_wav = std::memcmp(head, "RIFF", 4) == 0 || std::memcmp(head, "RF64", 4) == 0;
    const std::uint64_t size = read_le32(head + 4);
    bool is_id = true;
    for (int i = 0; i < 4; ++i) is_id = is_id && (std::isalnum(head[i]) || head[i] == ' ' || head[i] == '_');
    if (!past.is_second_wav && is_id && past.bytes - 8 - size <= 1) return std::nullopt;
    return past;
}

// What the reader says of a WAV's bytes past its stated end.
std::string describe_bytes_past_end(const BytesPastEnd& past) {
    const std::string seconds =
        past.bytes_per_second == 0
            ? std::string()
            : ", about " +
                  format_fixed(static_cast<double>(past.bytes) / static_cast<double>(past.bytes_per_second),
                               1) +
                  " s of sound at this file's rate";
    return "the file goes on for " + std::to_string(past.bytes) +
           " bytes past the end its header states (byte " + std::to_string(past.first_byte) + ")" + seconds +
           ", which no reader reads" +
           (past.is_second_wav
                ? ": a second WAV file begins there, as when two recordings or two copies of one "
                  "are joined; only the first was aligned"
                : "; only the sound before them was aligned");
}

// A RIFF WAV that libsndfile cannot open, refused for what its header says: it ends before its
// data chunk starts (a copy or a download cut inside the header: FFmpeg called it "Invalid data",
// as if it were no audio), or its format chunk states a channel count or a rate no reader takes
// (0 channels read as "no audio stream", rate 0 as "Invalid data"). Returns if neither.
// \throws talkface::FileError if the file was cut, talkface::ParseError for its format chunk.
void check_wav_header(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return;
    const auto file_bytes = static_cast<std::uint64_t>(in.tellg());
    unsigned char head[8];
    for (std::uint64_t at = 12;;) {
        in.seekg(static_cast<std::streamoff>(at));
        if (at + 8 > file_bytes || !in.read(reinterpret_cast<char*>(head), 8))
            throw FileError(path, "truncated: the file ends after " + std::to_string(file_bytes) +
                                      " bytes, inside its header, before any sound; it was cut while it was "
                                      "copied or recorded");
        if (std::memcmp(head, "data", 4) == 0) return;
        const std::uint64_t size = read_le32(head + 4);
        unsigned char format[8];
        if (std::memcmp(head, "fmt ", 4) == 0 && size >= 16 && in.read(reinterpret_cast<char*>(format), 8)) {
            const int channels = format[2] | format[3] << 8;
            const auto rate_hz = static_cast<int>(
                std::min<std::uint64_t>(read_le32(format + 4), std::numeric_limits<int>::max()));
            if (!is_readable_format(rate_hz, channels))
                throw ParseError(path, 0, 0, "", unsupported_format_text("header", rate_hz, channels));
        }
        at += 8 + size + (size & 1);
    }
}

// What the reader says of a stale WAV header: the sound it states and the sound the file holds.
std::string describe_stale_size(const StaleDataSize& data) {
    const std::string held = "its header states " + std::to_string(data.stated_bytes) + " bytes of sound, the file holds " +
                             std::to_string(data.present_bytes);
    const std::string said =
        data.bytes_per_second == 0
            ? held
            : "its header states " +
                  format_fixed(static_cast<double>(data.stated_bytes) / static_cast<double>(data.bytes_per_second), 1) +
                  " s of sound, the file holds " +
                  format_fixed(static_cast<double>(data.present_bytes) / static_cast<double>(data.bytes_per_second), 1) +
                  " s";
    return said + " (a header not brought up to date when the recording stopped, as a recorder that crashed or "
                  "lost power leaves it); read to the end of the file";
}

// Whether a file libsndfile reads holds its samples as they are, with no check a copy's damage
// would fail: PCM or floats in WAV, AIFF and their kin (pcm_damage.hpp), not FLAC's checked frames
// nor Ogg's pages.
bool holds_unchecked_samples(const SF_INFO& info) {
    const int type = info.format & SF_FORMAT_TYPEMASK;
    if (type == SF_FORMAT_FLAC || type == SF_FORMAT_OGG) return false;
    switch (info.format & SF_FORMAT_SUBMASK) {
        case SF_FORMAT_PCM_S8:
        case SF_FORMAT_PCM_U8:
        case SF_FORMAT_PCM_16:
        case SF_FORMAT_PCM_24:
        case SF_FORMAT_PCM_32:
        case SF_FORMAT_FLOAT:
        case SF_FORMAT_DOUBLE:
            return true;
        default:
            return false;
    }
}

class FileSource final : public AudioSource {
public:
    FileSource(std::string path, SNDFILE* file, const SF_INFO& info, std::size_t promised_frames)
        : path_(std::move(path)), file_(file), info_(info), promised_frames_(promised_frames) {
        if (holds_unchecked_samples(info)) damage_.emplace(info.samplerate);
    }
    ~FileSource() override { sf_close(file_); }
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;

    std::size_t read_frames(float* mono, std::size_t max_frames) override {
        const auto channels = static_cast<std::size_t>(info_.channels);
        // One channel is read straight into `mono`: mixing it copied each sample as it was (but for
        // a zero's sign, which no feature tells), at a cost as high as the rest of reading.
        float* into = mono;
        if (channels > 1) {
            interleaved_.resize(max_frames * channels);
            into = interleaved_.data();
        }
        const sf_count_t got = sf_readf_float(file_, into, static_cast<sf_count_t>(max_frames));
        const auto frames = got > 0 ? static_cast<std::size_t>(got) : 0;
        if (channels > 1) mixer_.mix(interleaved_.data(), frames, channels, mono);
        frames_read_ += frames;
        if (damage_) note_damage(mono, frames);
        if (frames == 0 && frames_read_ < promised_frames_) {
            const std::string reason = sf_error(file_) != SF_ERR_NO_ERROR ? std::string(": ") + sf_strerror(file_) : "";
            throw FileError(path_, "truncated: the header promises " + std::to_string(promised_frames_) +
                                       " frames (" + seconds_text(promised_frames_, info_.samplerate) +
                                       ") but the data ends at frame " + std::to_string(frames_read_) + " (" +
                                       seconds_text(frames_read_, info_.samplerate) + ")" + reason);
        }
        return frames;
    }
    int sample_rate_hz() const override { return info_.samplerate; }
    std::size_t frame_count() const override { return promised_frames_; }
    const std::string& name() const override { return path_; }

private:
    // Only inside what the header promises: a file cut short fails its seek there and is read on
    // to where its data ends, which the truncation's message names.
    bool seek_frames(std::size_t frame) override {
        if (!info_.seekable || frame > promised_frames_ ||
            sf_seek(file_, static_cast<sf_count_t>(frame), SEEK_SET) != static_cast<sf_count_t>(frame))
            return false;
        frames_read_ = frame;
        if (damage_) damage_->restart_at(frame);
        return true;
    }

    // Follows the samples read for damage (pcm_damage.hpp), and at the end of the data notes it.
    void note_damage(const float* mono, std::size_t frames) {
        if (frames > 0) {
            damage_->push(mono, frames);
            return;
        }
        damage_->finish();
        for (std::string& note : describe_pcm_damage(*damage_, info_.samplerate)) add_note(std::move(note));
        for (const DamagedSamples& cut : damage_->cut_zeros())
            note_cut_to_zeros(cut.first_frame, cut.end_frame - cut.first_frame);
        damage_.reset();
    }

    std::string path_;
    SNDFILE* file_;
    SF_INFO info_;
    std::size_t promised_frames_;
    std::size_t frames_read_ = 0;
    std::vector<float> interleaved_;
    ChannelMixer mixer_;
    std::optional<PcmDamageFinder> damage_;
};

class ViewSource final : public AudioSource {
public:
    explicit ViewSource(const AudioView& audio) : audio_(audio) {}
    std::size_t read_frames(float* mono, std::size_t max_frames) override {
        const auto channels = static_cast<std::size_t>(audio_.channel_count);
        const std::size_t frames = std::min(max_frames, audio_.frame_count - position_);
        mixer_.mix(audio_.samples + position_ * channels, frames, channels, mono);
        position_ += frames;
        return frames;
    }
    int sample_rate_hz() const override { return audio_.sample_rate_hz; }
    std::size_t frame_count() const override { return audio_.frame_count; }
    const std::string& name() const override { return name_; }

private:
    bool seek_frames(std::size_t frame) override {
        if (frame > audio_.frame_count) return false;
        position_ = frame;
        return true;
    }

    AudioView audio_;
    std::size_t position_ = 0;
    std::string name_ = "audio";
    ChannelMixer mixer_;
};

}  // namespace

// How strongly a channel must run against (or with) the first before it is turned over (or back):
// voices recorded by two microphones correlate at +0.3 to +1 and one inverted at -0.3 to -1; a
// channel that holds only noise or silence lies near 0 and is added as it is.
constexpr double kOppositeCorrelation = 0.2;
// Frames mixed before a channel may be turned over: over a few frames of two channels' independent
// noise (the dither of espeak-ng's stereo corpus before its speech) the correlation swings past
// +-0.2 by chance, and turned the second channel over for the first 0.4 s; over 1024 frames its
// chance spread is 0.03 (1/sqrt(1024)), a sixth of the limit.
constexpr std::size_t kFramesBeforeJudging = 1024;

void ChannelMixer::mix(const float* interleaved, std::size_t frames, std::size_t channels, float* mono) {
    if (channels == 1) {
        std::copy_n(interleaved, frames, mono);
        return;
    }
    if (sign_.size() != channels) {
        energy_.assign(channels, 0.0);
        with_first_.assign(channels, 0.0);
        sign_.assign(channels, 1.0f);
        first_energy_ = 0.0;
        frames_mixed_ = 0;
    }
    if (channels == 2) {
        mix_stereo(interleaved, frames, mono);
        return;
    }
    for (std::size_t i = 0; i < frames; ++i) {
        const float* frame = interleaved + i * channels;
        const double first = frame[0];
        first_energy_ += first * first;
        float sum = frame[0];
        for (std::size_t c = 1; c < channels; ++c) {
            const double value = frame[c];
            energy_[c] += value * value;
            with_first_[c] += value * first;
            // |correlation| > kOppositeCorrelation, squared: no square root per sample.
            if (frames_mixed_ >= kFramesBeforeJudging &&
                with_first_[c] * with_first_[c] > kOppositeCorrelation * kOppositeCorrelation * first_energy_ * energy_[c])
                sign_[c] = with_first_[c] < 0.0 ? -1.0f : 1.0f;
            sum += sign_[c] * frame[c];
        }
        mono[i] = sum / static_cast<float>(channels);
        ++frames_mixed_;
    }
}

// The loop above for two channels, the commonest, with every sum and the sign in registers (the
// loop above keeps them in vectors, which a store to `mono` might change as far as the compiler
// knows, so it reloads them each frame): the same operations in the same order, so the same
// samples, in under half the instructions (50 -> 28 a frame; the loop above took 4.2% of aligning a
// 44.1 kHz stereo clip).
void ChannelMixer::mix_stereo(const float* interleaved, std::size_t frames, float* mono) {
    double first_energy = first_energy_;
    double energy = energy_[1];
    double with_first = with_first_[1];
    float sign = sign_[1];
    std::size_t frames_mixed = frames_mixed_;
    for (std::size_t i = 0; i < frames; ++i) {
        const double first = interleaved[2 * i];
        const double value = interleaved[2 * i + 1];
        first_energy += first * first;
        energy += value * value;
        with_first += value * first;
        // Only a correlation of the other sign than the channel's can turn it: the products are
        // asked only then (a stereo file whose sides agree never asks them past its first frames).
        if ((with_first < 0.0) != (sign < 0.0f) && frames_mixed >= kFramesBeforeJudging &&
            with_first * with_first > kOppositeCorrelation * kOppositeCorrelation * first_energy * energy)
            sign = with_first < 0.0 ? -1.0f : 1.0f;
        float sum = interleaved[2 * i];
        sum += sign * interleaved[2 * i + 1];
        mono[i] = sum / 2.0f;
        ++frames_mixed;
    }
    first_energy_ = first_energy;
    energy_[1] = energy;
    with_first_[1] = with_first;
    sign_[1] = sign;
    frames_mixed_ = frames_mixed;
}

void AudioSource::add_note(std::string note) { notes_.push_back(std::move(note)); }

namespace {

// Adds frames [at_frame, at_frame + frames) of a source at `rate_hz` to `stretches`, joined to the
// last stretch when they follow it.
template <class Stretch>
void add_stretch(std::vector<Stretch>& stretches, double rate_hz, std::size_t at_frame, std::size_t frames) {
    const double start_s = static_cast<double>(at_frame) / rate_hz;
    const double end_s = static_cast<double>(at_frame + frames) / rate_hz;
    if (!stretches.empty() && start_s <= stretches.back().end_s + 1e-9)
        stretches.back().end_s = std::max(stretches.back().end_s, end_s);
    else
        stretches.push_back({start_s, end_s});
}

}  // namespace

void AudioSource::note_lost_audio(std::size_t at_frame, std::size_t frames) {
    has_lost_audio_read_ = true;
    const std::size_t end = at_frame + frames;
    if (end <= taken_until_frame_) return;
    at_frame = std::max(at_frame, taken_until_frame_);
    add_stretch(lost_audio_, sample_rate_hz(), at_frame, end - at_frame);
}

void AudioSource::note_codec_pause(std::size_t at_frame, std::size_t frames) {
    add_stretch(codec_pauses_, sample_rate_hz(), at_frame, frames);
}

void AudioSource::note_cut_to_zeros(std::size_t at_frame, std::size_t frames) {
    add_stretch(cuts_to_zeros_, sample_rate_hz(), at_frame, frames);
}

double lost_seconds(const std::vector<LostAudio>& lost) {
    double total_s = 0.0;
    for (const LostAudio& stretch : lost) total_s += stretch.end_s - stretch.start_s;
    return total_s;
}

std::string describe_lost_audio(const std::vector<LostAudio>& lost) {
    if (lost.empty()) return {};
    constexpr std::size_t kNamed = 3;
    std::string where;
    for (std::size_t i = 0; i < lost.size() && i < kNamed; ++i) {
        if (i > 0) where += i + 1 == lost.size() ? " and " : ", ";
        where += format_fixed(lost[i].start_s, 3) + "-" + format_fixed(lost[i].end_s, 3) + " s";
    }
    if (lost.size() > kNamed) where += " and " + std::to_string(lost.size() - kNamed) + " more";
    return format_fixed(lost_seconds(lost), 3) + " s of its sound could not be decoded, at " + where;
}

namespace {

// "3.27e37": a sample's level past any scale, locale-independent, three digits.
std::string scientific_text(double value) {
    int exponent = static_cast<int>(std::floor(std::log10(std::fabs(value))));
    // 9.999e33 rounds to 10.00: one more power of ten.
    if (std::fabs(rounded(value / std::pow(10.0, exponent), 2)) >= 10.0) ++exponent;
    return format_fixed(value / std::pow(10.0, exponent), 2) + "e" + std::to_string(exponent);
}

}  // namespace

std::string describe_non_finite_samples(std::size_t non_finite, std::size_t total, double first_s) {
    if (non_finite == total)
        return "none of its " + std::to_string(total) +
               " samples is a number (each is NaN or infinite): the file is damaged or the program "
               "that wrote it failed";
    return std::to_string(non_finite) + " of its " + std::to_string(total) +
           " samples are not numbers (NaN or infinite), the first at " + format_fixed(first_s, 3) + " s" +
           ": read as silence there; the file is damaged or the program that wrote it failed";
}

std::size_t AudioSource::read(float* mono, std::size_t max_frames) {
    const std::size_t frames = read_frames(mono, max_frames);
    for (std::size_t i = 0; i < frames; ++i) {
        if (!std::isfinite(mono[i])) {
            if (frames_read_ + i >= taken_until_frame_) {
                if (non_finite_frames_ == 0) first_non_finite_frame_ = frames_read_ + i;
                ++non_finite_frames_;
            }
            mono[i] = 0.0f;
        } else if (std::fabs(mono[i]) > kMostSampleMagnitude) {
            const double at_s = static_cast<double>(frames_read_ + i) / sample_rate_hz();
            throw ParseError(
                name(), 0, 0, "",
                "a sample at " + format_fixed(at_s, 3) + " s reads " + scientific_text(mono[i]) +
                    ", where a recording's samples lie within -1..1 (or an integer format's range, "
                    "under 2^31): the file was written with a wrong scale or is damaged; scale it "
                    "to -1..1 first");
        }
    }
    frames_read_ += frames;
    if (frames == 0 && non_finite_frames_ > 0 && !is_end_noted_) {
        is_end_noted_ = true;
        add_note(
            describe_non_finite_samples(non_finite_frames_, frames_read_,
                                        static_cast<double>(first_non_finite_frame_) / sample_rate_hz()));
    }
    return frames;
}

AudioSource::FirstReading AudioSource::first_reading() const {
    return {frames_read_, non_finite_frames_, first_non_finite_frame_, lost_audio_};
}

void AudioSource::take_first_reading(FirstReading earlier) {
    non_finite_frames_ = earlier.non_finite_frames;
    first_non_finite_frame_ = earlier.first_non_finite_frame;
    // A stretch is noted as its silence is put before the frames read out: the earlier reading may
    // have noted one that reaches past where it stopped, which this reading notes again from there.
    lost_audio_ = std::move(earlier.lost_audio);
    taken_until_frame_ = earlier.frames_read;
}

bool AudioSource::skip_to(std::size_t frame) {
    if (frame <= frames_read_ || !seek_frames(frame)) return false;
    frames_read_ = frame;
    return true;
}

namespace {

// The first bytes of the file at `path`, enough to tell its container (is_sndfile_container).
// Throws FileError where it cannot be read, InvalidArgument where it is empty, ParseError where it
// is text (text_refused), before any size is judged: a few words are no recording cut short. A directory is
// refused before (open_audio_file's non_file_at), with what it is.
std::array<char, 12> read_container_header(const std::string& path) {
    std::array<char, 12> header{};
    std::ifstream probe(path, std::ios::binary | std::ios::ate);
    if (!probe) throw FileError(path, std::strerror(errno));
    const std::streamoff bytes = probe.tellg();
    if (bytes == 0) throw InvalidArgument(path, "empty file: no audio frames");
    // Text of any length is named as text (the transcript given as the recording), a few words too.
    if (const auto text = text_instead_of_audio(path)) throw text_refused(path, *text);
    // Every container's header is longer (a WAV's 44 bytes, an MP4's first box, Matroska's EBML
    // header): FFmpeg guessed at so few bytes, and called them an MP4 without its index.
    if (bytes < static_cast<std::streamoff>(header.size()))
        throw FileError(path, "truncated: the file holds only " + std::to_string(bytes) +
                                  (bytes == 1 ? " byte" : " bytes") +
                                  ", fewer than any recording's header; it was cut while it was copied "
                                  "or downloaded, or is not a recording");
    probe.seekg(0);
    errno = 0;
    probe.read(header.data(), static_cast<std::streamsize>(header.size()));
    // The file opened but its first read failed (EIO on a failing disk).
    if (probe.bad() || (probe.gcount() == 0 && errno != 0)) throw FileError(path, std::strerror(errno));
    return header;
}

// An Ogg file libsndfile refused to open (or would refuse: vorbis_headers_refused), FFmpeg's turn.
// An Ogg file whose header pages are damaged is refused by both, and said to be damaged there; one
// whose Opus header states no channel is refused by both too (FFmpeg found "no audio stream" in
// it, which hid the reason), and said so.
std::unique_ptr<AudioSource> open_ogg_refused_by_sndfile(const std::string& path) {
    if (opus_head_channels(path) == 0)
        throw ParseError(
            path, 0, 0, "",
            "its Opus header (OpusHead, the stream's first packet) states 0 channels, where an "
            "Opus stream has 1 or more: the header is damaged, and no sound can be read without it");
    FfmpegReading reading;
    if (const auto damage = find_damaged_ogg_page(path))
        reading.damaged_ogg_page_byte = damage->first_damaged_byte;
    return open_ffmpeg_file(path, reading);
}

// A file in a container libsndfile reads (`header` its first bytes) that libsndfile refused to open:
// FFmpeg's turn, but for a system error (FileError) and a WAV header that is broken (check_wav_header's
// ParseError).
std::unique_ptr<AudioSource> open_refused_by_sndfile(const std::string& path,
                                                     const std::array<char, 12>& header) {
    // sf_strerror(NULL) is libsndfile's process-global last error: read it before anything else
    // can open a file on this thread.
    const std::string reason = sf_strerror(nullptr);
    if (reason.find("System error") != std::string::npos) throw FileError(path, reason);
    if (std::string_view(header.data(), 4) == "RIFF") check_wav_header(path);
    // A container libsndfile knows holding a codec it does not (Opus in an old libsndfile): FFmpeg's
    // turn.
    if (std::string_view(header.data(), 4) == "OggS") return open_ogg_refused_by_sndfile(path);
    return open_ffmpeg_file(path);
}

// A file libsndfile opened (`file`, described by `info`; `header` its first bytes), read by libsndfile, or
// closed and given to FFmpeg where libsndfile misreads it: MPEG audio inside a WAV, an Ogg stream with a
// damaged page, a container that states no length, a data chunk stated as 0 bytes. Throws ParseError for a
// sample rate or channel count talkface does not read, FileError for a file cut short.
std::unique_ptr<AudioSource> open_opened_by_sndfile(const std::string& path,
                                                    const std::array<char, 12>& header, SNDFILE* file,
                                                    const SF_INFO& info) {
    if (!is_readable_format(info.samplerate, info.channels)) {
        sf_close(file);
        throw ParseError(path, 0, 0, "", unsupported_format_text("header", info.samplerate, info.channels));
    }
    // MPEG audio inside a WAV (a dictaphone's, a broadcast system's): libsndfile's length is the
    // same estimate as for a bare MP3's, and it called a whole file truncated 26 ms short of it;
    // FFmpeg reads it to its real end, as it does a bare MP3, but states no length for it, so a
    // data chunk cut short is told here.
    if (const int codec = info.format & SF_FORMAT_SUBMASK; codec == SF_FORMAT_MPEG_LAYER_I ||
                                                           codec == SF_FORMAT_MPEG_LAYER_II ||
                                                           codec == SF_FORMAT_MPEG_LAYER_III) {
        const auto data_bytes = data_bytes_if_truncated(file);
        const auto held = static_cast<std::size_t>(std::max<sf_count_t>(info.frames, 0));
        sf_close(file);
        if (data_bytes && !is_placeholder_size(data_bytes->stated))
            throw FileError(path,
                            "truncated: the header states " + std::to_string(data_bytes->stated) +
                                " bytes of MPEG sound (about " +
                                seconds_text(frames_promised_by(info, 0, *data_bytes), info.samplerate) +
                                ") but the file holds " + std::to_string(data_bytes->present) + " (about " +
                                seconds_text(held, info.samplerate) + ")");
        return open_ffmpeg_file(path);
    }
    // First: a damaged page can also hide the stream's last page from libsndfile's length.
    if ((info.format & SF_FORMAT_TYPEMASK) == SF_FORMAT_OGG) {
        if (const auto damage = find_damaged_ogg_page(path)) {
            sf_close(file);
            FfmpegReading reading;
            reading.keeps_stated_length = true;
            reading.overlong_ogg_page_byte = damage->overlong_page_byte;
            reading.damaged_ogg_page_byte = damage->first_damaged_byte;
            return open_ffmpeg_file(path, reading);
        }
        // libsndfile reads a chained file's first stream alone, and its length: the second recording
        // was lost without a word. FFmpeg reads on through every stream.
        if (ffmpeg_is_loadable() && chained_stream(path)) {
            sf_close(file);
            return open_ffmpeg_file(path);
        }
    }
    if (info.frames == SF_COUNT_MAX) {
        // libsndfile found no length: in an Ogg stream, no complete last page (the file was cut),
        // which FFmpeg would read as far as it goes and never call cut; another container that
        // states no length is FFmpeg's to read to its end.
        const bool is_ogg = (info.format & SF_FORMAT_TYPEMASK) == SF_FORMAT_OGG;
        sf_close(file);
        if (is_ogg)
            throw FileError(path, "truncated: the Ogg stream breaks off inside a page, before its end; the file "
                                  "was cut while it was copied or recorded");
        return open_ffmpeg_file(path);
    }
    if ((info.format & SF_FORMAT_SUBMASK) == SF_FORMAT_OPUS && ffmpeg_is_loadable()) {
        // Opus in Ogg (a phone's voice message, a browser recorder's): libsndfile's decoding, through
        // libopus at the rate the header names, took 25 s of CPU for 2 h of silence (8 times
        // FFmpeg's own decoder) and 1.1 s for 5 min of speech (3 times), and a long recording's
        // first reading decodes all of it; FFmpeg reads it as it reads Opus in Matroska or WebM,
        // once libsndfile has found it whole (a damaged page, a cut file, above). Without FFmpeg's
        // module libsndfile reads it, slower, rather than refuse a file it reads.
        sf_close(file);
        return open_ffmpeg_file(path);
    }
    auto promised = static_cast<std::size_t>(std::max<sf_count_t>(info.frames, 0));
    if (const auto data_bytes = data_bytes_if_truncated(file); data_bytes && !is_placeholder_size(data_bytes->stated))
        promised = std::max(promised, frames_promised_by(info, bytes_per_frame(info), *data_bytes));
    if (promised == 0) {
        // libsndfile reads nothing from a data chunk stated as 0 bytes, as a recorder stopped before
        // it closed the file leaves it; FFmpeg reads what follows to the end of the file, and
        // refuses a file with no sound after its header. libsndfile opens a WAV cut inside its data
        // chunk's header too (FFmpeg called it "Invalid data"): check_wav_header says it was cut.
        sf_close(file);
        if (std::string_view(header.data(), 4) == "RIFF") check_wav_header(path);
        return open_ffmpeg_file(path);
    }
    return std::make_unique<FileSource>(path, file, info, promised);
}

// A file in a container libsndfile reads (`header` its first bytes, past open_audio_file's checks of a
// WAV's chunks), read by libsndfile, or by FFmpeg where libsndfile refuses or misreads it.
std::unique_ptr<AudioSource> open_sndfile_container(const std::string& path,
                                                    const std::array<char, 12>& header) {
    if (std::string_view(header.data(), 4) == "OggS" && vorbis_headers_refused(path))
        return open_ogg_refused_by_sndfile(path);
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (file == nullptr) return open_refused_by_sndfile(path, header);
    return open_opened_by_sndfile(path, header, file, info);
}

}  // namespace

std::unique_ptr<AudioSource> open_audio_file(const std::string& path) {
    // A named pipe nothing writes to blocked the open below for ever; one that is written to gave
    // "Illegal seek", as a recording is read more than once (its first sound, then its features).
    if (const NonFile kind = non_file_at(path); kind == NonFile::directory)
        throw FileError(path, "a directory, not an audio file");
    else if (kind != NonFile::none)
        throw FileError(path,
                        describe(kind) +
                            ", not a file: talkface reads a recording more than once, which a pipe or a "
                            "device cannot give; save the sound to a file first");
    const std::array<char, 12> header = read_container_header(path);
    if (is_silk_voice_message(header))
        throw ParseError(
            path, 0, 0, "",
            "a voice message in SILK v3, the codec of WeChat's and QQ's voice messages, which talkface "
            "cannot decode (nor can FFmpeg); convert it to WAV or MP3 with a SILK v3 decoder first");
    if (const auto length = wrong_streaminfo_length(header))
        throw ParseError(path, 0, 0, "",
                         "the file is damaged: its FLAC header (STREAMINFO) states " +
                             std::to_string(*length) + " bytes, where FLAC's is 34");
    if (!is_sndfile_container(header)) return open_ffmpeg_file(path);
    if (std::string_view(header.data(), 4) == "RIFF") {
        if (const auto chunks = wav_data_chunks(path); chunks.size() > 1) {
            std::uint64_t total_bytes = 0;
            for (const auto& data : chunks) total_bytes += data.second;
            throw ParseError(path, 0, 0, "",
                             "its sound is in " + std::to_string(chunks.size()) +
                                 " data chunks (a second at byte " + std::to_string(chunks[1].first - 8) +
                                 "), where a WAV holds one: every reader takes the first (" +
                                 std::to_string(chunks[0].second) + " of " + std::to_string(total_bytes) +
                                 " bytes) and the speech after it would be lost; save the recording again "
                                 "as one WAV from the program that made it");
        }
        if (const auto stale = data_past_stated_size(path)) {
            FfmpegReading reading;
            reading.reads_past_stated_size = true;
            auto source = open_ffmpeg_file(path, reading);
            source->add_note(describe_stale_size(*stale));
            return source;
        }
    }
    auto source = open_sndfile_container(path, header);
    // libsndfile and FFmpeg alike stop at the first WAV's end (a data chunk that runs on past its
    // stated size is read to the file's end, above).
    if (std::string_view(header.data(), 4) == "RIFF")
        if (const auto past = bytes_past_riff_end(path)) source->add_note(describe_bytes_past_end(*past));
    return source;
}

std::string wav_codec_browsers_do_not_play(const std::string& path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (file == nullptr) return {};
    sf_close(file);
    const int type = info.format & SF_FORMAT_TYPEMASK;
    if (type != SF_FORMAT_WAV && type != SF_FORMAT_WAVEX && type != SF_FORMAT_RF64) return {};
    switch (info.format & SF_FORMAT_SUBMASK) {
        case SF_FORMAT_PCM_U8: case SF_FORMAT_PCM_S8: case SF_FORMAT_PCM_16: case SF_FORMAT_PCM_24:
        case SF_FORMAT_PCM_32: case SF_FORMAT_FLOAT: case SF_FORMAT_ULAW: case SF_FORMAT_ALAW:
            return {};
        default: break;
    }
    SF_FORMAT_INFO codec{};
    codec.format = info.format & SF_FORMAT_SUBMASK;
    if (sf_command(nullptr, SFC_GET_FORMAT_INFO, &codec, sizeof codec) != 0 || codec.name == nullptr)
        return "codec " + std::to_string(codec.format);
    return codec.name;
}

std::unique_ptr<AudioSource> open_audio_view(const AudioView& audio) {
    if (audio.frame_count == 0) throw InvalidArgument("audio.frame_count", "empty audio: no frames");
    if (audio.samples == nullptr) throw InvalidArgument("audio.samples", "null, with " + std::to_string(audio.frame_count) + " frames");
    if (audio.channel_count <= 0 || audio.channel_count > kMaxChannels)
        throw InvalidArgument("audio.channel_count", "expected 1.." + std::to_string(kMaxChannels) + ", found " +
                                                         std::to_string(audio.channel_count));
    if (audio.sample_rate_hz < kMinSampleRateHz || audio.sample_rate_hz > kMaxSampleRateHz)
        throw InvalidArgument("audio.sample_rate_hz", "expected " + std::to_string(kMinSampleRateHz) + ".." +
                                                          std::to_string(kMaxSampleRateHz) + ", found " +
                                                          std::to_string(audio.sample_rate_hz));
    return std::make_unique<ViewSource>(audio);
}

}  // namespace talkface::detail
