#include "text/episode_codes.hpp"

#include <string>

#include "text/number_words.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

std::optional<SpokenForm> read_season_episode(const std::vector<CodePoint>& text, std::size_t start) {
    const auto is_word_character = [](char32_t c) { return is_ascii_letter(c) || is_ascii_digit(c); };
    if (!is_one_of(value_at(text, start), U"Ss") || (start > 0 && is_word_character(text[start - 1].value)))
        return std::nullopt;
    auto k = start + 1;
    const auto season = digits_from(text, k);
    constexpr std::size_t kLongestSeason = 2;
    if (season.empty() || season.size() > kLongestSeason || !is_one_of(value_at(text, k), U"Ee"))
        return std::nullopt;
    ++k;
    const auto episode = digits_from(text, k);
    constexpr std::size_t kLongestEpisode = 3;
    if (episode.empty() || episode.size() > kLongestEpisode || is_word_character(value_at(text, k)))
        return std::nullopt;
    SpokenForm form;
    form.words = "第" + cardinal_words(season, false) + "季第" + cardinal_words(episode, false) + "集";
    form.end = k;
    return form;
}

}  // namespace talkface::detail
