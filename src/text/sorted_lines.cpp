#include "text/sorted_lines.hpp"

#include <algorithm>

namespace talkface::detail {

SortedLines::SortedLines(EmbeddedText text) {
    std::size_t count = 0;
    for (std::size_t chunk = 0; chunk < text.chunk_count; ++chunk) {
        const std::string_view lines = text.chunks[chunk];
        count += static_cast<std::size_t>(std::count(lines.begin(), lines.end(), '\n'));
    }
    lines_.reserve(count);
    for (std::size_t chunk = 0; chunk < text.chunk_count; ++chunk) {
        const std::string_view lines = text.chunks[chunk];
        for (std::size_t start = 0; start < lines.size();) {
            const auto end = std::min(lines.find('\n', start), lines.size());
            if (end > start) lines_.push_back(lines.substr(start, end - start));
            start = end + 1;
        }
    }
}

std::optional<std::string_view> SortedLines::find(std::string_view key) const {
    const auto found = std::lower_bound(lines_.begin(), lines_.end(), key,
                                        [](std::string_view line, std::string_view k) { return key_of(line) < k; });
    if (found == lines_.end() || key_of(*found) != key) return std::nullopt;
    return value_of(*found);
}

bool SortedLines::keys_ascend() const {
    return std::adjacent_find(lines_.begin(), lines_.end(), [](std::string_view before, std::string_view after) {
               return !(key_of(before) < key_of(after));
           }) == lines_.end();
}

std::string_view SortedLines::key_of(std::string_view line) { return line.substr(0, line.find('\t')); }

std::string_view SortedLines::value_of(std::string_view line) {
    const auto tab = line.find('\t');
    return tab == std::string_view::npos ? std::string_view() : line.substr(tab + 1);
}

std::vector<std::string_view> split_words(std::string_view text, char separator) {
    std::vector<std::string_view> words;
    words.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), separator)) + 1);
    for (std::size_t start = 0; start <= text.size();) {
        const auto end = std::min(text.find(separator, start), text.size());
        if (end > start) words.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return words;
}

}  // namespace talkface::detail
