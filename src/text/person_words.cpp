#include "text/person_words.hpp"

#include <algorithm>
#include <iterator>

namespace talkface::detail {

bool is_person_word(std::string_view word) {
    constexpr std::string_view kPersons[] = {"我",   "你",   "他",   "她",   "它",   "您",
                                             "我们", "你们", "他们", "她们", "我們", "你們",
                                             "他們", "她們", "咱们", "咱們", "人家", "大家"};
    return std::find(std::begin(kPersons), std::end(kPersons), word) != std::end(kPersons);
}

}  // namespace talkface::detail
