// FrameRenderer: the layers of thesis 6.3.1 drawn as pixels with cairo, what does not move drawn
// once. Each frame draws only the region the head covers now or covered in the frame before.
#include "talkface/frame_renderer.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "common/number_format.hpp"
#include "raster/cairo_drawing.hpp"
#include "raster/frame_layout.hpp"
#include "raster/rgba_pixels.hpp"
#include "render/face_canvas.hpp"
#include "render/layers.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr int kMaxWidthPx = 7680;
constexpr int kMaxHeightPx = 4320;
// Antialiasing reaches a pixel beyond a shape's edge; one more for rounding to whole pixels.
constexpr int kDirtyMarginPx = 2;

void validate(const FrameOptions& options) {
    detail::check_face_look(options.look);
    if (options.width_px < 1 || options.width_px > kMaxWidthPx) {
        throw InvalidArgument("width_px", "expected 1.." + std::to_string(kMaxWidthPx) + ", found " +
                                              std::to_string(options.width_px));
    }
    if (options.height_px < 1 || options.height_px > kMaxHeightPx) {
        throw InvalidArgument("height_px", "expected 1.." + std::to_string(kMaxHeightPx) + ", found " +
                                               std::to_string(options.height_px));
    }
    const int layout = static_cast<int>(options.layout);
    if (layout != static_cast<int>(FrameLayout::announcer) && layout != static_cast<int>(FrameLayout::face)) {
        throw InvalidArgument("layout", "expected announcer or face, found " + std::to_string(layout));
    }
    const int alpha = static_cast<int>(options.alpha);
    if (alpha != static_cast<int>(AlphaMode::straight) && alpha != static_cast<int>(AlphaMode::premultiplied)) {
        throw InvalidArgument("alpha", "expected straight or premultiplied, found " + std::to_string(alpha));
    }
    if (!std::isfinite(options.stroke_width_in_d) || options.stroke_width_in_d <= 0.0) {
        throw InvalidArgument("stroke_width_in_d", "expected a finite number > 0, found " +
                                                       detail::format_shortest(options.stroke_width_in_d));
    }
    if (!std::isfinite(options.face_d_px) || options.face_d_px < 0.0) {
        throw InvalidArgument("face_d_px", "expected a finite number >= 0 (0: as tall as the frame), found " +
                                               detail::format_shortest(options.face_d_px));
    }
    if (options.face_origin_px &&
        !(std::isfinite(options.face_origin_px->x) && std::isfinite(options.face_origin_px->y))) {
        throw InvalidArgument("face_origin_px", "expected finite coordinates");
    }
}

void check_buffer(const std::uint8_t* rgba, std::size_t stride_bytes, int width, const char* name) {
    if (rgba == nullptr) throw InvalidArgument(name, "is null");
    if (stride_bytes < 4 * static_cast<std::size_t>(width)) {
        throw InvalidArgument("stride_bytes", "expected at least 4 * width = " + std::to_string(4 * width) +
                                                  ", found " + std::to_string(stride_bytes));
    }
}

// Owns a cairo image surface.
struct Surface {
    cairo_surface_t* surface = nullptr;
    Surface() = default;
    Surface(int width, int height) : surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height)) {
        if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
            cairo_surface_destroy(surface);
            throw std::bad_alloc();
        }
    }
    Surface(Surface&& other) noexcept : surface(std::exchange(other.surface, nullptr)) {}
    Surface& operator=(Surface&& other) noexcept {
        std::swap(surface, other.surface);
        return *this;
    }
    ~Surface() { cairo_surface_destroy(surface); }
    std::uint8_t* data() const { return cairo_image_surface_get_data(surface); }
    std::size_t stride() const { return static_cast<std::size_t>(cairo_image_surface_get_stride(surface)); }
};

// Owns a cairo context.
struct Context {
    cairo_t* cairo;
    explicit Context(const Surface& surface) : cairo(cairo_create(surface.surface)) {}
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    ~Context() { cairo_destroy(cairo); }
};

bool is_same_state(const FaceState& a, const FaceState& b) {
    return a.pose == b.pose && a.expression == b.expression && a.mouth == b.mouth;
}

}  // namespace

struct FrameRenderer::Impl {
    FaceModel face;
    FrameOptions options;
    detail::CanvasBox canvas;
    detail::FramePlacement placement;
    detail::FacePaints paints;  // in image pixels: the view is the identity
    Surface background_colour;  // the colour alone
    Surface background;         // the colour and the picture: what every frame starts from
    Surface clothes;            // transparent but for the clothes
    detail::PixelBox clothes_box;  // where the clothes are
    Surface frame;              // the last frame drawn
    std::vector<std::uint8_t> rgba;  // the last frame in the callers' layout
    bool has_frame = false;
    FaceState last_state;
    detail::PixelBox last_head;  // where the head was drawn in the last frame

