#include "common/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

std::string os_reason(int error_number) { return std::strerror(error_number); }

}  // namespace

void write_file_atomically(const std::string& path, std::string_view content) {
    // mkstemp in the target's own directory, so the final rename never crosses file systems.
    std::string temp_path = path + ".tmp-XXXXXX";
    const int fd = ::mkstemp(temp_path.data());
    if (fd < 0) throw FileError(path, "cannot create a temporary file beside it: " + os_reason(errno));
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            const int saved = errno;
            ::close(fd);
            ::unlink(temp_path.c_str());
            throw FileError(path, "cannot write: " + os_reason(saved));
        }
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    // mkstemp creates 0600. Keep the mode of the file being replaced, else the usual 0644 (reading
    // the umask would need umask(), which changes it for every thread of the caller's process).
    struct stat existing {};
    ::fchmod(fd, ::stat(path.c_str(), &existing) == 0 ? (existing.st_mode & 07777) : 0644);
    if (::close(fd) != 0) {
        const int saved = errno;
        ::unlink(temp_path.c_str());
        throw FileError(path, "cannot write: " + os_reason(saved));
    }
    if (std::rename(temp_path.c_str(), path.c_str()) != 0) {
        const int saved = errno;
        ::unlink(temp_path.c_str());
        throw FileError(path, "cannot replace: " + os_reason(saved));
    }
}

std::string read_file(const std::string& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot open: " + os_reason(errno != 0 ? errno : ENOENT));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw FileError(path, "cannot read: " + os_reason(errno));
    return buffer.str();
}

}  // namespace talkface::detail
