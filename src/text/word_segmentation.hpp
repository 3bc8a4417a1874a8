// A run of Chinese characters cut into words, so that each polyphonic character is read by the
// word it stands in. The likeliest cut wins (a unigram model: the words' probabilities
// multiplied), not the longest word at each place: in 亿人参加 the longest match takes 人参
// (ren2 shen1) where 人 参加 (can1 jia1) is meant, and matching from the end breaks 首都是.
#ifndef TALKFACE_TEXT_WORD_SEGMENTATION_HPP
#define TALKFACE_TEXT_WORD_SEGMENTATION_HPP

#include <cstddef>
#include <string_view>
#include <vector>

#include "text/reading_tables.hpp"

namespace talkface::detail {

// The length in characters of each word of the cut of `characters` (each one UTF-8 character)
// whose words' costs (ReadingTables::word; a character the list lacks costs
// unknown_character_cost()) add up lowest; among equal cuts, the one with the longer last word.
// `ends_clause`: a pause or end mark follows the run, or it ends the text (aspect_particle.hpp:
// the idioms said so only at a clause's end).
std::vector<std::size_t> likeliest_words(const std::vector<std::string_view>& characters,
                                         const ReadingTables& tables, bool ends_clause);

}  // namespace talkface::detail

#endif
