// The drawing model: a face state as layers of shapes, in numbers (thesis 6.3.1's layers, the
// syntaxes of 6.3.1 as data). The layer builders (layers.hpp) fill it from a projected face; the SVG
// writer (svg_writer.hpp), the two animation encodings (frames_encoder.hpp, keyframes_encoder.hpp)
// and the raster renderer (src/raster/) read it. No renderer reads another's text.
//
// What a layer holds, in paint order:
//   definitions  clip paths (each an outline path with an id of its own, which a shape may draw
//                again, or an earlier clip path's outline moved) and radial gradients, referred to
//                by their index in Layer::definitions;
//   elements     shapes: a path (moves, lines, cubic and quadratic Bezier segments, closes), a
//                polyline, a circle, a rectangle, a reference (a clip path's outline drawn again with
//                a paint of its own, moved or not: SVG <use>), or a group of shapes clipped by a clip
//                path (groups nest: their clips intersect).
// Coordinates are in the drawing's units (image pixels, y down, unless the builder's view maps
// them: layers.hpp ViewMap). Fills use the nonzero rule; strokes have round joins and caps.
//
// To add a shape kind: an enumerator in ShapeKind and its fields in Shape, its element in
// svg_writer.cpp (write_shape), its numbers in list_numeric_attributes() below (what an animation
// may move, in the order the writer writes them), and its drawing in src/raster/cairo_canvas.cpp.
// To add a layer: a builder in layers.hpp, and its place in the documents (svg_animator.cpp,
// svg_animation.cpp) and frames (src/raster/frame_renderer.cpp).
#ifndef TALKFACE_RENDER_DRAWING_HPP
#define TALKFACE_RENDER_DRAWING_HPP

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "render/curves.hpp"
#include "talkface/types.hpp"

namespace talkface::detail {

// One step of a path; each takes the points after the previous step's.
enum class PathVerb : std::uint8_t {
    move,       // 1 point: starts a subpath
    line,       // 1 point
    cubic,      // 3 points: c1, c2, end
    quadratic,  // 2 points: control, end
    close,      // 0 points: back to the subpath's start
};

// How many points `verb` takes.
int points_of(PathVerb verb);

// A path as verbs and the points they take, in order.
struct Path {
    std::vector<PathVerb> verbs;
    std::vector<Point2> points;

    Path& move_to(Point2 point);
    Path& line_to(Point2 point);
    Path& curves(const std::vector<CubicSegment>& segments);
    // arc(points) (curves.hpp) from points.front(), which must be the pen's position (or a new move).
    Path& arc(const std::vector<Point2>& points);
    // The closed polygon `corners` cut at its corners without end (thesis 2.2, Chaikin's corner
    // cutting: each edge keeps its 1/4 and 3/4 points, round after round): the limit is the
    // quadratic B-spline of the polygon, one quadratic Bezier segment per corner, from the middle of
    // the edge before it to the middle of the edge after it, with the corner as its control point.
    // Inside the polygon's convex hull. Starts with a move; nothing for fewer than 3 corners.
    Path& corner_cut_closed(const std::vector<Point2>& corners);
    Path& close();
    bool operator==(const Path& other) const { return verbs == other.verbs && points == other.points; }
};

// A colour stop of a gradient; offset 0..1 along the gradient's radius.
struct GradientStop {
    double offset = 0.0;
    Rgb colour;
};

// A radial gradient in the painted shape's bounding box units (SVG objectBoundingBox): the
// centre at (cx, cy), the last stop at radius r, the focus at the centre; padded beyond.
struct RadialGradient {
    double cx = 0.5, cy = 0.5, r = 0.5;
    std::vector<GradientStop> stops;
};

enum class PaintKind : std::uint8_t { none, colour, gradient };

// How a fill or a stroke is painted: nothing, a colour, or a gradient of the layer's definitions.
struct Paint {
    PaintKind kind = PaintKind::none;
    Rgb colour;
    std::size_t gradient = 0;  // index into Layer::definitions, for PaintKind::gradient
    static Paint of(Rgb colour) { return {PaintKind::colour, colour, 0}; }
    static Paint of_gradient(std::size_t definition) { return {PaintKind::gradient, Rgb{}, definition}; }
};

// A shape's fill and stroke. A stroke of PaintKind::none draws no outline.
struct ShapePaint {
    Paint fill;
    Paint stroke;
    double stroke_width = 0.0;  // in the drawing's units
};

enum class DefinitionKind : std::uint8_t { clip_path, radial_gradient };

// A clip path (an outline, drawn again by references) or a gradient. Ids are static text ("tf-..."),
// unique in a document; an animation's frames encoding prefixes them per frame.
//
// A clip path may instead be an earlier clip path's outline moved by `offset` (`is_moved` set,
// `source` that clip path, which has an outline of its own; `outline` and `outline_id` empty): a shape that follows another at a
// fixed distance costs an animation no numbers of its own. Moves (here and on references) are
// static: an animation writes frame 0's.
struct Definition {
    DefinitionKind kind = DefinitionKind::clip_path;
    std::string_view id;
    std::string_view outline_id;  // clip_path: the id of its outline path
    Path outline;                 // clip_path: what is inside it is drawn, nonzero rule
    bool is_moved = false;        // clip_path: `source`'s outline moved by `offset`
    std::size_t source = 0;
    Point2 offset{0.0, 0.0};
    RadialGradient gradient;      // radial_gradient
};

enum class ShapeKind : std::uint8_t { path, polyline, circle, rect, reference, group };

// One element of a layer. `name` is static text (the SVG class), empty for none.
struct Shape {
    ShapeKind kind = ShapeKind::path;
    std::string_view name;
    ShapePaint paint;
    Path path;                   // path
    std::vector<Point2> points;  // polyline: open, its fill closes it
    Point2 centre;               // circle
    double radius = 0.0;         // circle
    Point2 corner;               // rect: its top-left corner, and its size
    double width = 0.0, height = 0.0;
    std::size_t definition = 0;  // reference: the clip path whose outline it draws; group: its clip
    Point2 offset{0.0, 0.0};     // reference: the outline drawn moved by this
    bool is_clipped = false;     // group: clipped by `definition`
    std::vector<Shape> children; // group: drawn in order
};

// One layer's content (its id and place in the document are the document's).
struct Layer {
    std::vector<Definition> definitions;
    std::vector<Shape> elements;
};

// `path` moved by `offset`.
Path moved(const Path& path, Point2 offset);

// The outline a clip path clips to: its own, or its source's moved.
Path clip_outline(const Layer& layer, const Definition& clip);

// The outline a reference draws: its clip path's, moved by its offset.
Path reference_outline(const Layer& layer, const Shape& reference);

// A number an animation may move, in document order: a path's points, a polyline's points, a
// circle's cx, cy, r, a rectangle's x, y, width, height.
enum class AttributeKind : std::uint8_t { path_data, polyline_points, number };

struct NumericAttribute {
    AttributeKind kind = AttributeKind::number;
    const char* name = "";                    // the SVG attribute: "d", "points", "cx" ...
    const Path* path = nullptr;               // path_data
    const std::vector<Point2>* points = nullptr;  // polyline_points
    double value = 0.0;                       // number
};

// Every numeric attribute of `layer`, in the order svg_writer.cpp writes them (the definitions
// first, then the elements, a group's children in place; moved clip paths and offsets are none). Cleared first. The pointers point into
// `layer`.
void list_numeric_attributes(const Layer& layer, std::vector<NumericAttribute>& attributes);

}  // namespace talkface::detail

#endif
