// E-mail and web addresses (zhangwei@163.com, www.gov.cn, https://example.com/news) and the @
// of a mention, read as Mandarin speakers say them (issue 13): @ 艾特, a dot 点, a hyphen 杠, an
// underscore 下划线, a slash 斜杠; the scheme (https://) is not said. The conventions are in
// docs/written-forms.md.
#ifndef TALKFACE_TEXT_WEB_ADDRESSES_HPP
#define TALKFACE_TEXT_WEB_ADDRESSES_HPP

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/code_points.hpp"

namespace talkface::detail {

// A piece of an address as it is said: Chinese words (点, 艾特), a run of Latin letters (read as
// a word, pinyin or letter by letter by the caller), or digits (said one by one).
struct AddressPart {
    enum class Kind { words, letters, digits };
    Kind kind = Kind::words;
    std::string text;
};

struct WebAddress {
    std::size_t end = 0;  // index past the address in the code points
    std::vector<AddressPart> parts;
};

// The address that starts at text[start] (width-folded code points), or nullopt: an e-mail
// address (a name, @, a host of two or more labels), a web address (a scheme and a host, or a
// host starting with www or ending with a common top-level domain such as com, cn, org), a file's
// or a library's dotted name (index.html, Node.js: a suffix such as html, js, pdf), or a lone @
// before a name (a mention: @新华社). A dot that ends a sentence after the address is not taken.
std::optional<WebAddress> read_web_address(const std::vector<CodePoint>& text, std::size_t start);

// The letters, digits and marks of text[first, end) as an address says them: each run of letters or of
// digits a part, a mark its words (. 点, @ 艾特, - 杠, _ 下划线, / 斜杠, + 加).
void append_address_parts(std::vector<AddressPart>& parts, const std::vector<CodePoint>& text,
                          std::size_t first, std::size_t end);

// True for the suffix of a stock exchange after a code, in capitals (HK Hong Kong; SH and SS
// Shanghai; SZ Shenzhen; BJ Beijing; TW and TWO Taiwan: 00700.HK, 600519.SH, 2330.TW): digits and
// such a suffix are a stock's code, no address (session 15).
bool is_exchange_suffix(std::string_view letters);

}  // namespace talkface::detail

#endif
