#include "common/input_file.hpp"

#include <sys/stat.h>

namespace talkface::detail {

NonFile non_file_at(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return NonFile::none;
    if (S_ISDIR(status.st_mode)) return NonFile::directory;
    if (S_ISFIFO(status.st_mode)) return NonFile::pipe;
    if (S_ISSOCK(status.st_mode)) return NonFile::socket;
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) return NonFile::device;
    return NonFile::none;
}

std::string describe(NonFile kind) {
    switch (kind) {
        case NonFile::directory:
            return "a directory";
        case NonFile::pipe:
            return "a named pipe (FIFO)";
        case NonFile::socket:
            return "a socket";
        case NonFile::device:
            return "a device";
        case NonFile::none:
            break;
    }
    return {};
}

}  // namespace talkface::detail
