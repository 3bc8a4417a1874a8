// The virtual announcer (thesis 7.2): the talking face on a stage, in front of a background colour
// or picture, moved to any place and scaled to any size by its rotation origin and eye distance
// (7.2.3: "the location of cartoon faces can be easily changed" by moving the origin), framed as a
// news programme: a lower third with the title and the caption of the sentence being spoken.
//
// The stage is one box of the stage's proportions holding nothing but the frame (the controls sit
// under it), so that it can be recorded as a video as it is. The caption is HTML over the stage's
// SVG, so that a long sentence wraps and the system's CJK fonts are found as in any page.
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "apps/apps.hpp"
#include "apps/packed_animation.hpp"
#include "apps/page_fonts.hpp"
#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "render/announcer_layout.hpp"
#include "render/html_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

std::string number(double value) {
    return format_fixed(value, 2);
}

// The length of UTF-8 `text` in UTF-16 code units, as a script counts a string's characters.
std::size_t utf16_length(std::string_view text) {
    std::size_t units = 0;
    for (const char byte : text) {
        const auto lead = static_cast<unsigned char>(byte);
        if ((lead & 0xC0) != 0x80) units += lead >= 0xF0 ? 2 : 1;
    }
    return units;
}

// Where each syllable stands in its sentence's text, and when it starts, per sentence: "OFFSET
// TIME" pairs (OFFSET in UTF-16 code units, as the page's script reads the sentence's text), for
// the caption to show the line being said. A written form's syllables ("2026" said in four) stand
// at the form; a syllable whose text the sentence does not show as such is left out, and the one
// before it stands for it.
std::vector<std::string> syllable_marks(const Timeline& timeline) {
    std::vector<std::string> marks(timeline.sentences.size());
    std::vector<std::size_t> cursors(timeline.sentences.size(), 0);
    std::size_t form = 0;
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        const Syllable& syllable = timeline.syllables[k];
        const std::vector<WrittenForm>& forms = timeline.written_forms;
        while (form < forms.size() && forms[form].first_syllable + forms[form].syllable_count <= k) ++form;
        const bool in_form = form < forms.size() && forms[form].first_syllable <= k;
        if (syllable.sentence >= marks.size() || (in_form && forms[form].first_syllable != k)) continue;
        const std::string& text = timeline.sentences[syllable.sentence].text;
        const std::string& shown = in_form ? forms[form].text : syllable.text;
        std::size_t& cursor = cursors[syllable.sentence];
        const std::size_t at = shown.empty() ? std::string::npos : text.find(shown, cursor);
        if (at == std::string::npos) continue;
        std::string& sentence_marks = marks[syllable.sentence];
        sentence_marks += (sentence_marks.empty() ? "" : " ") +
                          std::to_string(utf16_length(std::string_view(text).substr(0, at))) + " " +
                          format_fixed(syllable.start_s, 3);
        cursor = at + shown.size();
    }
    return marks;
}

// A share of the stage as a CSS percentage.
std::string percent(double value, double of) { return format_fixed(100.0 * value / of, 3) + "%"; }

// The animation's root start tag with its size replaced by a place on the stage.
std::string placed(const std::string& animation_svg, const StageBox& place) {
    const std::size_t tag_end = animation_svg.find('>');
    std::string tag = animation_svg.substr(0, tag_end);
    for (const char* name : {" width=\"", " height=\""}) {
        const std::size_t start = tag.find(name);
        if (start == std::string::npos) continue;
        const std::size_t end = tag.find('"', start + std::char_traits<char>::length(name));
        tag.erase(start, end + 1 - start);
    }
    tag += " x=\"" + number(place.x) + "\" y=\"" + number(place.y) + "\" width=\"" + number(place.width) +
           "\" height=\"" + number(place.height) + "\"";
    return tag + animation_svg.substr(tag_end);
}

