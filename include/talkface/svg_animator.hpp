// talkface: SvgAnimator, which draws faces as SVG (thesis 6.3).
#ifndef TALKFACE_SVG_ANIMATOR_HPP
#define TALKFACE_SVG_ANIMATOR_HPP

#include <memory>
#include <optional>
#include <string>

#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// How a face is drawn. The canvas is the same for every state of one face, so frames line up.
struct SvgOptions {
    /// Background layer colour; nullopt leaves the background transparent.
    std::optional<Rgb> background = Rgb{0xdd, 0xe8, 0xf0};
    bool draw_clothes = true;                 ///< the clothes layer (neck and shoulders)
    Rgb clothes{0x2f, 0x4f, 0x7f};            ///< clothes colour
    double stroke_width_in_d = 0.025;         ///< outline width, in units of d
    int decimals = 2;                         ///< digits after the point in coordinates (0..6)
    /// Canvas size in pixels; 0 fits the face at any pose with a margin (about 4.4 d by 5.2 d).
    int width_px = 0;
    int height_px = 0;
};

/// Draws a face as SVG 1.1 in four layers (background, hair, clothes, face): cubic Bezier paths for
/// face, ears, nose, eyes and mouth, polylines for hair and eyebrows (corner-cutting subdivision),
/// eyeballs clipped to the eye outline with a radial gradient.
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

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace v0
}  // namespace talkface

#endif
