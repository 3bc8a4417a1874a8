// talkface: SvgAnimator, which draws faces as SVG (thesis 6.3): one face state (the spatial half,
// 6.3.1) or a whole animation (the temporal half, 6.3.2).
//
//   talkface::SvgAnimator animator(face);
//   std::string svg = animator.render_animation_svg(animation);   // plays in any browser
#ifndef TALKFACE_SVG_ANIMATOR_HPP
#define TALKFACE_SVG_ANIMATOR_HPP

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "talkface/animation.hpp"
#include "talkface/export.h"
#include "talkface/face_look.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/progress.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// The most digits after the point SvgOptions::decimals may ask for: past 6 a coordinate, in
/// pixels, carries only noise.
inline constexpr int kMaxSvgDecimals = 6;

/// How a face is drawn. The canvas is the same for every state of one face, so frames line up.
struct SvgOptions {
    /// Background layer colour; nullopt leaves the background transparent.
    std::optional<Rgb> background = Rgb{0xdd, 0xe8, 0xf0};
    bool draw_clothes = true;                 ///< the clothes layer (neck and shoulders)
    Rgb clothes{0x2f, 0x4f, 0x7f};            ///< clothes colour
    FaceLook look = FaceLook::outlined;       ///< how the shapes are painted
    double stroke_width_in_d = 0.025;         ///< outline width, in units of d (FaceLook::outlined)
    int decimals = 2;                         ///< digits after the point in coordinates (0..kMaxSvgDecimals)
    /// Canvas size in pixels; 0 fits the face at any pose with a margin (about 4.4 d by 5.2 d).
    int width_px = 0;
    int height_px = 0;
};

/// How an animation becomes SVG. Both play in any browser that runs SMIL (Chromium, Firefox,
/// Safari), alone or driven by a page's audio clock (web_page.hpp).
enum class AnimationEncoding : int {
    /// The default: the face drawn once, each moving element animated by SMIL <animate> between
    /// key frames that the browser interpolates linearly (the head's groups turn with its tilt, and
    /// an outline may move under an animated translate of its own). Key frames are chosen per
    /// element from every frame of the animation so that no drawn point strays from the frame it
    /// stands for by more than SvgAnimationOptions::tolerance_px, plus 0.06 px of rounding (0.19 px
    /// for a Bezier control point that an S or T command leaves implicit): small files.
    keyframes = 0,
    /// Thesis 6.3.2: one <g> per frame, hidden except while its <set> shows it. Identical
    /// consecutive frames share one group. Exact at every frame, but large.
    frames = 1,
};

/// "keyframes" or "frames".
TALKFACE_API const char* animation_encoding_name(AnimationEncoding encoding);
/// Parses a name as animation_encoding_name() writes it.
/// \throws talkface::InvalidArgument listing the valid names.
TALKFACE_API AnimationEncoding animation_encoding_from_name(std::string_view name);

/// How an animation is written.
struct SvgAnimationOptions {
    AnimationEncoding encoding = AnimationEncoding::keyframes;
    /// keyframes: the largest distance, in the face's pixels, between a coordinate the browser
    /// interpolates and the same coordinate of the frame at that time (> 0). 0.3 px is below what
    /// an eye sees at the face's own size.
    double tolerance_px = 0.3;
};

/// How an animation becomes Lottie JSON (SvgAnimator::render_animation_lottie()).
struct LottieOptions {
    /// The largest distance, in the face's pixels, between a coordinate the player interpolates
    /// and the same coordinate of the frame at that time (> 0), as SvgAnimationOptions::tolerance_px.
    double tolerance_px = 0.3;
};

/// Draws a face as SVG 1.1 in four layers (background, hair, clothes, face): cubic Bezier paths for
/// face, ears, nose, eyes and mouth, hair and eyebrows as the limit of corner-cutting subdivision
/// (quadratic Bezier paths), eyeballs clipped to the eye outline with a radial gradient.
///
/// Holds its face and options; movable, not copyable. Thread safety: const members may be called from
/// several threads at once.
class TALKFACE_API SvgAnimator {
public:
    /// \throws talkface::InvalidArgument if an option is out of range.
    explicit SvgAnimator(FaceModel face, SvgOptions options = {});
    ~SvgAnimator();
    SvgAnimator(SvgAnimator&&) noexcept;
    SvgAnimator& operator=(SvgAnimator&&) noexcept;
    SvgAnimator(const SvgAnimator&) = delete;
    SvgAnimator& operator=(const SvgAnimator&) = delete;

    const FaceModel& face() const;       ///< the neutral face
    const SvgOptions& options() const;   ///< the drawing options

    /// A standalone SVG document of the face at `state`.
    /// \throws talkface::InvalidArgument as project_face() does.
    std::string render_svg(const FaceState& state) const;

    /// Writes render_svg(state) to `path` through a temporary file and a rename: a failure leaves
    /// no partial file. \throws talkface::FileError if it cannot be written.
    void write_svg(const std::string& path, const FaceState& state) const;

    /// A standalone SVG document that plays `animation` (its frames, at its fps) from document
    /// time 0, on the same canvas as render_svg(). The root <svg> has class "tf-animation"; the
    /// animation ends on its last frame (fill="freeze"). A page can pause the document's timeline
    /// and set its time from an audio clock (SVGSVGElement.setCurrentTime), as web_page.hpp does.
    /// \throws talkface::InvalidArgument if the animation has no frames, a frame's state is out of
    ///         range (as project_face()), or an option is out of range;
    ///         talkface::Cancelled if `progress` returned false.
    std::string render_animation_svg(const Animation& animation, const SvgAnimationOptions& options = {},
                                     const ProgressCallback& progress = {}) const;

    /// Writes render_animation_svg() to `path` through a temporary file and a rename.
    /// \throws talkface::FileError if it cannot be written, and as render_animation_svg().
    void write_animation_svg(const std::string& path, const Animation& animation,
                             const SvgAnimationOptions& options = {}, const ProgressCallback& progress = {}) const;

    /// The animation as one Lottie document (JSON, as lottie-web 5.7 reads it; lottie-android,
    /// lottie-ios and rlottie play the same files): the same layers, shapes, gradients and clip
    /// paths as render_animation_svg() on the same canvas, as Lottie shape layers (a clipped group,
    /// such as an eyeball, as a layer masked by its clip path). Every number that moves is animated
    /// between key frames chosen as the keyframes encoding chooses them (within `tolerance_px` of
    /// every frame), linear between them (held where a key repeats); coordinates are written to
    /// one digit fewer than SvgOptions::decimals (at the default, to 0.1 px: at most 0.05 px off).
    /// Frame rate: the animation's; frame i shows time i / fps. Lottie carries no sound: a page plays the
    /// recording beside it and sets the animation's time from the audio's clock
    /// (lottie-web's goToAndStop(audio.currentTime * 1000, false); README.md shows it).
    /// \throws talkface::InvalidArgument if the animation has no frames, a frame's state is out of
    ///         range, or an option is out of range; talkface::Cancelled if `progress` returned false.
    std::string render_animation_lottie(const Animation& animation, const LottieOptions& options = {},
                                        const ProgressCallback& progress = {}) const;

    /// Writes render_animation_lottie() to `path` through a temporary file and a rename.
    /// \throws talkface::FileError if it cannot be written, and as render_animation_lottie().
    void write_animation_lottie(const std::string& path, const Animation& animation,
                                const LottieOptions& options = {}, const ProgressCallback& progress = {}) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace v0
}  // namespace talkface

#endif
