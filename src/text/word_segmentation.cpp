#include "text/word_segmentation.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "text/aspect_particle.hpp"

namespace talkface::detail {

std::vector<std::size_t> likeliest_words(const std::vector<std::string_view>& characters,
                                         const ReadingTables& tables, bool ends_clause) {
    const auto count = characters.size();
    // Viterbi over the places between characters: best_cost[end] is the cheapest cut of the
    // first `end` characters, whose last word starts at word_start[end].
    constexpr long long kUnreached = std::numeric_limits<long long>::max();
    std::vector<long long> best_cost(count + 1, kUnreached);
    std::vector<std::size_t> word_start(count + 1, 0);
    best_cost[0] = 0;
    std::string word;
    for (std::size_t end = 1; end <= count; ++end) {
        const auto longest = std::min(end, std::max<std::size_t>(tables.longest_word_characters(), 1));
        for (auto start = end - longest; start < end; ++start) {
            word.clear();
            for (auto k = start; k < end; ++k) word += characters[k];
            if (!may_start_word_here(characters, start, end, tables, ends_clause)) continue;
            const auto found = tables.word(word);
            long long cost = 0;
            if (found) {
                cost = found->cost;
            } else if (end - start == 1) {
                cost = tables.unknown_character_cost();
            } else {
                continue;
            }
            if (best_cost[start] + cost < best_cost[end]) {
                best_cost[end] = best_cost[start] + cost;
                word_start[end] = start;
            }
        }
    }
    std::vector<std::size_t> lengths;
    for (auto end = count; end > 0; end = word_start[end]) lengths.push_back(end - word_start[end]);
    std::reverse(lengths.begin(), lengths.end());
    return lengths;
}

}  // namespace talkface::detail
