#include "text/pinyin_tokens.hpp"

#include <algorithm>

#include "text/reading_tables.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

bool is_pinyin_letter(char32_t c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == 0xFC /*ü*/ || c == 0xDC /*Ü*/;
}

bool is_capital(char32_t c) {
    return (c >= 'A' && c <= 'Z') || c == 0xDC;
}

std::size_t end_of_token(const std::vector<CodePoint>& text, std::size_t start) {
    auto end = start;
    while (end < text.size()) {
        const auto c = text[end].value;
        const bool continues =
            is_pinyin_letter(c) || is_ascii_digit(c) ||
            (c == ':' && end > start && (text[end - 1].value == 'u' || text[end - 1].value == 'U')) ||
            (c == '\'' && end > start && end + 1 < text.size() && is_pinyin_letter(text[end + 1].value));
        if (!continues) break;
        ++end;
    }
    return end;
}

std::string latin_spelling(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    std::string spelling;
    for (auto k = start; k < end; ++k) {
        if (text[k].value < 0x80) {
            spelling += static_cast<char>(text[k].value);
        } else {
            spelling += text[k].text;
        }
    }
    return spelling;
}

std::optional<std::vector<WrittenSyllable>> split_pinyin(const std::vector<CodePoint>& token) {
    std::vector<WrittenSyllable> syllables;
    std::size_t part_start = 0;
    while (part_start <= token.size()) {
        std::size_t part_end = part_start;
        while (part_end < token.size() && token[part_end].value != '\'') ++part_end;
        const auto count = part_end - part_start;
        if (count == 0) return std::nullopt;
        auto written = [&](std::size_t from, std::size_t to) {
            std::string text;
            for (auto i = part_start + from; i < part_start + to; ++i) text += token[i].text;
            return text;
        };
        auto spelling = [&](std::size_t from, std::size_t to) {
            return latin_spelling(token, part_start + from, part_start + to);
        };
        // fewest[i]: fewest syllables spelling the part's code points from i on (count+1 = none).
        constexpr std::size_t kLongestSyllable = 7;  // "zhuang" + tone digit
        std::vector<std::size_t> fewest(count + 1, count + 1);
        fewest[count] = 0;
        for (std::size_t i = count; i-- > 0;) {
            for (std::size_t end = i + 1; end <= std::min(count, i + kLongestSyllable); ++end) {
                if (fewest[end] < fewest[i] - 1 && !detail::normalise_pinyin(spelling(i, end)).empty()) {
                    fewest[i] = fewest[end] + 1;
                }
            }
        }
        if (fewest[0] > count) return std::nullopt;
        for (std::size_t i = 0; i < count;) {
            for (std::size_t end = std::min(count, i + kLongestSyllable); end > i; --end) {
                auto pinyin = detail::normalise_pinyin(spelling(i, end));
                if (!pinyin.empty() && fewest[end] + 1 == fewest[i]) {
                    syllables.push_back({written(i, end), std::move(pinyin)});
                    i = end;
                    break;
                }
            }
        }
        part_start = part_end + 1;
    }
    return syllables;
}

bool looks_like_pinyin(const std::vector<CodePoint>& token) {
    bool has_tone = false;
    bool has_inner_capital = false;
    for (std::size_t i = 0; i < token.size(); ++i) {
        const auto c = token[i].value;
        has_tone = has_tone || is_ascii_digit(c);
        has_inner_capital = has_inner_capital || (is_capital(c) && i > 0 && token[i - 1].value != '\'');
    }
    return has_tone || !has_inner_capital;
}

bool starts_as_pinyin_only(std::string_view letters) {
    return starts_with_any(letters, {"xi", "xu", "qi", "zh"});
}

bool has_tone_digit(const std::vector<CodePoint>& token) {
    return std::any_of(token.begin(), token.end(),
                       [](const CodePoint& c) { return is_ascii_digit(c.value); });
}

bool splits_into_interjection(const std::vector<WrittenSyllable>& split) {
    constexpr std::string_view kInterjectionOnly[] = {"m", "n", "ng", "hm", "hng", "lo", "yo"};
    if (split.size() < 2) return false;
    return std::any_of(split.begin(), split.end(), [&](const WrittenSyllable& syllable) {
        const auto toneless = syllable.pinyin.substr(0, syllable.pinyin.size() - 1);
        return std::find(std::begin(kInterjectionOnly), std::end(kInterjectionOnly), toneless) !=
               std::end(kInterjectionOnly);
    });
}

}  // namespace talkface::detail
