// A show's season and episode as subtitle files, download lists and fans write them (S3E5, S01E10), read
// as presenters say them, in the Chinese words the letters abbreviate: 第三季第五集 (issue 13; session 34:
// the letters and the digits, ai si 三 yi 五).
#ifndef TALKFACE_TEXT_EPISODE_CODES_HPP
#define TALKFACE_TEXT_EPISODE_CODES_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "text/code_points.hpp"
#include "text/written_numbers.hpp"

namespace talkface::detail {

// An S, one or two digits, an E and one to three digits at text[start] (either case; leading zeros
// not said), standing alone: no letter or digit on either side (S3E5是, 《老友记》S01E10); said
// 第 the season 季第 the episode 集. nullopt elsewhere (PS5, S3E, S3E5X).
std::optional<SpokenForm> read_season_episode(const std::vector<CodePoint>& text, std::size_t start);

}  // namespace talkface::detail

#endif
