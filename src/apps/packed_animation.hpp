// The face's animation carried in a page gzip-compressed (base64 in a data block), and the script
// that unpacks it: the keyframes SVG is text of a few kinds of numbers and commands that deflate
// shrinks about four times, which no choice of key frames or digits comes near at the same
// tolerance. The browser inflates it with DecompressionStream (Chromium 80, Firefox 113, Safari
// 16.4: older than any Safari that plays Opus in WebM) into the animation's root element, then
// runs the page's script.
//
// The browser shows the head still when the reader's system asks for reduced motion
// (prefers-reduced-motion: reduce, WCAG 2.3.3), also when the setting changes while the page is
// open. In the keyframes encoding the face is drawn at rest and the pose's animations are marked
// (class tf-pose, render_animation_with_pose_apart()): the script takes them out. In the frames
// encoding the still face is a document of its own, packed in the same stream after a form feed,
// which XML forbids in a document and so never occurs in either.
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
// its XML declaration) into an empty root and its packed content; `still_svg`, when not empty, is
// the same animation with the head held still (its root element the same), packed after it.
// Deterministic: the same documents pack to the same bytes.
PackedAnimation pack_animation(const std::string& svg, const std::string& still_svg);

// The viewBox of an animation's root element (`svg` begins with it), which render_animation_svg()
// always writes: where the face is drawn, and the shape a page gives it.
StageBox root_view_box(const std::string& svg);

// `script` (the page's own) run once the animation is unpacked into its root, as one script.
std::string after_unpacking(const std::string& script);

}  // namespace talkface::detail

#endif
