// The audio book (thesis 7.3): the title, the text with the sentence being spoken highlighted, the
// links, and the talking face beside them. Link URLs were checked by build_web_page(). Each sentence carries its times, so the page's script
// highlights it while it is spoken and a click on it seeks the audio there.
#include <string>

#include "apps/apps.hpp"
#include "common/number_format.hpp"
#include "render/html_text.hpp"

namespace talkface::detail {

PageParts audiobook_page(const std::string& animation_svg, const Timeline& timeline, const WebPageOptions& options,
                         const std::string& title, const std::string& audio_element) {
    std::string text;
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const Sentence& sentence = timeline.sentences[k];
        text += "<span class=\"tf-sentence\" tabindex=\"0\" data-index=\"" + std::to_string(k) + "\" data-start=\"" +
                format_fixed(sentence.start_s, 3) + "\" data-end=\"" + format_fixed(sentence.end_s, 3) + "\">" +
                escape_html(sentence.text) + "</span>\n";
    }
    std::string links;
    if (!options.links.empty()) {
        links = "<nav class=\"tf-links\"><h2>Links</h2><ul>\n";
        for (std::size_t k = 0; k < options.links.size(); ++k) {
            const WebLink& link = options.links[k];
            links += "<li><a href=\"" + escape_html(percent_encode_url(link.url)) + "\">" +
                     escape_html(link.text.empty() ? link.url : link.text) + "</a></li>\n";
        }
        links += "</ul></nav>\n";
    }

    PageParts parts;
    parts.style =
        "body{margin:0;background:#f7f3ea;color:#2b2b2b;font-family:\"Noto Serif CJK TC\",\"Noto Serif CJK SC\","
        "serif}"
        ".tf-book{display:flex;flex-wrap:wrap;gap:32px;max-width:1080px;margin:0 auto;padding:32px 24px}"
        ".tf-reader{flex:1 1 420px;min-width:280px}"
        ".tf-reader h1{font-size:2rem;margin:0 0 24px;border-bottom:2px solid #d6c9a8;padding-bottom:12px}"
        ".tf-text{font-size:1.35rem;line-height:2.1;margin:0}"
        ".tf-sentence{cursor:pointer;border-radius:4px;padding:2px 1px;transition:background .15s}"
        ".tf-sentence:hover{background:#efe6cf}"
        ".tf-sentence.tf-current{background:#ffd95e;box-shadow:0 0 0 2px #ffd95e}"
        ".tf-links h2{font-size:1rem;margin:32px 0 8px;color:#6b5e3e}"
        ".tf-links ul{margin:0;padding-left:1.2em}.tf-links a{color:#1d4ed8}"
        ".tf-teacher{flex:0 0 320px;position:sticky;top:16px;align-self:flex-start;background:#fff;"
        "border-radius:12px;padding:12px;box-shadow:0 2px 12px #0002}"
        ".tf-teacher svg.tf-animation{display:block;width:100%;height:auto;border-radius:8px}"
        "audio{display:block;width:100%;margin-top:10px}";
    parts.body = "<main class=\"tf-book\">\n<article class=\"tf-reader\">\n<h1>" + escape_html(title) +
                 "</h1>\n<p class=\"tf-text\">\n" + text + "</p>\n" + links + "</article>\n<aside class=\"tf-teacher\">\n" +
                 animation_svg + audio_element + "</aside>\n</main>\n";
    return parts;
}

}  // namespace talkface::detail
