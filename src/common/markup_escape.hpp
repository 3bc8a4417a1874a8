// Escaping text for markup: HTML, XML and WebVTT cue text share & < > and differ only in the quotes.
#ifndef TALKFACE_COMMON_MARKUP_ESCAPE_HPP
#define TALKFACE_COMMON_MARKUP_ESCAPE_HPP

#include <string>
#include <string_view>

namespace talkface::detail {

// What becomes of the quote characters; & < > always become &amp; &lt; &gt;.
enum class QuoteEscape {
    none,     // element text only (WebVTT cue text): quotes stay
    html,     // &quot; and &#39; (HTML has no &apos; before HTML5)
    xml,      // &quot; and &apos;, as Boost's property-tree writer (Rhubarb's XML) writes them
};

// `text` safe as markup text (and, with quotes escaped, inside a quoted attribute value).
std::string escape_markup(std::string_view text, QuoteEscape quotes);

}  // namespace talkface::detail

#endif
