// Two recordings joined into one file (a copy appended to itself, `cat` of two recordings, an
// upload that appends instead of replacing), told by the file's opening bytes recurring inside it,
// or by an MP3's second tag frame (issue 13, "Bad input"): a FLAC, Ogg, MP3 or Matroska file read on
// through the second copy as one recording, whose transcript was refused as not its speech with no
// word of why. A WAV and an MP4 say more of it (bytes_past_riff_end, second_file_byte: how much
// their readers left unread).
#ifndef TALKFACE_AUDIO_JOINED_COPY_HPP
#define TALKFACE_AUDIO_JOINED_COPY_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace talkface::detail {

// How many of a file's first bytes must recur: a container's signature, sizes and stream numbers
// (a FLAC's STREAMINFO, an Ogg page's serial number and CRC, Matroska's EBML header), which no sound
// inside a recording repeats.
constexpr std::size_t kOpeningBytes = 32;

// The first byte, kOpeningBytes or more from the start, where the first kOpeningBytes bytes of the
// file at `path` recur, in a file that opens with a header found once in a recording: FLAC's
// "fLaC", an Ogg stream's first page, Matroska's EBML header, an MP3's ID3 tag. nullopt where they
// do not, or the file opens otherwise: an MPEG transport stream repeats its tables, an untagged
// MP3 its frames of silence, byte for byte.
std::optional<std::uint64_t> repeated_opening_byte(const std::string& path);

// A second recording joined to a file: what the messages say of it, and, where the file tells it, the
// time of the decoded sound where the second begins (an Ogg file's first stream's end, a Matroska file's
// first Segment's sound's end, an MP3's restart, a repeat of the sound; not a join told only by bytes
// recurring where no stream's walk times it), so that digital silence opening the second recording is
// left to the join's message (silenced_words.hpp).
struct JoinedRecording {
    std::string description;
    std::optional<double> second_starts_s;
};

// "its first 32 bytes (its header) recur at byte 38334: a second copy of the recording ...": what a
// refusal of the text of the file at `path` says of a second recording joined to it, or nullopt: its
// opening bytes recurring (repeated_opening_byte), or a second FLAC stream's header, or, in an MP3, a second
// frame holding the Xing or Info tag an encoder writes once, in a recording's first frame (an MP3 with no ID3
// tag, or two recordings whose tags differ), or, where no bytes tell it, its decoded sound repeating itself
// to its end (repeated_sound: an MP3 with neither tag, as sox writes it, joined to itself), or an MP3 frame
// starting a second stream's bit reservoir afresh (restarted_mp3_stream: sox's MP3s of two recordings
// joined), or a second Ogg stream or Matroska Segment (chained_stream). Asked only where the text's fit
// is not vouched for (speech_aligner.cpp): the search reads the whole file (a 10 h FLAC is 1 GB), and a
// join read on as one recording shows as a text that does not fit it.
std::optional<JoinedRecording> describe_joined_copy(const std::string& path);

// What describe_joined_copy says of an MP3 whose frames start a second bit reservoir
// (restarted_mp3_stream), or of an Ogg or Matroska file whose second stream follows its first
// (chained_stream), or nullopt: the joins it tells by walking the frames', pages' or Segment's headers
// alone, without decoding (a 1 h MP3's 57 MB read in well under a second), so asked of every file that
// aligns as well: a text that fits the first recording is stretched over the second one too, or
// aligned over speech the transcript lacks (bench/README.md sessions 39 and 41).
std::optional<JoinedRecording> describe_second_stream(const std::string& path);

}  // namespace talkface::detail

#endif
