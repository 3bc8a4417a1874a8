// The audio book (thesis 7.3): the title, the text with the sentence being spoken highlighted, the
// links, and the talking face beside them. Link URLs were checked by build_web_page(). Each
// sentence carries its times, so the page's script highlights it while it is spoken, keeps it in
// view, and a click on it (or Enter) seeks the audio there.
//
// Layout: one column on a phone, the face and the player first and held at the top of the screen
// while the text scrolls under them (a reader deep in the book still sees the face talk); from
// 820 px on, and on a phone turned on its side, the text on the left and the face beside it, held
// in view the same way.
#include <string>

#include "apps/apps.hpp"
#include "apps/packed_animation.hpp"
#include "apps/page_fonts.hpp"
#include "common/number_format.hpp"
#include "render/html_text.hpp"

namespace talkface::detail {

namespace {

// Keeps the sentence being spoken in view: when it changes and lies outside the part of the window
// that the held face leaves free, it is scrolled to a third of the way down that part. Not while
// the reader scrolls by hand (for 4 s after a wheel, touch or scroll key), so reading ahead works.
constexpr const char* kFollowScript = R"js((function () {
  "use strict";
  var teacher = document.querySelector(".tf-teacher");
  var handScrolledAt = -1e9;
  ["wheel", "touchmove"].forEach(function (name) {
    window.addEventListener(name, function () { handScrolledAt = Date.now(); }, { passive: true });
  });
  window.addEventListener("keydown", function (event) {
    if (["PageUp", "PageDown", "Home", "End"].indexOf(event.key) >= 0) handScrolledAt = Date.now();
  });
  function keep_in_view(sentence) {
    if (!sentence || Date.now() - handScrolledAt < 4000) return;
    var box = sentence.getBoundingClientRect();
    var held = window.getComputedStyle(teacher).position === "sticky" && teacher.getBoundingClientRect().bottom < window.innerHeight / 2;
    var top = held && teacher.getBoundingClientRect().left < box.right && teacher.getBoundingClientRect().right > box.left
      ? teacher.getBoundingClientRect().bottom : 0;
    if (box.top >= top + 8 && box.bottom <= window.innerHeight - 8) return;
    window.scrollTo(0, window.scrollY + box.top - top - (window.innerHeight - top) / 3);
  }
  // The text is one stop on the Tab key's way, the sentence being spoken (the first before any):
  // with a stop at every sentence, a keyboard user passed 417 of them to reach the links after a
  // 30-minute book. The arrows move from sentence to sentence (the page's script).
  function hold_tab_stop(sentence) {
    var stop = document.querySelector('.tf-sentence[tabindex="0"]');
    if (!sentence || sentence === stop) return;
    if (stop) stop.tabIndex = -1;
    sentence.tabIndex = 0;
  }
  hold_tab_stop(document.querySelector(".tf-sentence.tf-current"));
  document.addEventListener("tf-sentence", function (event) {
    hold_tab_stop(event.detail.element);
    keep_in_view(event.detail.element);
  });
  // The room below the text lets its last sentence scroll up to where a reader follows it; a book
  // that fits the window whole needs none, and with it scrolled (49 px with three sentences on a
  // 390x844 phone) to show nothing more.
  var book = document.querySelector(".tf-book");
  function fit_room() {
    var room = book.classList.contains("tf-fits") ? 0 : parseFloat(window.getComputedStyle(book).paddingBottom);
    book.classList.toggle("tf-fits", document.documentElement.scrollHeight - room <= window.innerHeight);
  }
  fit_room();
  window.addEventListener("resize", fit_room);
  // Until the document's load event the page is not laid out as it will be, and a scroll made then
  // may come to nothing (a link to a time deep in the book, opened, stayed at the top): again then.
  window.addEventListener("load", function () {
    fit_room();
    keep_in_view(document.querySelector(".tf-sentence.tf-current"));
  });
})();
)js";

}  // namespace