// Where the caption stands, and its size. On the stage its size follows the band's; where that
// falls under the smallest size a reader reads (0.75rem, or the minimum font size the reader set in
// the browser, which cut the caption it enlarged: 7.8 px on a 320 px phone), the band stands under
// the stage at the reader's own size ("tf-caption-under"). That is decided by the width the stage
// has with the band on it, which the caption never changes.
// A sentence longer than the caption's lines is shown smaller until it fits (down to 55% of the
// caption's size, never under the readable size; a sentence longer still is cut at the band's
// edge rather than cover the face). Fitted again whenever the stage or the band changes size (a
// window resized, a phone turned: a size fitted in pixels for one band overflowed a smaller one
// and stayed small in a larger one), and once the page is laid out: a page opened at a time
// ("#t=") shows its sentence before this script runs. Fitting ends with the band the size it
// found, so the notices it causes change nothing and cannot loop.
// A sentence cut even so (a transcript with no punctuation is one sentence) scrolls its lines
// through the caption as it is spoken, the line of the syllable being said (data-syllables) second
// from the caption's top (a line of it before): its first lines alone stood there for minutes, and
// the share of the sentence's time spoken, which came first, showed a line ahead or behind where
// the speaker slowed or hurried.
// The caption is a live region only when the reader asks (the first button, shown when focused):
// the speech says the same words aloud, and a screen reader announcing each sentence would talk
// over it; a reader who does not hear it (a braille display's) turns it on. Video players do the
// same with captions (Video.js's caption display is aria-live="off"; only spoken descriptions are
// live). On, it is polite and atomic: one sentence, read out whole when the next one shows.
constexpr const char* kCaptionScript = R"js((function () {
  "use strict";
  var caption = document.querySelector(".tf-caption");
  if (!caption) return;
  var screen = document.querySelector(".tf-announcer");
  var stage = document.querySelector(".tf-stage");
  var share = parseFloat(screen.getAttribute("data-caption-share"));
  function readable() {
    caption.style.fontSize = "1px";
    var enforced = parseFloat(window.getComputedStyle(caption).fontSize);
    caption.style.fontSize = "";
    return Math.max(0.75 * parseFloat(window.getComputedStyle(document.documentElement).fontSize), enforced);
  }
  function fit() {
    var smallest = readable();
    screen.classList.remove("tf-caption-under");
    screen.classList.toggle("tf-caption-under", share * stage.clientWidth < smallest);
    var size = parseFloat(window.getComputedStyle(caption).fontSize);
    for (var k = 0; k < 9 && size * 0.93 >= smallest && caption.scrollHeight > caption.clientHeight + 1; ++k) {
      size *= 0.93;
      caption.style.fontSize = size + "px";
    }
    follow();
  }
  var audio = document.getElementById("tf-audio");
  function follow() {
    var spoken = caption.querySelector(".tf-current");
    var hidden = caption.scrollHeight - caption.clientHeight;
    if (!spoken || hidden <= 1) { caption.scrollTop = 0; return; }
    var marks = (spoken.getAttribute("data-syllables") || "").split(" ").map(parseFloat);
    var at = 0;
    for (var k = 0; k + 1 < marks.length && marks[k + 1] <= audio.currentTime; k += 2) at = marks[k];
    var said = document.createRange();
    said.setStart(spoken.firstChild, at);
    said.setEnd(spoken.firstChild, Math.min(at + 1, spoken.firstChild.length));
    var line = parseFloat(window.getComputedStyle(caption).lineHeight);
    var index = Math.floor((said.getBoundingClientRect().top - spoken.getBoundingClientRect().top) / line + 0.25);
    caption.scrollTop = Math.min(hidden, Math.max(0, index - 1) * line);
  }
  ["timeupdate", "seeked"].forEach(function (name) { audio.addEventListener(name, follow); });
  var reading = document.querySelector(".tf-caption-reading");
  reading.addEventListener("click", function () {
    var on = reading.getAttribute("aria-pressed") !== "true";
    reading.setAttribute("aria-pressed", String(on));
    caption.setAttribute("aria-live", on ? "polite" : "off");
  });
  document.addEventListener("tf-sentence", fit);
  var resized = new ResizeObserver(fit);
  resized.observe(stage);
  resized.observe(caption.parentElement);
})();
)js";

}  // namespace

