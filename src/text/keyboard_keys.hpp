// Keys of a keyboard shortcut as a tutorial's presenter says them (issue 13): Ctrl+C control 加 C, ⌘+空格
// command 加空格, Shift+⌘+4 shift 加 command 加四. The conventions are in docs/written-forms.md.
#ifndef TALKFACE_TEXT_KEYBOARD_KEYS_HPP
#define TALKFACE_TEXT_KEYBOARD_KEYS_HPP

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// The English word a key's sign on a Mac's keyboard stands for (⌘ command, ⌥ option, ⇧ shift, ⌃
// control), empty for any other code point.
std::string_view key_sign_word(char32_t c);

// The English word a key's written short name stands for, any case: Ctrl control always, Cmd command
// only in a shortcut (a + beside it, or 键 after it: 输入cmd is the program, C M D). nullopt for any other.
std::optional<std::string_view> key_name_word(const std::vector<CodePoint>& text, std::size_t start,
                                              std::size_t end);

// A + at text[i] between two keys of a shortcut, said 加: a key's sign on either side (⌘+C, Shift+⌘,
// ⌘+空格), or a modifier's name (Ctrl Shift Alt Cmd Win Fn Option) before it and a key after (Shift+4,
// which a signed number's reader would say 正四).
bool joins_shortcut_keys(const std::vector<CodePoint>& text, std::size_t i);

}  // namespace talkface::detail

#endif
