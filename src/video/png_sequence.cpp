#include "video/png_sequence.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string_view>

#include <unistd.h>

#include "common/atomic_file.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Six digits: 9 hours at 30 frames per second, in name order.
constexpr int kDigits = 6;

std::string numbered_name(const std::string& stem, std::size_t index) {
    char number[32];
    std::snprintf(number, sizeof number, "-%0*zu.png", kDigits, index);
    return stem + number;
}

}  // namespace

std::string PngSequenceOutput::frame_path(const std::string& path, std::size_t index) {
    const std::filesystem::path target(path);
    return (target.parent_path() / numbered_name(target.stem().string(), index)).string();
}

PngSequenceOutput::PngSequenceOutput(const std::string& path) : path_(path) {
    const std::filesystem::path target(path);
    const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
    std::string pattern = (folder / ("." + target.stem().string() + ".tmp-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        throw FileError(path, std::string("cannot create a temporary folder beside it: ") + std::strerror(errno));
    }
    temp_folder_ = pattern;
}

PngSequenceOutput::~PngSequenceOutput() {
    if (temp_folder_.empty()) return;
    std::error_code ignored;
    std::filesystem::remove_all(temp_folder_, ignored);
}

void PngSequenceOutput::write_frame(const std::uint8_t* bytes, std::size_t size) {
    const std::string name = std::filesystem::path(frame_path(path_, frame_count_)).filename().string();
    write_file_atomically(temp_folder_ + "/" + name, std::string_view(reinterpret_cast<const char*>(bytes), size));
    ++frame_count_;
}

void PngSequenceOutput::finish() {
    for (std::size_t index = 0; index < frame_count_; ++index) {
        const std::string target = frame_path(path_, index);
        const std::string name = std::filesystem::path(target).filename().string();
        if (std::rename((temp_folder_ + "/" + name).c_str(), target.c_str()) != 0) {
            throw FileError(target, std::string("cannot move into place: ") + std::strerror(errno));
        }
    }
    ::rmdir(temp_folder_.c_str());
    temp_folder_.clear();
}

}  // namespace talkface::detail