PageParts audiobook_page(const std::string& animation_svg, const Timeline& timeline, const WebPageOptions& options,
                         const std::string& title, const std::string& audio_element) {
    std::string text;
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const Sentence& sentence = timeline.sentences[k];
        if (k == 0 || sentence.starts_paragraph) {
            if (k > 0) text += "\n</p>\n";
            text += "<p class=\"tf-paragraph\">\n";
        }
        text += "<span class=\"tf-sentence\" tabindex=\"" + std::string(k == 0 ? "0" : "-1") +
                "\" data-index=\"" + std::to_string(k) + "\" data-start=\"" +
                format_fixed(sentence.start_s, 3) + "\" data-end=\"" + format_fixed(sentence.end_s, 3) +
                "\">" + escape_html(sentence.text) + "</span>";  // no space between: Chinese sets none
    }
    if (!timeline.sentences.empty()) text += "\n</p>\n";
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

    // The face's column from 820 px: 280-360 px, or a quarter of a wider window's width where its
    // height lets the face be that large (at 4K, 3840x2160 at DPR 1, held to 360 px, the face stood
    // a tenth of the width); the book wider by as much, so that the text keeps its column.
    const StageBox face = root_view_box(animation_svg);
    const std::string face_column =
        "max(360px,min(25vw,(100vh - 160px) * " + format_fixed(face.width / face.height, 4) + " + 24px))";
    PageParts parts;
    parts.style =
        std::string(
            ":root{color-scheme:light dark}body{margin:0;background:#f7f3ea;color:#2b2b2b;font-family:") +
        kSerifFonts +
        "}"
        ".tf-book{display:grid;grid-template-columns:minmax(0,1fr);gap:0 40px;max-width:1180px;margin:0 auto;"
        "padding:0 16px 40vh}"
        ".tf-reader h1{font-family:" +
        kSansFonts +
        ";font-size:1.5rem;margin:16px 0 12px;border-bottom:2px solid #d6c9a8;padding-bottom:8px}"
        ".tf-text{font-size:1.2rem;line-height:1.95}"
        ".tf-paragraph{margin:0 0 .9em;text-indent:2em}"
        ".tf-sentence{cursor:pointer;border-radius:4px;padding:2px 1px;transition:background .15s}"
        ".tf-sentence:hover{background:#efe6cf}"
        ".tf-sentence.tf-current{background:#ffd95e;box-shadow:0 0 0 2px #ffd95e}"
        // The page's focus ring (web_page.cpp) sits outside the highlight: both show on one sentence.
        ".tf-sentence:focus-visible{outline-offset:4px;border-radius:4px}"
        ".tf-links h2{font-family:" +
        kSansFonts +
        ";font-size:1rem;margin:32px 0 8px;color:#6b5e3e}"
        ".tf-links ul{margin:0;padding-left:1.2em}.tf-links a{color:#1d4ed8}"
        // Phone first: the face and the player held at the top, at most 40% of the screen's height.
        ".tf-teacher{position:sticky;top:0;z-index:1;margin:0 -16px;padding:8px 16px;background:#fffdf8;"
        "box-shadow:0 2px 10px #0002}"
        ".tf-teacher svg.tf-animation{display:block;height:calc(40vh - 70px);max-height:420px;width:auto;"
        "max-width:100%;margin:0 auto;border-radius:8px}"
        "audio{display:block;width:100%;height:44px;margin-top:6px}"
        ".tf-keys{font-family:" +
        kSansFonts +
        ";font-size:.8rem;color:#6b5e3e;margin:4px 0 0;text-align:center}"
        "kbd{border:1px solid #c9bb97;border-radius:3px;padding:0 4px;background:#fff}"
        // From 820 px, or on a phone turned on its side (where the phone's layout left the face 58 px
        // high on 568x320), the text on the left and the face beside it.
        "@media (min-width:820px),(orientation:landscape) and (min-width:560px){"
        ".tf-book{grid-template-columns:minmax(0,1fr) minmax(280px," +
        face_column + ");max-width:calc(820px + " + face_column +
        ");padding:24px 24px 30vh}"
        ".tf-reader{grid-column:1;grid-row:1}"
        ".tf-teacher{grid-column:2;grid-row:1;top:16px;align-self:start;margin:16px 0 0;border-radius:12px;"
        "padding:12px;box-shadow:0 2px 12px #0002}"
        ".tf-teacher svg.tf-animation{height:auto;width:100%;max-height:calc(100vh - 160px)}"
        ".tf-reader h1{font-size:2rem;margin:16px 0 24px}"
        ".tf-text{font-size:1.35rem;line-height:2.1;max-width:38em}"
        "}"
        "@media (orientation:landscape) and (min-width:560px) and (max-width:819px){"
        ".tf-book{grid-template-columns:minmax(0,1fr) minmax(180px,38%);gap:0 20px;padding:8px 12px 30vh}"
        ".tf-teacher{top:8px;margin-top:8px;padding:8px}"
        ".tf-teacher svg.tf-animation{max-height:calc(100vh - 130px)}"
        ".tf-reader h1{font-size:1.4rem;margin:8px 0 12px}"
        ".tf-text{font-size:1.2rem;line-height:1.95}"
        "}"
        // A reader's dark scheme (the page was white at night): the paper dark, the spoken sentence
        // marked in a dark amber under light text, the face keeping its own colours as a picture does.
        "@media screen and (prefers-color-scheme:dark){body{background:#1c1a16;color:#e7e0cf}"
        ".tf-reader h1{border-bottom-color:#4d4535}.tf-sentence:hover{background:#3a3428}"
        ".tf-sentence.tf-current{background:#7a5c10;color:#fff8e6;box-shadow:0 0 0 2px #7a5c10}"
        ".tf-teacher{background:#28251f;box-shadow:0 2px 12px #0009}.tf-links h2,.tf-keys{color:#c2b48f}"
        ".tf-links a{color:#93c5fd}kbd{background:#2f2b24;border-color:#5e5442}}"
        // High contrast (Windows' contrast themes, forced colours) replaces every background with the
        // theme's: the sentence being spoken was no longer told from the rest. The theme's own
        // highlight colours mark it, as they mark selected text.
        "@media (forced-colors:active){.tf-sentence.tf-current{forced-color-adjust:none;background:Highlight;"
        "color:HighlightText;box-shadow:none}}"
        ".tf-book.tf-fits{padding-bottom:0}"
        // A phone has no keys to press: no hint of them where the only pointer is a finger.
        "@media (hover:none) and (pointer:coarse){.tf-keys{display:none}}"
        // On paper: the text, without the keys' hint and the room left to scroll the last sentence up.
        "@media print{.tf-keys{display:none}.tf-book{padding-bottom:0}}";
    parts.body = "<main class=\"tf-book\">\n<aside class=\"tf-teacher\">\n" + animation_svg + audio_element +
                 "<p class=\"tf-keys\"><kbd>Space</kbd> play / pause &#183; <kbd>&#8592;</kbd> <kbd>&#8594;</kbd> "
                 "sentence</p>\n</aside>\n<article class=\"tf-reader\">\n<h1>" +
                 escape_html(title) + "</h1>\n<div class=\"tf-text\">\n" + text + "</div>\n" + links +
                 "</article>\n</main>\n";
    parts.script = kFollowScript;
    return parts;
}

}  // namespace talkface::detail
