// Names typed as a computer shows them, read as a tutorial's presenter reads them out (issue 13): a
// file's path (C:\Users\Admin 西冒号反斜杠 users 反斜杠 admin, /etc/hosts 斜杠 etc 斜杠 hosts), a name
// joined by underscores (a Wi-Fi's Home_5G, a handle's dance_2024: 下划线, its digits one by one) and a
// hexadecimal code (0x80070005 零 X 八零零七零零零五). Each is said as an address is (web_addresses.hpp):
// its marks as words, its runs of letters read by the caller, its digits one by one.
#ifndef TALKFACE_TEXT_TYPED_NAMES_HPP
#define TALKFACE_TEXT_TYPED_NAMES_HPP

#include <cstddef>
#include <optional>
#include <vector>

#include "text/code_points.hpp"
#include "text/web_addresses.hpp"

namespace talkface::detail {

// The typed name that starts at text[start], or nullopt: a Windows path (a drive's letter, :\ and
// names joined by \), a Unix path (two or more names, the first starting with a letter, each after a
// /, not right after a letter, a digit or a mark that joins them: km/h and 1/2 are no paths), a name
// of letters and digits joined by underscores (its first part two or more long and starting with a
// letter, so a face drawn as T_T and a formula's x_1 are none; nor one before an argument, log_3 9), or 0x
// and hexadecimal digits. A dot that no letter or digit follows is not the name's (it ends the sentence).
std::optional<WebAddress> read_typed_name(const std::vector<CodePoint>& text, std::size_t start);

}  // namespace talkface::detail

#endif
