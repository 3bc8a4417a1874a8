// A second recording's stream after the first's, in a container that lets one follow another
// (issue 13, "Bad input"): `cat a.ogg b.ogg` is a chained Ogg file, a legal one (an Internet radio
// stream chains its songs so), whose second logical stream opens with its own header pages; `cat
// a.webm b.webm` is a second EBML header and Segment where the first Segment's stated size ends.
// FFmpeg reads on through the second; libsndfile read a chained Vorbis file's first stream alone,
// and its second recording was lost without a word. Either way the text that fits the first was
// stretched over both, with no word of the join but "its header states 3.3 s of sound, the file
// holds 6.6 s" (the first stream's length, or the last page's).
#ifndef TALKFACE_AUDIO_CHAINED_STREAM_HPP
#define TALKFACE_AUDIO_CHAINED_STREAM_HPP

#include <cstdint>
#include <optional>
#include <string>

namespace talkface::detail {

// Where a second recording's stream starts: in which container, at which byte, and after how long a
// first stream as the file decodes (0 where not known): in an Ogg file of Vorbis or Opus, its last
// page's granule position; in a Matroska file, its sound track's last block's end; in a Matroska file,
// whether the first Segment's size is unknown (a live recording's).
struct ChainedStream {
    enum class Container { ogg, matroska };
    Container container = Container::ogg;
    std::uint64_t byte = 0;
    double first_seconds = 0.0;
    bool is_live_segment = false;
};

// The second stream of the file at `path`, if it opens as an Ogg file (a page beginning a logical
// stream after a page of sound: the streams of one recording, a video's picture and sound, all begin
// on its first pages) or a Matroska or WebM file (its first Segment's stated size ending at a second
// EBML header, or, a Segment of unknown size, its children followed by one). Reads the pages' headers
// only, or the first Segment's and its children's; nullopt for anything else.
std::optional<ChainedStream> chained_stream(const std::string& path);

}  // namespace talkface::detail

#endif
