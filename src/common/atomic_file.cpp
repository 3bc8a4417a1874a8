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

// A temporary file beside `target`, made by mkstemp in the target's own directory so that the rename
// that puts it in place never crosses file systems. Its descriptor is closed, and the file removed,
// on every way out but that rename, a throw among them: no error path can leave either behind.
class TemporaryFile {
public:
    explicit TemporaryFile(const std::string& target)
        : path_(target + ".tmp-XXXXXX"), fd_(::mkstemp(path_.data())) {
        if (fd_ < 0) throw FileError(target, "cannot create a temporary file beside it: " + os_reason(errno));
    }
    ~TemporaryFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!renamed_) ::unlink(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    int descriptor() const { return fd_; }

    // Closes the descriptor: 0, or -1 with errno set, since a file system may report a write's failure
    // only here (a full disk over NFS).
    int close() {
        const int result = ::close(fd_);
        fd_ = -1;
        return result;
    }

    // Renames the file over `target`: false, with errno set, where that fails.
    bool rename_over(const std::string& target) {
        renamed_ = std::rename(path_.c_str(), target.c_str()) == 0;
        return renamed_;
    }

private:
    std::string path_;
    int fd_;
    bool renamed_ = false;
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
    TemporaryFile temporary(path);
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ssize_t written = ::write(temporary.descriptor(), data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            throw FileError(path, "cannot write: " + os_reason(errno));
        }
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    // mkstemp creates 0600. Keep the mode of the file being replaced, else the usual 0644 (reading
    // the umask would need umask(), which changes it for every thread of the caller's process).
    struct stat existing {};
    ::fchmod(temporary.descriptor(),
             ::stat(path.c_str(), &existing) == 0 ? (existing.st_mode & 07777) : 0644);
    if (temporary.close() != 0) throw FileError(path, "cannot write: " + os_reason(errno));
    if (!temporary.rename_over(path)) throw FileError(path, "cannot replace: " + os_reason(errno));
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
