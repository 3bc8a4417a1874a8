// talkface: FrameRenderer, which draws a face state as pixels: the same layers, curves, gradients
// and clip paths as SvgAnimator's SVG (thesis 6.3.1), antialiased, at any size, into a caller's
// RGBA buffer. A video is these frames encoded; a caller who composites draws them itself.
//
//   talkface::FrameRenderer renderer(face);                 // 1280x720, the announcer layout
//   std::vector<std::uint8_t> pixels(renderer.height_px() * renderer.stride_bytes());
//   for (const talkface::FaceState& state : animation.frames)
//       renderer.render_frame_rgba(state, pixels.data(), renderer.stride_bytes());
#ifndef TALKFACE_FRAME_RENDERER_HPP
#define TALKFACE_FRAME_RENDERER_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "talkface/export.h"
#include "talkface/face_look.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// Where the face stands in a frame.
enum class FrameLayout : int {
    /// Thesis 7.2, the virtual announcer: the frame is a stage and the face stands where the
    /// announcer web page stands it on a stage of the frame's size (centred on the bottom edge, its
    /// canvas as tall as the frame, larger if its mouth at rest would meet the page's caption band),
    /// over the background; FrameOptions::face_origin_px and face_d_px move and scale it. The default.
    announcer = 0,
    /// The face's own canvas (SvgAnimator's, with its default size) scaled to fit the frame and
    /// centred, as an SVG viewer shows SvgAnimator::render_svg() at the frame's size.
    face = 1,
};

/// How the bytes of a pixel carry alpha.
enum class AlphaMode : int {
    /// R, G, B not multiplied by A (PNG, FFmpeg's rgba, most image libraries). The default.
    straight = 0,
    /// R, G, B multiplied by A / 255 (compositing libraries: cairo, Skia, Core Graphics).
    premultiplied = 1,
};

/// How frames are drawn. Checked when a FrameRenderer is made.
struct FrameOptions {
    int width_px = 1280;   ///< frame width, 1..7680
    int height_px = 720;   ///< frame height, 1..4320
    FrameLayout layout = FrameLayout::announcer;
    /// Background colour under everything; nullopt leaves the frame transparent where nothing is
    /// drawn (alpha 0). FrameRenderer::set_background_image() draws a picture over it.
    std::optional<Rgb> background = Rgb{0x1d, 0x3b, 0x5c};
    bool draw_clothes = true;           ///< the clothes layer (neck and shoulders)
    Rgb clothes{0x2f, 0x4f, 0x7f};      ///< clothes colour
    FaceLook look = FaceLook::outlined; ///< how the shapes are painted (as SvgOptions)
    double stroke_width_in_d = 0.025;   ///< outline width, in units of d (as SvgOptions)
    /// announcer: where the face's rotation origin O (the neck) stands, in frame pixels; unset:
    /// centred, the canvas standing on the bottom edge (as the announcer page places it).
    std::optional<Point2> face_origin_px;
    /// announcer: the face's eye distance d in frame pixels (> 0); 0: the canvas as tall as the frame.
    double face_d_px = 0.0;
    AlphaMode alpha = AlphaMode::straight;
};

/// Draws face states as RGBA pixels with cairo, layer by layer as SvgAnimator does (background,
/// hair, clothes, face): cubic Bezier paths, corner-cut hair and brows, eyeballs clipped to the eye
/// outline with a radial gradient, antialiased. What does not move (background, background image,
/// clothes) is drawn once and reused; only the region the head covered in the last frame or covers
/// in this one is drawn again, and a state equal to the last one is not drawn at all. Every frame is
/// the same, to the byte, as the one a new renderer would draw.
///
/// Pixels are 4 bytes, R, G, B, A in that order in memory, rows top to bottom, `stride_bytes`
/// apart (at least 4 * width_px), alpha as FrameOptions::alpha says.
///
/// Holds its face, options and the cached layers; movable, not copyable. Thread safety: one thread
/// at a time per renderer (a frame updates the cache); renderers on other threads are independent.
class TALKFACE_API FrameRenderer {
public:
    /// \throws talkface::InvalidArgument if an option is out of range (naming it).
    explicit FrameRenderer(FaceModel face, FrameOptions options = {});
    ~FrameRenderer();
    FrameRenderer(FrameRenderer&&) noexcept;
    FrameRenderer& operator=(FrameRenderer&&) noexcept;
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    const FaceModel& face() const;        ///< the neutral face
    const FrameOptions& options() const;  ///< the options it was made with
    int width_px() const;                 ///< frame width
    int height_px() const;                ///< frame height
    std::size_t stride_bytes() const;     ///< 4 * width_px: rows packed

    /// Draws a picture over the background colour, covering the frame (scaled to fill it, its
    /// overflow cropped, centred: CSS "cover"), under the face. `rgba`: `height` rows of `width`
    /// straight-alpha RGBA pixels, `stride_bytes` apart; copied.
    /// \throws talkface::InvalidArgument for a null buffer, a size of 0 or a stride < 4 * width.
    void set_background_image(const std::uint8_t* rgba, int width, int height, std::size_t stride_bytes);

    /// Draws the face at `state` into `rgba` (height_px() rows of width_px() pixels, `stride_bytes`
    /// apart); every pixel of the frame is written.
    /// \throws talkface::InvalidArgument for a null buffer, a stride < 4 * width_px(), or a state
    ///         out of range (as project_face()).
    void render_frame_rgba(const FaceState& state, std::uint8_t* rgba, std::size_t stride_bytes);

    /// The same into a new buffer of height_px() * stride_bytes() bytes.
    std::vector<std::uint8_t> render_frame_rgba(const FaceState& state);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace v0
}  // namespace talkface

#endif
