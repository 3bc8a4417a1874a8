// Output files are written whole or not at all: a temporary file beside the target, renamed over it.
#ifndef TALKFACE_COMMON_ATOMIC_FILE_HPP
#define TALKFACE_COMMON_ATOMIC_FILE_HPP

#include <string>
#include <string_view>

#include "talkface/export.h"

// Exported from libtalkface though not in its installed headers, for talkface's own programs and
// libraries (the command, talkface::photo), so each does not compile a copy: not API, may change.
namespace talkface::detail {

// Writes `content` to `path` atomically. On failure the temporary file is removed, `path` is left
// as it was, and talkface::FileError names the path and the OS reason.
TALKFACE_API void write_file_atomically(const std::string& path, std::string_view content);

// Reads a whole file, or a pipe to its end (a process substitution's). Throws talkface::FileError
// naming the path and the OS reason, or a directory, or a pipe that gave nothing in 10 s.
TALKFACE_API std::string read_file(const std::string& path);

}  // namespace talkface::detail

#endif
