#include "common/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/input_file.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

std::string os_reason(int error_number) { return std::strerror(error_number); }

// Closes a descriptor on every way out of the scope that opened it, a refusal's throw among them.
class DescriptorCloser {
public:
    explicit DescriptorCloser(int fd) : fd_(fd) {}
    ~DescriptorCloser() { ::close(fd_); }
    DescriptorCloser(const DescriptorCloser&) = delete;
    DescriptorCloser& operator=(const DescriptorCloser&) = delete;

private:
    int fd_;
};

// How long a pipe may keep its first byte: a process substitution's command (talkface align a.wav
// <(opencc -i t.txt)) has its writer open at once, a named pipe nothing writes to never has one.
constexpr int kPipeWaitMs = 10000;

// Reads a pipe or a socket to its end, refusing one that gives nothing, not even its end, in
// kPipeWaitMs: opened without waiting for a writer, then polled.
std::string read_pipe(const std::string& path, const std::string& what) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK);
    if (fd < 0) throw FileError(path, "cannot open: " + os_reason(errno));
    const DescriptorCloser closer(fd);
    pollfd ready{fd, POLLIN, 0};
    if (::poll(&ready, 1, kPipeWaitMs) <= 0) {
        throw FileError(path, "cannot read: " + what + " that nothing wrote to in " +
                                  std::to_string(kPipeWaitMs / 1000) +
                                  " s; give talkface the file itself, or start what writes the pipe first");
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::string text;
    char buffer[1 << 16];
    for (ssize_t got; (got = ::read(fd, buffer, sizeof buffer)) != 0;) {
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw FileError(path, "cannot read: " + os_reason(errno));
        text.append(buffer, static_cast<std::size_t>(got));
    }
    return text;
}

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
    // A device (a terminal's /dev/stdin) is read as a file is: waiting on it is what was asked.
    const NonFile kind = non_file_at(path);
    if (kind == NonFile::directory) throw FileError(path, "cannot read: a directory, not a file");
    if (kind == NonFile::pipe || kind == NonFile::socket) return read_pipe(path, describe(kind));
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot open: " + os_reason(errno != 0 ? errno : ENOENT));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw FileError(path, "cannot read: " + os_reason(errno));
    return buffer.str();
}

}  // namespace talkface::detail