    void set_matrix(cairo_t* cairo) const {
        cairo_matrix_t matrix;
        cairo_matrix_init(&matrix, placement.scale, 0.0, 0.0, placement.scale, placement.offset.x, placement.offset.y);
        cairo_set_matrix(cairo, &matrix);
    }

    // announcer: the layers are cut at the canvas's edges, as the page's nested <svg> viewport cuts
    // them; face: by the frame's, as a document's own viewport, which meets its viewBox. The edges are
    // rounded to whole pixels: a clip on pixel edges is a region to cairo, a fractional one a mask
    // drawn anew with every shape (measured: a third of a frame's time).
    void clip_to_canvas(cairo_t* cairo) const {
        if (options.layout != FrameLayout::announcer) return;
        const detail::CanvasBox& box = placement.canvas_in_frame;
        const double x0 = std::round(box.x), y0 = std::round(box.y);
        cairo_rectangle(cairo, x0, y0, std::round(box.x + box.width) - x0, std::round(box.y + box.height) - y0);
        cairo_clip(cairo);
    }

    detail::PixelBox frame_box_of(const detail::CanvasBox& extent) const {
        if (extent.width <= 0.0) return {};
        const Point2 a = placement.apply({extent.x, extent.y});
        const Point2 b = placement.apply({extent.x + extent.width, extent.y + extent.height});
        const int x0 = std::max(0, static_cast<int>(std::floor(a.x)) - kDirtyMarginPx);
        const int y0 = std::max(0, static_cast<int>(std::floor(a.y)) - kDirtyMarginPx);
        const int x1 = std::min(options.width_px, static_cast<int>(std::ceil(b.x)) + kDirtyMarginPx);
        const int y1 = std::min(options.height_px, static_cast<int>(std::ceil(b.y)) + kDirtyMarginPx);
        return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
    }

    void compose_background(const Surface* picture, int picture_width, int picture_height) {
        {
            const Context context(background);
            cairo_set_operator(context.cairo, CAIRO_OPERATOR_SOURCE);
            cairo_set_source_surface(context.cairo, background_colour.surface, 0.0, 0.0);
            cairo_paint(context.cairo);
            if (picture != nullptr) {
                // CSS "cover", centred, as the announcer page's <image preserveAspectRatio="xMidYMid slice">.
                const double scale = std::max(static_cast<double>(options.width_px) / picture_width,
                                              static_cast<double>(options.height_px) / picture_height);
                cairo_set_operator(context.cairo, CAIRO_OPERATOR_OVER);
                cairo_translate(context.cairo, 0.5 * (options.width_px - scale * picture_width),
                                0.5 * (options.height_px - scale * picture_height));
                cairo_scale(context.cairo, scale, scale);
                cairo_set_source_surface(context.cairo, picture->surface, 0.0, 0.0);
                cairo_pattern_set_filter(cairo_get_source(context.cairo), CAIRO_FILTER_GOOD);
                cairo_pattern_set_extend(cairo_get_source(context.cairo), CAIRO_EXTEND_PAD);
                cairo_paint(context.cairo);
            }
        }
        cairo_surface_flush(background.surface);
        has_frame = false;
    }

    void draw(const FaceState& state) {
        const ProjectedFace projected = project_face(face, state);
        const detail::Layer hair = detail::draw_hair_layer(projected, paints);
        const detail::Layer face_layer = detail::draw_face_layer(projected, paints);
        const detail::PixelBox head =
            detail::united(frame_box_of(detail::layer_extent(hair)), frame_box_of(detail::layer_extent(face_layer)));
        const detail::PixelBox dirty =
            has_frame ? detail::united(head, last_head) : detail::PixelBox{0, 0, options.width_px, options.height_px};
        {
            const Context context(frame);
            cairo_t* cairo = context.cairo;
            cairo_rectangle(cairo, dirty.x, dirty.y, dirty.width, dirty.height);
            cairo_clip(cairo);
            cairo_set_operator(cairo, CAIRO_OPERATOR_SOURCE);
            cairo_set_source_surface(cairo, background.surface, 0.0, 0.0);
            cairo_paint(cairo);
            cairo_set_operator(cairo, CAIRO_OPERATOR_OVER);
            // Thesis 6.3.1's order: background, hair, clothes, face.
            clip_to_canvas(cairo);
            cairo_save(cairo);
            set_matrix(cairo);
            detail::draw_layer(cairo, hair);
            cairo_restore(cairo);
            if (options.draw_clothes) {
                // Composited only where they are: an OVER of a whole frame's pixels costs more than
                // drawing the head.
                cairo_save(cairo);
                cairo_rectangle(cairo, clothes_box.x, clothes_box.y, clothes_box.width, clothes_box.height);
                cairo_clip(cairo);
                cairo_set_source_surface(cairo, clothes.surface, 0.0, 0.0);
                cairo_paint(cairo);
                cairo_restore(cairo);
            }
            set_matrix(cairo);
            detail::draw_layer(cairo, face_layer);
        }
        cairo_surface_flush(frame.surface);
        detail::argb32_to_rgba(frame.data(), frame.stride(), rgba.data(), 4 * static_cast<std::size_t>(options.width_px),
                               dirty, options.alpha == AlphaMode::premultiplied);
        last_state = state;
        last_head = head;
        has_frame = true;
    }
};

