#include "text/shots_made.hpp"

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

bool follows_attempts(std::string_view before_run, std::string_view number) {
    if (number.empty() || before_run.size() < number.size() ||
        before_run.substr(before_run.size() - number.size()) != number) {
        return false;
    }
    before_run.remove_suffix(number.size());
    constexpr std::string_view kAttempts[] = {"投", "罚", "罰"};
    for (const auto attempts : kAttempts) {
        if (before_run.size() <= attempts.size() ||
            before_run.substr(before_run.size() - attempts.size()) != attempts) {
            continue;
        }
        before_run.remove_suffix(attempts.size());
        const auto characters = decode_utf8(before_run, "<text>");
        return !characters.empty() && is_ascii_digit(ascii_form(characters.back().value));
    }
    return false;
}

std::string_view shots_made_reading(const std::vector<std::string>& words, std::size_t w,
                                    bool after_attempts) {
    return after_attempts && w == 0 && !words.empty() && words[0] == "中" ? "zhong4" : "";
}

}  // namespace talkface::detail
