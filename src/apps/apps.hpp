// The applications of thesis chapter 7, as the middle of a web page: what the page shows around
// the talking face. apps/web_page.cpp wraps them with the audio, the script and the head.
#ifndef TALKFACE_APPS_APPS_HPP
#define TALKFACE_APPS_APPS_HPP

#include <string>

#include "talkface/animation.hpp"
#include "talkface/face_model.hpp"
#include "talkface/timeline.hpp"
#include "talkface/web_page.hpp"

namespace talkface::detail {

// The page-specific part of a page: its style rules, the content of its <body>, and a script run
// after the page's clock script (which sends a "tf-sentence" event, detail {index, element}, to
// the document whenever the sentence being spoken changes).
struct PageParts {
    std::string style;
    std::string body;
    std::string script;
};

// Thesis 7.2: the face on a stage of options.stage_width_px x stage_height_px, over a colour or an
// image, placed by its rotation origin O and scaled by its eye distance d, with a lower third that
// shows the title and the sentence being spoken (announcer_layout.hpp keeps it off the mouth in
// every frame of `animation`).
// `animation_svg` is the face's animation document drawn with no background (its root element first).
PageParts announcer_page(const std::string& animation_svg, const FaceModel& face, const Animation& animation,
                         const Timeline& timeline, const WebPageOptions& options, const std::string& title, const std::string& audio_element);

// Thesis 7.3: the title, the text paragraph by paragraph and sentence by sentence (each a span with
// its times, which the page's script highlights, keeps in view and seeks to), the links, and the
// talking face beside them (above them on a phone).
PageParts audiobook_page(const std::string& animation_svg, const Timeline& timeline, const WebPageOptions& options,
                         const std::string& title, const std::string& audio_element);

}  // namespace talkface::detail

#endif
