// The face's animation carried in a page gzip-compressed (base64 in a data block), and the script
// that unpacks it: the keyframes SVG is text of a few kinds of numbers and commands that deflate
// shrinks about four times, which no choice of key frames or digits comes near at the same
// tolerance. The browser inflates it with DecompressionStream (Chromium 80, Firefox 113, Safari
// 16.4: older than any Safari that plays Opus in WebM) into the animation's root element, then
// runs the page's script.
#ifndef TALKFACE_APPS_PACKED_ANIMATION_HPP
#define TALKFACE_APPS_PACKED_ANIMATION_HPP

#include <string>

#include "render/announcer_layout.hpp"

namespace talkface::detail {

struct PackedAnimation {
    std::string root;  // the animation's root element, empty: "<svg ...></svg>\n"
    std::string data;  // a <script type="application/gzip"> data block: the root's content, packed
};

// Splits an animation document (root element first, as render_animation_svg() writes it without
// its XML declaration) into an empty root and its packed content. Deterministic: the same
// document packs to the same bytes.
PackedAnimation pack_animation(const std::string& svg);

// The viewBox of an animation's root element (`svg` begins with it), which render_animation_svg()
// always writes: where the face is drawn, and the shape a page gives it.
StageBox root_view_box(const std::string& svg);

// `script` (the page's own) run once the animation is unpacked into its root, as one script.
std::string after_unpacking(const std::string& script);

}  // namespace talkface::detail

#endif
