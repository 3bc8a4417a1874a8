// The virtual announcer (thesis 7.2): the talking face on a stage, in front of a background colour
// or picture, moved to any place and scaled to any size by its rotation origin and eye distance
// (7.2.3: "the location of cartoon faces can be easily changed" by moving the origin), framed as a
// news programme: a lower third with the title and the caption of the sentence being spoken.
//
// The stage is one box of the stage's proportions holding nothing but the frame (the controls sit
// under it), so that it can be recorded as a video as it is. The caption is HTML over the stage's
// SVG, so that a long sentence wraps and the system's CJK fonts are found as in any page.
#include <cstddef>
#include <cstdlib>
#include <string>

#include "render/announcer_layout.hpp"
#include "apps/apps.hpp"
#include "apps/page_fonts.hpp"
#include "common/atomic_file.hpp"
#include "common/internal_error.hpp"
#include "common/number_format.hpp"
#include "render/html_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// The viewBox of the animation's root element, which render_animation_svg() always writes.
StageBox view_box_of(const std::string& svg) {
    const std::size_t start = svg.find("viewBox=\"");
    if (start == std::string::npos) {
        throw detail::internal_error("the animation has no viewBox");
    }
    StageBox box;
    const char* text = svg.c_str() + start + 9;
    double* fields[] = {&box.x, &box.y, &box.width, &box.height};
    for (double* field : fields) {
        char* end = nullptr;
        *field = std::strtod(text, &end);
        text = end;
    }
    return box;
}

std::string number(double value) { return format_fixed(value, 2); }

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

// A sentence longer than the caption's two lines is shown smaller until it fits (down to 55% of
// the caption's size; a sentence longer still is cut at the band's edge rather than cover the face).
// Fitted again whenever the band changes size (a window resized, a phone turned: a size fitted in
// pixels for one band overflowed a smaller one and stayed small in a larger one), and once the
// page is laid out: a page opened at a time ("#t=") shows its sentence before this script runs.
// The band's size follows the stage alone, never the caption's text, so fitting cannot loop.
constexpr const char* kCaptionScript = R"js((function () {
  "use strict";
  var caption = document.querySelector(".tf-caption");
  if (!caption) return;
  function fit() {
    caption.style.fontSize = "";
    var size = parseFloat(window.getComputedStyle(caption).fontSize);
    for (var k = 0; k < 9 && caption.scrollHeight > caption.clientHeight + 1; ++k) {
      size *= 0.93;
      caption.style.fontSize = size + "px";
    }
  }
  document.addEventListener("tf-sentence", fit);
  new ResizeObserver(fit).observe(caption.parentElement);
})();
)js";

}  // namespace

PageParts announcer_page(const std::string& animation_svg, const FaceModel& face, const Animation& animation,
                         const Timeline& timeline, const WebPageOptions& options, const std::string& title, const std::string& audio_element) {
    const double stage_width = options.stage_width_px;
    const double stage_height = options.stage_height_px;
    const AnnouncerLayout layout = announcer_layout(face, view_box_of(animation_svg), animation.frames, options);

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
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const Sentence& sentence = timeline.sentences[k];
        sentences += "<p class=\"tf-sentence\" data-index=\"" + std::to_string(k) + "\" data-start=\"" +
                     format_fixed(sentence.start_s, 3) + "\" data-end=\"" + format_fixed(sentence.end_s, 3) + "\">" +
                     escape_html(sentence.text) + "</p>\n";
    }
    const StageBox& band = layout.caption;
    const std::string lower_third =
        "<div class=\"tf-lower-third" + std::string(layout.is_caption_on_top ? " tf-on-top" : "") +
        "\" style=\"left:" + percent(band.x, stage_width) + ";top:" + percent(band.y, stage_height) +
        ";width:" + percent(band.width, stage_width) + ";height:" + percent(band.height, stage_height) + "\">\n" +
        (title.empty() ? std::string() : "<div class=\"tf-title\">" + escape_html(title) + "</div>\n") +
        "<div class=\"tf-caption\">\n" + sentences + "</div>\n</div>\n";

    PageParts parts;
    parts.style = std::string("body{margin:0;background:#0f172a;color:#e2e8f0;font-family:") + kSansFonts +
                  "}"
                  // The stage and the player under it within the window's height (16 + 12 + 54 + 16 px around
                  // the stage): on a phone turned on its side the player lay below the screen.
                  ".tf-announcer{max-width:min(" +
                  std::to_string(options.stage_width_px) + "px,max(320px,calc((100vh - 100px) * " +
                  std::to_string(options.stage_width_px) + " / " + std::to_string(options.stage_height_px) +
                  " + 32px)));margin:0 auto;padding:16px}"
                  ".tf-stage{position:relative;overflow:hidden;aspect-ratio:" +
                  std::to_string(options.stage_width_px) + "/" + std::to_string(options.stage_height_px) +
                  "}"
                  ".tf-stage-art{display:block;width:100%;height:100%}"
                  // The band is a size container: its text is sized by the band's height (cqh), which the
                  // layout kept clear of the mouth, and never by the window.
                  ".tf-lower-third{position:absolute;container-type:size;display:flex;flex-direction:column;"
                  "justify-content:flex-end}"
                  ".tf-lower-third.tf-on-top{justify-content:flex-start}"
                  ".tf-title{align-self:flex-start;flex:none;background:#b91c1c;color:#fff;font-weight:700;"
                  "font-size:min(15cqh,2.6cqw);line-height:1.3;padding:.15em .6em}"
                  ".tf-caption{flex:0 1 "
                  "auto;min-height:0;max-height:70cqh;overflow:hidden;background:#0f172ae0;color:#fff;"
                  "font-size:min(22cqh,3.4cqw);line-height:1.3;padding:.2em .6em}"
                  ".tf-caption .tf-sentence{display:none;margin:0}"
                  ".tf-caption .tf-sentence.tf-current{display:block}"
                  ".tf-caption:not(:has(.tf-current)){visibility:hidden}"
                  "audio{display:block;width:100%;margin-top:12px}"
                  ":focus-visible{outline-color:#93c5fd}";  // light on the dark page
    parts.body = "<main class=\"tf-announcer\">\n<div class=\"tf-stage\">\n<svg class=\"tf-stage-art\" "
                 "xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " +
                 number(stage_width) + " " + number(stage_height) + "\" role=\"img\" aria-label=\"" +
                 escape_html(title) + "\">\n" + background + placed(animation_svg, layout.face) + "</svg>\n" +
                 lower_third + "</div>\n" + audio_element + "</main>\n";
    parts.script = kCaptionScript;
    return parts;
}

}  // namespace talkface::detail
