// What an input path names when it is no file: a directory, a named pipe, a socket or a device
// given where a recording, a transcript or a face is expected. A directory opened as a stream read
// as an empty transcript, and a named pipe that nothing writes to blocked its open for ever.
#ifndef TALKFACE_COMMON_INPUT_FILE_HPP
#define TALKFACE_COMMON_INPUT_FILE_HPP

#include <string>

#include "talkface/export.h"

// Exported for talkface's own programs and libraries, as atomic_file.hpp's helpers: not API.
namespace talkface::detail {

enum class NonFile { none, directory, pipe, socket, device };

// What `path` names if it is no regular file; none for a file, or for a path that cannot be looked
// at (its open says why).
TALKFACE_API NonFile non_file_at(const std::string& path);

// "a directory", "a named pipe (FIFO)", "a socket", "a device"; empty for none.
TALKFACE_API std::string describe(NonFile kind);

}  // namespace talkface::detail

#endif