FrameRenderer::FrameRenderer(FaceModel face, FrameOptions options) {
    validate(options);
    impl_ = std::make_unique<Impl>();
    Impl& impl = *impl_;
    impl.canvas = detail::fit_face_canvas(face);
    impl.placement = detail::place_face(face, impl.canvas, options);
    const ProjectedFace neutral = project_face(face, FaceState{});
    const detail::LayerStyle style{2, options.stroke_width_in_d * neutral.d, options.look};
    impl.paints = detail::make_face_paints(neutral, style);
    impl.face = std::move(face);
    impl.options = options;
    const int width = options.width_px;
    const int height = options.height_px;
    impl.background_colour = Surface(width, height);
    if (options.background) {
        const Context context(impl.background_colour);
        const Rgb colour = *options.background;
        cairo_set_source_rgb(context.cairo, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0);
        cairo_paint(context.cairo);
    }
    cairo_surface_flush(impl.background_colour.surface);
    impl.background = Surface(width, height);
    impl.compose_background(nullptr, 0, 0);
    impl.clothes = Surface(width, height);
    if (options.draw_clothes) {
        const Context context(impl.clothes);
        impl.clip_to_canvas(context.cairo);
        impl.set_matrix(context.cairo);
        const detail::Layer clothes = detail::draw_clothes_layer(neutral, impl.canvas, options.clothes, style);
        detail::draw_layer(context.cairo, clothes);
        impl.clothes_box = impl.frame_box_of(detail::layer_extent(clothes));
    }
    cairo_surface_flush(impl.clothes.surface);
    impl.frame = Surface(width, height);
    impl.rgba.assign(static_cast<std::size_t>(height) * 4 * static_cast<std::size_t>(width), 0);
}

FrameRenderer::~FrameRenderer() = default;
FrameRenderer::FrameRenderer(FrameRenderer&&) noexcept = default;
FrameRenderer& FrameRenderer::operator=(FrameRenderer&&) noexcept = default;

const FaceModel& FrameRenderer::face() const { return impl_->face; }
const FrameOptions& FrameRenderer::options() const { return impl_->options; }
int FrameRenderer::width_px() const { return impl_->options.width_px; }
int FrameRenderer::height_px() const { return impl_->options.height_px; }
std::size_t FrameRenderer::stride_bytes() const { return 4 * static_cast<std::size_t>(impl_->options.width_px); }

void FrameRenderer::set_background_image(const std::uint8_t* rgba, int width, int height, std::size_t stride_bytes) {
    if (width < 1 || height < 1) {
        throw InvalidArgument("background image", "expected a size of at least 1x1, found " + std::to_string(width) +
                                                      "x" + std::to_string(height));
    }
    check_buffer(rgba, stride_bytes, width, "background image");
    Surface picture(width, height);
    detail::rgba_to_argb32(rgba, stride_bytes, picture.data(), picture.stride(), width, height);
    cairo_surface_mark_dirty(picture.surface);
    impl_->compose_background(&picture, width, height);
}

void FrameRenderer::render_frame_rgba(const FaceState& state, std::uint8_t* rgba, std::size_t stride_bytes) {
    Impl& impl = *impl_;
    check_buffer(rgba, stride_bytes, impl.options.width_px, "rgba");
    // Holds (pauses, a held head) repeat a state exactly: the last frame stands.
    if (!impl.has_frame || !is_same_state(state, impl.last_state)) impl.draw(state);
    const std::size_t row_bytes = this->stride_bytes();
    for (int row = 0; row < impl.options.height_px; ++row) {
        std::memcpy(rgba + static_cast<std::size_t>(row) * stride_bytes,
                    impl.rgba.data() + static_cast<std::size_t>(row) * row_bytes, row_bytes);
    }
}

std::vector<std::uint8_t> FrameRenderer::render_frame_rgba(const FaceState& state) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(height_px()) * stride_bytes());
    render_frame_rgba(state, pixels.data(), stride_bytes());
    return pixels;
}

}  // namespace v0
}  // namespace talkface