PageParts announcer_page(const std::string& animation_svg, const FaceModel& face, const Animation& animation,
                         const Timeline& timeline, const WebPageOptions& options, const std::string& title, const std::string& audio_element) {
    const double stage_width = options.stage_width_px;
    const double stage_height = options.stage_height_px;
    const AnnouncerLayout layout =
        announcer_layout(face, root_view_box(animation_svg), animation.frames, options);

    std::string background = "<rect width=\"" + number(stage_width) + "\" height=\"" + number(stage_height) +
                             "\" fill=\"" + to_hex(options.stage_colour) + "\"/>\n";
    if (!options.background_image_path.empty()) {
        const std::string mime = image_mime_type(options.background_image_path);
        if (mime.empty()) {
            throw InvalidArgument("background_image_path",
                                  "expected a .png, .jpg, .jpeg, .gif, .webp or .svg file, found \"" +
                                      options.background_image_path + "\"");
        }
        // Covers the stage whatever its shape, cropping the picture's overflow (CSS "cover").
        background += "<image width=\"" + number(stage_width) + "\" height=\"" + number(stage_height) +
                      "\" preserveAspectRatio=\"xMidYMid slice\" href=\"" +
                      data_uri(mime, read_file(options.background_image_path)) + "\"/>\n";
    }

    // Every sentence is in the caption, and the page's script shows the one being spoken.
    std::string sentences;
    const std::vector<std::string> marks = syllable_marks(timeline);
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const Sentence& sentence = timeline.sentences[k];
        sentences += "<p class=\"tf-sentence\" data-index=\"" + std::to_string(k) + "\" data-start=\"" +
                     format_fixed(sentence.start_s, 3) + "\" data-end=\"" + format_fixed(sentence.end_s, 3) +
                     "\" data-syllables=\"" + marks[k] + "\">" + escape_html(sentence.text) + "</p>\n";
    }
    const StageBox& band = layout.caption;
    const std::string lower_third =
        "<div class=\"tf-lower-third" + std::string(layout.is_caption_on_top ? " tf-on-top" : "") +
        "\" style=\"--band-left:" + percent(band.x, stage_width) +
        ";--band-top:" + percent(band.y, stage_height) + ";--band-width:" + percent(band.width, stage_width) +
        ";--band-height:" + percent(band.height, stage_height) + "\">\n" +
        (title.empty() ? std::string() : "<div class=\"tf-title\">" + escape_html(title) + "</div>\n") +
        "<div class=\"tf-caption\" aria-live=\"off\" aria-atomic=\"true\">\n" + sentences +
        "</div>\n</div>\n";

    // The caption's size on the stage, min(22cqh, 3.4cqw) of its band, as a share of the stage's width.
    const double caption_share = std::min(0.22 * band.height, 0.034 * band.width) / stage_width;

    // The stage as large as the window lets it and the player under it be (16 + 12 + 54 + 16 px around
    // the stage, and the band's title and two lines when it stands under the stage), as a video
    // fills a page that shows nothing else: held to its --stage size, it stood a fifth of a 4K
    // window's width in the middle, its caption 21 px; and on a phone turned on its side the player
    // lay below the screen. The stage's size gives its shape and the units the face is placed in.
    const auto widest = [&](const std::string& around) {
        return "max-width:max(320px,calc((100vh - " + around + ") * " +
               std::to_string(options.stage_width_px) + " / " + std::to_string(options.stage_height_px) +
               " + 32px))";
    };

    PageParts parts;
    parts.style =
        // Dark whatever the reader's scheme, the player's controls too (they were a white bar under
        // the stage).
        std::string(":root{color-scheme:dark}body{margin:0;background:#0f172a;color:#e2e8f0;font-family:") +
        kSansFonts +
        "}"
        ".tf-announcer{" +
        widest("100px") +
        ";position:relative;margin:0 auto;padding:16px}"
        // Out of sight but for a keyboard's focus, as a "skip to content" link is.
        ".tf-caption-reading{position:absolute;left:24px;top:24px;z-index:1;padding:.4em .8em;border:0;"
        "border-radius:6px;background:#1e293b;color:#fff;font:inherit}"
        ".tf-caption-reading:not(:focus){width:1px;height:1px;padding:0;overflow:hidden;clip-path:inset(50%);"
        "white-space:nowrap}"
        ".tf-stage{position:relative;overflow:hidden;aspect-ratio:" +
        std::to_string(options.stage_width_px) + "/" + std::to_string(options.stage_height_px) +
        "}"
        ".tf-stage-art{display:block;width:100%;height:100%}"
        // The band is a size container: its text is sized by the band's height (cqh), which the
        // layout kept clear of the mouth, and never by the window.
        ".tf-lower-third{position:absolute;left:var(--band-left);top:var(--band-top);width:var(--band-width);"
        "height:var(--band-height);container-type:size;display:flex;flex-direction:column;"
        "justify-content:flex-end}"
        ".tf-lower-third.tf-on-top{justify-content:flex-start}"
        // One line, as a title bar is: a long one ends in an ellipsis rather than cover the face.
        ".tf-title{align-self:flex-start;flex:none;max-width:100%;white-space:nowrap;overflow:hidden;"
        "text-overflow:ellipsis;background:#b91c1c;color:#fff;font-weight:700;"
        "font-size:min(15cqh,2.6cqw);line-height:1.3;padding:.15em .6em}"
        ".tf-caption{flex:0 1 "
        "auto;min-height:0;max-height:70cqh;overflow:hidden;background:#0f172ae0;color:#fff;"
        "font-size:min(22cqh,3.4cqw);line-height:1.3;padding:.2em .6em}"
        ".tf-caption .tf-sentence{display:none;margin:0}"
        ".tf-caption .tf-sentence.tf-current{display:block}"
        ".tf-caption:not(:has(.tf-current)){visibility:hidden}"
        "audio{display:block;width:100%;margin-top:12px}"
        ":focus-visible{outline-color:#93c5fd}"  // light on the dark page
        // Under the stage (the caption script): the band follows the face with two lines at
        // least, so that the player does not jump with each sentence, and four at most.
        ".tf-announcer.tf-caption-under{" +
        widest("100px - 4.3rem") +
        "}"
        ".tf-caption-under .tf-stage{aspect-ratio:auto;overflow:visible}"
        ".tf-caption-under .tf-stage-art{height:auto;aspect-ratio:" +
        std::to_string(options.stage_width_px) + "/" + std::to_string(options.stage_height_px) +
        "}"
        ".tf-caption-under .tf-lower-third{position:static;width:auto;height:auto;container-type:normal}"
        ".tf-caption-under .tf-title{font-size:.8rem}"
        ".tf-caption-under .tf-caption{font-size:1rem;min-height:calc(2.6em + .4em);"
        "max-height:calc(5.2em + .4em)}"
        // Printed, a band that is a size container left the whole page blank (Chromium 156),
        // and the caption's white text on its unprinted dark band would not show.
        "@media print{.tf-lower-third{container-type:inline-size}"
        ".tf-title,.tf-caption{print-color-adjust:exact}}";
    parts.body = "<main class=\"tf-announcer\" data-caption-share=\"" + format_fixed(caption_share, 6) +
                 "\">\n<button type=\"button\" class=\"tf-caption-reading\" aria-pressed=\"false\">"
                 "Captions to screen reader and braille</button>\n"
                 "<div class=\"tf-stage\">\n<svg class=\"tf-stage-art\" "
                 "xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " +
                 number(stage_width) + " " + number(stage_height) + "\" role=\"img\" aria-label=\"" +
                 escape_html(title) + "\">\n" + background + placed(animation_svg, layout.face) + "</svg>\n" +
                 lower_third + "</div>\n" + audio_element + "</main>\n";
    parts.script = kCaptionScript;
    return parts;
}

}  // namespace talkface::detail
