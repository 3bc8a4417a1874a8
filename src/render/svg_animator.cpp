// SvgAnimator: the spatial half of thesis 6.3 (one state -> one SVG document) and the canvas that
// every frame of one face shares.
#include "talkface/svg_animator.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "render/layers.hpp"
#include "render/lottie_animation.hpp"
#include "render/svg_animation.hpp"
#include "render/svg_document.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

void validate(const SvgOptions& options) {
    detail::check_face_look(options.look);
    if (options.decimals < 0 || options.decimals > kMaxSvgDecimals) {
        throw InvalidArgument("decimals", "expected 0.." + std::to_string(kMaxSvgDecimals) + ", found " +
                                              std::to_string(options.decimals));
    }
    if (!std::isfinite(options.stroke_width_in_d) || options.stroke_width_in_d <= 0.0) {
        throw InvalidArgument("stroke_width_in_d", "expected a finite number > 0, found " +
                                                       detail::format_shortest(options.stroke_width_in_d));
    }
    if (options.width_px < 0) {
        throw InvalidArgument("width_px", "expected >= 0 (0 fits the face), found " +
                                              std::to_string(options.width_px));
    }
    if (options.height_px < 0) {
        throw InvalidArgument("height_px", "expected >= 0 (0 fits the face), found " +
                                               std::to_string(options.height_px));
    }
}

}  // namespace

const char* animation_encoding_name(AnimationEncoding encoding) {
    switch (encoding) {
        case AnimationEncoding::keyframes: return "keyframes";
        case AnimationEncoding::frames: return "frames";
    }
    return "unknown";
}

AnimationEncoding animation_encoding_from_name(std::string_view name) {
    if (name == "keyframes") return AnimationEncoding::keyframes;
    if (name == "frames") return AnimationEncoding::frames;
    throw InvalidArgument("encoding", "expected keyframes or frames, found \"" + std::string(name) + "\"");
}

struct SvgAnimator::Impl {
    FaceModel face;
    SvgOptions options;
    detail::SvgCanvas canvas;
};

SvgAnimator::SvgAnimator(FaceModel face, SvgOptions options) {
    validate(options);
    impl_ = std::make_unique<Impl>();
    impl_->canvas = detail::face_svg_canvas(face, options.width_px, options.height_px);
    impl_->face = std::move(face);
    impl_->options = options;
}

SvgAnimator::~SvgAnimator() = default;
SvgAnimator::SvgAnimator(SvgAnimator&&) noexcept = default;
SvgAnimator& SvgAnimator::operator=(SvgAnimator&&) noexcept = default;

const FaceModel& SvgAnimator::face() const { return impl_->face; }
const SvgOptions& SvgAnimator::options() const { return impl_->options; }

std::string SvgAnimator::render_svg(const FaceState& state) const {
    const ProjectedFace projected = project_face(impl_->face, state);
    const SvgOptions& options = impl_->options;
    const detail::LayerStyle style{options.decimals, options.stroke_width_in_d * projected.d, options.look};
    // The user space is the face's own image space: a caller can crop or place a document with
    // points from project_face() (the samples zoom on the mouth that way).
    const int decimals = options.decimals;
    std::string svg = detail::kXmlDeclaration;
    svg += detail::open_svg_root(impl_->canvas, decimals, "");
    svg += detail::background_layer_svg(impl_->canvas, options.background, decimals);
    const detail::FacePaints paints = detail::make_face_paints(projected, style);
    svg += detail::layer_group_svg("hair", detail::draw_hair_layer(projected, paints), decimals);
    svg += detail::layer_group_svg(
        "clothes",
        options.draw_clothes ? detail::draw_clothes_layer(projected, impl_->canvas.box, options.clothes, style)
                             : detail::Layer(),
        decimals);
    svg += detail::layer_group_svg("face", detail::draw_face_layer(projected, paints), decimals);
    return svg + "</svg>\n";
}

void SvgAnimator::write_svg(const std::string& path, const FaceState& state) const {
    detail::write_file_atomically(path, render_svg(state));
}

std::string SvgAnimator::render_animation_svg(const Animation& animation, const SvgAnimationOptions& options,
                                              const ProgressCallback& progress) const {
    return detail::render_animation(impl_->face, impl_->options, impl_->canvas, animation, options, progress);
}

void SvgAnimator::write_animation_svg(const std::string& path, const Animation& animation,
                                      const SvgAnimationOptions& options, const ProgressCallback& progress) const {
    detail::write_file_atomically(path, render_animation_svg(animation, options, progress));
}

std::string SvgAnimator::render_animation_lottie(const Animation& animation, const LottieOptions& options,
                                                 const ProgressCallback& progress) const {
    return detail::render_lottie(impl_->face, impl_->options, impl_->canvas, animation, options, progress);
}

void SvgAnimator::write_animation_lottie(const std::string& path, const Animation& animation,
                                         const LottieOptions& options, const ProgressCallback& progress) const {
    detail::write_file_atomically(path, render_animation_lottie(animation, options, progress));
}

}  // namespace v0
}  // namespace talkface
