// The demo's speech and transcript (samples/speech/demo.ogg and demo.txt), compiled into the
// `talkface` command by embed_files.cmake, so `talkface demo` works from the build tree and from
// any install with no data file to find.
#ifndef TALKFACE_CLI_EMBEDDED_DEMO_HPP
#define TALKFACE_CLI_EMBEDDED_DEMO_HPP

#include <cstddef>

namespace talkface_cli {

struct EmbeddedFile {
    const unsigned char* bytes;
    std::size_t size;
};

EmbeddedFile demo_speech();      // Ogg Vorbis, about 11 s of Mandarin
EmbeddedFile demo_transcript();  // its transcript, UTF-8, three sentences

}  // namespace talkface_cli

#endif
