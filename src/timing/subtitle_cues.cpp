#include "timing/subtitle_cues.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "talkface/errors.hpp"
#include "timing/subtitle_time.hpp"

namespace talkface::detail {

std::vector<TextLine> text_lines(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::vector<TextLine> lines;
    int number = 1;
    std::size_t start = 0;
    for (std::size_t k = 0; k <= text.size(); ++k) {
        if (k < text.size() && text[k] != '\n' && text[k] != '\r') continue;
        lines.push_back({std::string(text.substr(start, k - start)), number++});
        if (k + 1 < text.size() && text[k] == '\r' && text[k + 1] == '\n') ++k;
        start = k + 1;
    }
    if (!lines.empty() && lines.back().text.empty()) lines.pop_back();
    return lines;
}

std::vector<std::vector<TextLine>> text_blocks(const std::vector<TextLine>& lines) {
    std::vector<std::vector<TextLine>> blocks;
    bool is_in_block = false;
    for (const TextLine& line : lines) {
        const bool is_blank = line.text.find_first_not_of(" \t") == std::string::npos;
        if (is_blank) {
            is_in_block = false;
            continue;
        }
        if (!is_in_block) blocks.emplace_back();
        blocks.back().push_back(line);
        is_in_block = true;
    }
    return blocks;
}

namespace {

bool read_cue_times(const std::string& line, char separator, double& start_s, double& end_s) {
    const std::size_t arrow = line.find(" --> ");
    if (arrow == std::string::npos) return false;
    const std::string_view after = std::string_view(line).substr(arrow + 5);
    const std::optional<double> start = parse_subtitle_time(std::string_view(line).substr(0, arrow), separator);
    const std::optional<double> end = parse_subtitle_time(after.substr(0, after.find_first_of(" \t")), separator);
    if (!start || !end) return false;
    start_s = *start;
    end_s = *end;
    return true;
}

}  // namespace

int read_cue_timing(const std::vector<TextLine>& block, std::size_t at, char separator, const std::string& source,
                    double& start_s, double& end_s) {
    if (at >= block.size() || !read_cue_times(block[at].text, separator, start_s, end_s)) {
        const TextLine& line = block[std::min(at, block.size() - 1)];
        const std::string time = std::string("HH:MM:SS") + separator + "mmm";
        throw ParseError(source, line.line, 0, "",
                         "expected a cue's times, " + time + " --> " + time + ", found \"" + line.text + "\"");
    }
    return block[at].line;
}

std::string without_markup(const std::string& text) {
    std::string out;
    for (std::size_t k = 0; k < text.size();) {
        const char closing = text[k] == '<' ? '>' : text[k] == '{' && text.compare(k, 2, "{\\") == 0 ? '}' : '\0';
        const std::size_t close = closing != '\0' ? text.find(closing, k) : std::string::npos;
        if (close != std::string::npos) {
            k = close + 1;
            continue;
        }
        if (text[k] == '&') {
            bool is_entity = false;
            for (const auto& [name, replacement] : {std::pair<const char*, const char*>{"&amp;", "&"},
                                                    {"&lt;", "<"}, {"&gt;", ">"}, {"&nbsp;", " "}}) {
                if (!is_entity && text.compare(k, std::char_traits<char>::length(name), name) == 0) {
                    out += replacement;
                    k += std::char_traits<char>::length(name);
                    is_entity = true;
                }
            }
            if (is_entity) continue;
        }
        out += text[k++];
    }
    return out;
}

}  // namespace talkface::detail
