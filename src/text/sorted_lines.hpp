// A table of "key\tvalue" lines compiled into the library (embedded_text.hpp), sorted by key,
// searched in place. The reading tables hold 140 000 lines: hash maps of them cost a CLI call
// more to build and free (0.2 G instructions) than the whole of reading a short transcript, where
// an index of the lines costs a pass over the text.
#ifndef TALKFACE_TEXT_SORTED_LINES_HPP
#define TALKFACE_TEXT_SORTED_LINES_HPP

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "text/embedded_text.hpp"

namespace talkface::detail {

class SortedLines {
public:
    // Indexes the lines of `text`, which must be sorted by key in byte order: the generators in
    // tools/ sort their output (Python sorts strings by code point, UTF-8's byte order), and a test
    // checks every table, where checking at each start would cost a tenth of a short call's time.
    explicit SortedLines(EmbeddedText text);

    // Whether every key follows the one before it in byte order (what the binary search needs).
    bool keys_ascend() const;

    // The value after `key`'s tab ("" where its line has none), or nothing if no line has `key`.
    std::optional<std::string_view> find(std::string_view key) const;

    const std::vector<std::string_view>& lines() const { return lines_; }

    // The part of a line before its first tab, and the part after it.
    static std::string_view key_of(std::string_view line);
    static std::string_view value_of(std::string_view line);

private:
    std::vector<std::string_view> lines_;
};

// The words of `text` between `separator`s, empty ones skipped.
std::vector<std::string_view> split_words(std::string_view text, char separator = ' ');

}  // namespace talkface::detail

#endif
