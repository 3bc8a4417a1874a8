// One layer of the drawing model (drawing.hpp) over an animation's frames, as Lottie shape layers
// (lottie-web's JSON schema): each shape a group ("gr") of its geometry ("sh" Bezier paths, "el"
// circles, "rc" rectangles), its stroke and fill ("st"/"fl", "gs"/"gf" for radial gradients) and a
// transform ("tr"). A group clipped by a clip path becomes a layer of its own, masked by the clip's
// outline (Lottie clips layers, not groups), and a clipped group inside it one masked by both
// outlines, intersected; so a drawing layer may give several Lottie layers; so
// does a gradient fill on a shape other than a circle (SVG stretches it over the shape's box, which
// Lottie can only do with a transform: a unit square stretched onto the box, masked by the shape).
//
// Nothing here knows the face's parts: whatever shapes a layer builder draws are written. Every
// number (coordinates, radii, colours, stroke widths, gradient stops and their box) is a property:
// static where it holds still, else animated between key frames chosen as the SVG keyframes
// encoding chooses its own (key_frames.hpp), so that linear interpolation stays within the
// tolerance of every frame. As there, every frame must draw the same shapes with the same path
// verbs (only the numbers change); a frame that does not is a bug, reported as one.
#ifndef TALKFACE_RENDER_LOTTIE_LAYER_ENCODER_HPP
#define TALKFACE_RENDER_LOTTIE_LAYER_ENCODER_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "render/drawing.hpp"
#include "render/key_frames.hpp"

namespace talkface::detail {

// A Lottie layer's content: its shapes and, for a clipped group, its masks (JSON arrays).
struct LottieLayerContent {
    std::string name;
    std::string shapes;  // "[...]", the top shape first, as Lottie lists them
    std::string masks;   // "[...]" or empty for none
};

// A one-number property (a layer transform's rotation, degrees) keyed as the encoder keys its
// shapes' numbers: {"a":0,"k":held_value} when `keys` has none.
std::string lottie_scalar_property(const KeyFrames& keys, double held_value, int decimals);

class LottieLayerEncoder {
public:
    // `name` names the Lottie layers; `tolerance`: the largest distance, in the drawing's units,
    // between an interpolated coordinate and the frame's; `decimals`: digits of the written
    // coordinates (the key frames are chosen on numbers a digit finer: the same keys at any digits);
    // `expected_frames`: how many frames will come (room is reserved once).
    LottieLayerEncoder(std::string name, double tolerance, int decimals, std::size_t expected_frames);

    // The next frame's layer.
    // \throws talkface::Error (internal) if it draws other shapes or path verbs than the first, a
    //         gradient-filled shape (but a circle) inside a clipped group, or a clip of several
    //         subpaths inside one (Lottie intersects masks one at a time).
    void add(const Layer& layer);

    // The next frame is the same as the one before.
    void add_repeat();

    // The Lottie layers in paint order (the bottom one first); empty ones are left out. A layer
    // added once holds still however many frames the document has.
    std::vector<LottieLayerContent> finish() const;

    // The properties recorded (tests: how much moves).
    std::size_t property_count() const { return properties_.size(); }
    std::size_t animated_property_count() const;

private:
    enum class Form { scalar, vector, bezier };
    struct Property {
        Form form = Form::vector;
        bool closed = false;  // bezier: the path is closed
        double tolerance = 0.0;
        int decimals = 0;
        TrackRecorder numbers;
    };
    struct Frame;  // one frame's walk: its numbers and, for the first, the text

    std::string property_text(const Property& property) const;

    std::string name_;
    double tolerance_;
    int decimals_;
    std::size_t expected_frames_;
    std::size_t frame_count_ = 0;
    std::vector<Property> properties_;
    std::vector<LottieLayerContent> templates_;  // with a placeholder per property
};

}  // namespace talkface::detail

#endif
