// The temporal half of thesis 6.3.2: every frame of an Animation drawn as by the spatial half, then
// written either as one group per frame (the thesis's <set> frames) or as one face whose moving
// attributes are SMIL <animate> elements over key frames chosen per attribute.
//
// The key frames come from the drawn frames themselves, not from the mouth key frames and events:
// whatever moves (lips, jaw, lids, eyeballs, the whole head) gets exactly the key frames it needs
// for linear interpolation to stay within the tolerance of every frame, and whatever holds still
// gets none. This relies on each frame's document having the same elements and the same path
// commands, only other numbers: the layers draw a fixed number of points at every pose (contour
// substitution changes which points, not how many). A frame that breaks this is a bug, reported
// as one.
#include "render/svg_animation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/number_format.hpp"
#include "render/svg_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Progress shares of the two stages: drawing the frames is most of the work.
constexpr double kFramesShare = 0.85;
constexpr std::size_t kProgressEveryFrames = 50;

void report(const ProgressCallback& progress, double fraction, const char* stage, std::size_t frame) {
    if (progress && !progress(fraction, stage)) {
        throw Cancelled("rendering the animation was cancelled at frame " + std::to_string(frame));
    }
}

void validate(const Animation& animation, const SvgAnimationOptions& options) {
    if (animation.frames.empty()) throw InvalidArgument("animation", "has no frames");
    if (!std::isfinite(animation.fps) || animation.fps <= 0.0) {
        throw InvalidArgument("animation.fps", "expected a finite number > 0, found " +
                                                   format_shortest(animation.fps));
    }
    if (!std::isfinite(options.tolerance_px) || options.tolerance_px <= 0.0) {
        throw InvalidArgument("tolerance_px", "expected a finite number > 0, found " +
                                                  format_shortest(options.tolerance_px));
    }
    const int encoding = static_cast<int>(options.encoding);
    if (encoding != static_cast<int>(AnimationEncoding::keyframes) &&
        encoding != static_cast<int>(AnimationEncoding::frames)) {
        throw InvalidArgument("encoding", "expected keyframes or frames, found " + std::to_string(encoding));
    }
}

// Seconds as SMIL clock values: milliseconds are finer than any frame.
std::string clock_value(double seconds) { return format_fixed(seconds, 3) + "s"; }

// --- frames ----------------------------------------------------------------------------------

// Each frame's clip paths and gradients need ids of their own: ids are unique per document.
std::string with_frame_ids(const std::string& layers, std::size_t group) {
    const std::string prefix = "f" + std::to_string(group) + "-";
    std::string result;
    result.reserve(layers.size() + 64);
    std::size_t position = 0;
    while (true) {
        const std::size_t id = layers.find("id=\"tf-", position);
        const std::size_t url = layers.find("url(#tf-", position);
        const std::size_t href = layers.find("href=\"#tf-", position);
        const std::size_t next = std::min({id, url, href});
        if (next == std::string::npos) break;
        const std::size_t insert_at = next == id ? id + 4 : next == url ? url + 5 : href + 7;
        result.append(layers, position, insert_at - position);
        result += prefix;
        position = insert_at;
    }
    result.append(layers, position, std::string::npos);
    return result;
}

// One layer of every frame as groups shown in turn, written as the frames come; a run of identical
// frames is one group.
class FramesEncoder {
public:
    FramesEncoder(const std::string& layer_id, double fps, std::size_t& group_counter)
        : fps_(fps), groups_(group_counter), svg_("<g" + attribute("id", layer_id) + ">\n") {}

    void add(std::string layer) {
        if (frames_ > 0 && layer == run_) {
            ++frames_;
            return;
        }
        if (frames_ > 0) flush(false);
        run_ = std::move(layer);
        run_start_ = frames_++;
    }

    std::string finish() {
        flush(true);
        return svg_ + "</g>\n";
    }

private:
    void flush(bool is_last) {
        const double begin_s = static_cast<double>(run_start_) / fps_;
        // The last group stays on after the end, as the key-frame encoding's fill="freeze" does.
        const std::string timing =
            is_last ? attribute("begin", clock_value(begin_s)) + attribute("fill", "freeze")
                    : attribute("begin", clock_value(begin_s)) +
                          attribute("dur", clock_value(static_cast<double>(frames_) / fps_ - begin_s));
        svg_ += "<g visibility=\"hidden\">\n<set attributeName=\"visibility\" to=\"visible\"" + timing + "/>\n";
        svg_ += with_frame_ids(run_, groups_++);
        svg_ += "</g>\n";
    }

    double fps_;
    std::size_t& groups_;
    std::string svg_;
    std::string run_;
    std::size_t run_start_ = 0;
    std::size_t frames_ = 0;
};

// --- keyframes -------------------------------------------------------------------------------

// A document cut at its attribute values: literals[0] value[0] literals[1] value[1] ... literals[n].
struct AttributeSplit {
    std::vector<std::string_view> literals;
    std::vector<std::string_view> values;
};

AttributeSplit split_attributes(std::string_view text) {
    AttributeSplit split;
    std::size_t position = 0;
    while (true) {
        const std::size_t open = text.find("=\"", position);
        if (open == std::string_view::npos) break;
        const std::size_t value_start = open + 2;
        const std::size_t close = text.find('"', value_start);
        split.literals.push_back(text.substr(position, value_start - position));
        split.values.push_back(text.substr(value_start, close - value_start));
        position = close;
    }
    split.literals.push_back(text.substr(position));
    return split;
}

bool starts_number(std::string_view text, std::size_t i) {
    const auto is_digit = [&](std::size_t k) { return k < text.size() && text[k] >= '0' && text[k] <= '9'; };
    if (is_digit(i)) return true;
    if (text[i] == '-' || text[i] == '.') return is_digit(i + 1) || (text[i] == '-' && i + 2 < text.size() &&
                                                                     text[i + 1] == '.' && is_digit(i + 2));
    return false;
}

// The numbers of an attribute value and the text between them ("M1,2 C3,4" -> 1 2 3 4 and
// "M" "," " C" "," ""). Only attributes that change are read this way, and they hold coordinates.
void read_numbers(std::string_view text, std::vector<float>& numbers, std::vector<std::string>* pieces) {
    std::size_t piece_start = 0;
    for (std::size_t i = 0; i < text.size();) {
        if (!starts_number(text, i)) {
            ++i;
            continue;
        }
        double value = 0.0;
        const auto result = std::from_chars(text.data() + i, text.data() + text.size(), value);
        if (pieces != nullptr) pieces->emplace_back(text.substr(piece_start, i - piece_start));
        numbers.push_back(static_cast<float>(value));
        i = static_cast<std::size_t>(result.ptr - text.data());
        piece_start = i;
    }
    if (pieces != nullptr) pieces->emplace_back(text.substr(piece_start));
}

// Appends the numbers of `text` if it is `pieces` with numbers between them, as the frame 0 value
// they were read from; false if it is not (other commands, another count). One pass, as this
// runs for every moving attribute of every frame.
bool read_matching_numbers(std::string_view text, const std::vector<std::string>& pieces, std::vector<float>& numbers) {
    std::size_t i = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (text.compare(i, pieces[k].size(), pieces[k]) != 0) return false;
        i += pieces[k].size();
        if (k + 1 == pieces.size()) break;
        if (i >= text.size() || !starts_number(text, i)) return false;
        double value = 0.0;
        const auto result = std::from_chars(text.data() + i, text.data() + text.size(), value);
        numbers.push_back(static_cast<float>(value));
        i = static_cast<std::size_t>(result.ptr - text.data());
    }
    return i == text.size();
}

// One attribute of the first frame's document, followed through every frame.
struct Track {
    std::vector<std::string> pieces;  // the text around its numbers
    std::size_t width = 0;            // numbers per frame
    std::vector<float> numbers;       // width numbers per frame, frame after frame
    bool varies = false;
};

// Frames where the attribute is a key frame: the first, the last, and in between each frame where
// going straight on to the next frame would let some earlier frame stray beyond the tolerance.
// For each number the admissible slopes from the segment's start form an interval that every frame
// inside the segment narrows; a frame can end the segment while its own slope stays inside every
// interval. Linear in the frames.
std::vector<std::size_t> choose_key_frames(const Track& track, std::size_t frame_count,
                                           const std::vector<double>& tolerances) {
    std::vector<std::size_t> keys{0};
    const std::size_t width = track.width;
    std::vector<double> low(width);
    std::vector<double> high(width);
    auto value = [&](std::size_t frame, std::size_t k) {
        return static_cast<double>(track.numbers[frame * width + k]);
    };
    std::size_t start = 0;
    auto reset = [&] {
        std::fill(low.begin(), low.end(), -std::numeric_limits<double>::infinity());
        std::fill(high.begin(), high.end(), std::numeric_limits<double>::infinity());
    };
    reset();
    for (std::size_t frame = 1; frame < frame_count; ++frame) {
        const double span = static_cast<double>(frame - start);
        bool fits = true;
        for (std::size_t k = 0; k < width && fits; ++k) {
            const double slope = (value(frame, k) - value(start, k)) / span;
            fits = slope >= low[k] && slope <= high[k];
        }
        if (!fits) {
            // The segment ends at the frame before; this frame opens the constraints of the next.
            start = frame - 1;
            keys.push_back(start);
            reset();
        }
        const double new_span = static_cast<double>(frame - start);
        for (std::size_t k = 0; k < width; ++k) {
            const double offset = value(frame, k) - value(start, k);
            low[k] = std::max(low[k], (offset - tolerances[k]) / new_span);
            high[k] = std::min(high[k], (offset + tolerances[k]) / new_span);
        }
    }
    if (keys.back() != frame_count - 1) keys.push_back(frame_count - 1);
    return keys;
}

// Animated values are written in tenths of a pixel: 0.05 px of rounding on top of the tolerance,
// far below what shows, and a third fewer bytes than the frames' own two decimals.
constexpr double kValueScale = 10.0;

// A number in tenths as short as SVG allows: "12.3", "-.5", "7".
void append_tenths(std::string& text, long tenths) {
    if (tenths < 0) {
        text += '-';
        tenths = -tenths;
    }
    const long whole = tenths / 10;
    const long tenth = tenths % 10;
    if (whole != 0 || tenth == 0) text += std::to_string(whole);
    if (tenth != 0) {
        text += '.';
        text += static_cast<char>('0' + tenth);
    }
}

void append_separated(std::string& text, long tenths) {
    // A minus sign separates numbers by itself in SVG's number lists and path data.
    if (!text.empty() && tenths >= 0) {
        const char last = text.back();
        if ((last >= '0' && last <= '9') || last == '.') text += ' ';
    }
    append_tenths(text, tenths);
}

std::vector<long> rounded_tenths(const Track& track, std::size_t frame) {
    std::vector<long> tenths(track.width);
    for (std::size_t k = 0; k < track.width; ++k) {
        tenths[k] = std::lround(static_cast<double>(track.numbers[frame * track.width + k]) * kValueScale);
    }
    return tenths;
}

// A value with the frame's numbers, in the text of frame 0 (a point list, a coordinate).
std::string track_value(const Track& track, std::size_t frame) {
    const std::vector<long> tenths = rounded_tenths(track, frame);
    std::string text;
    for (std::size_t k = 0; k < track.width; ++k) {
        text += track.pieces[k];
        append_tenths(text, tenths[k]);
    }
    text += track.pieces[track.width];
    return text;
}

// Path data with relative commands: the same shape in fewer bytes (small offsets instead of full
// coordinates), and interpolating offsets is interpolating coordinates, since the map between them
// is linear. Offsets are taken between rounded coordinates, so rounding never accumulates along the
// path. Our paths use M, L, C and Z only, each command letter written before its points.
std::string relative_path_value(const Track& track, std::size_t frame) {
    const std::vector<long> tenths = rounded_tenths(track, frame);
    std::string text;
    long current_x = 0, current_y = 0, start_x = 0, start_y = 0;
    long reference_x = 0, reference_y = 0;
    char command = 'M';
    int pair_in_command = 0;
    for (std::size_t k = 0; k + 1 < track.width; k += 2) {
        for (const char c : track.pieces[k]) {
            if (c == 'Z') {
                text += 'z';
                current_x = start_x;
                current_y = start_y;
            } else if (c == 'M' || c == 'L' || c == 'C') {
                command = c;
                pair_in_command = 0;
                text += k == 0 ? 'M' : static_cast<char>(c - 'A' + 'a');
            }
        }
        // Every point of a cubic segment is relative to where the segment starts (SVG "c").
        if (command != 'C' || pair_in_command == 0) {
            reference_x = k == 0 ? 0 : current_x;
            reference_y = k == 0 ? 0 : current_y;
        }
        const long x = tenths[k];
        const long y = tenths[k + 1];
        append_separated(text, x - reference_x);
        append_separated(text, y - reference_y);
        ++pair_in_command;
        if (command != 'C' || pair_in_command % 3 == 0) {
            current_x = x;
            current_y = y;
            if (command == 'M') {
                start_x = x;
                start_y = y;
            }
        }
    }
    if (track.pieces[track.width].find('Z') != std::string::npos) text += 'z';
    return text;
}

std::string key_times_of(const std::vector<std::size_t>& keys, std::size_t frame_count) {
    const double last = static_cast<double>(frame_count - 1);
    std::string key_times;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (i > 0) key_times += ';';
        // Six digits place a key time within 1 ms on an animation of 15 minutes.
        key_times += format_fixed(static_cast<double>(keys[i]) / last, 6);
    }
    return key_times;
}

std::string animate_element(std::string_view attribute_name, const Track& track, std::size_t frame_count,
                            double duration_s, const SvgAnimationOptions& options) {
    const bool is_path = attribute_name == "d";
    const std::vector<std::size_t> keys =
        choose_key_frames(track, frame_count, std::vector<double>(track.width, options.tolerance_px));
    std::string values;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (i > 0) values += ';';
        values += is_path ? relative_path_value(track, keys[i]) : track_value(track, keys[i]);
    }
    return "<animate attributeName=\"" + std::string(attribute_name) + "\"" +
           attribute("dur", clock_value(duration_s)) + attribute("values", values) +
           attribute("keyTimes", key_times_of(keys, frame_count)) + " fill=\"freeze\"/>";
}

// --- point lists that move as a whole ----------------------------------------------------------
//
// Under a head pose the hair polygon is close to an affine map of its first frame (SPEC "Pose":
// rotation and orthographic projection, plus a hair shift that is smooth in x). So a point list
// can be written as its first frame, centred, under an animated map: six numbers a key frame in
// place of every point's two. Where the map alone strays (a strong turn bends the hair a little
// more than an affine map does, a brow rises), the points themselves are animated as well, as what the map must be given to land on the frame (its pre-image): constant
// within their share of the tolerance wherever the map fits, so key frames only where it does not.
// The encoder keeps this or the plain animation, whichever is shorter. (Paths were tried too: the
// nose, eyes and face outline change shape with the pose and the jaw, and never came out shorter.)
//
// SMIL has no matrix animation, so the map is written as translate, rotate, skewX and scale
// (M = R(angle) * [[1, tan(skew)], [0, 1]] * diag(sx, sy), a QR decomposition), each an
// <animateTransform additive="sum"> after the static translate to the centre. The stroke scales
// with the map, by the few percent a pose shrinks or stretches the hair: not visible.

// Parameters of one frame's map, in the order they are animated.
enum RigidParameter : std::size_t { kTx, kTy, kAngle, kSkew, kScaleX, kScaleY, kRigidWidth };

struct RigidMotion {
    double centre_x = 0.0, centre_y = 0.0;
    Track parameters;                // kRigidWidth numbers a frame (degrees for the angles)
    std::vector<double> tolerances;  // per parameter, so that their errors add up within the map's share
    Track preimage;                  // the points each frame's map takes onto that frame, centred
    double preimage_tolerance = 0.0;
};

constexpr double kDegreesPerRadian = 57.29577951308232;
// Digits of the animated map: together they move a point by less than 0.02 px at 300 px.
constexpr int kTranslateDecimals = 2;
constexpr int kAngleDecimals = 3;
constexpr int kScaleDecimals = 4;
// Rounding of the written map, kept out of its share of the tolerance.
constexpr double kMapRoundingPx = 0.02;
// The map's share of the tolerance; the pre-image has the rest. The map's key frames are short.
constexpr double kMapShare = 0.25;
// An affine map needs three points that are not on one line; fewer than six rarely pay for it.
constexpr std::size_t kMinRigidNumbers = 12;

std::optional<RigidMotion> fit_rigid_motion(const Track& track, std::size_t frame_count, double tolerance) {
    const std::size_t points = track.width / 2;
    if (track.width < kMinRigidNumbers || track.width % 2 != 0) return std::nullopt;
    RigidMotion motion;
    for (std::size_t i = 0; i < points; ++i) {
        motion.centre_x += static_cast<double>(track.numbers[2 * i]);
        motion.centre_y += static_cast<double>(track.numbers[2 * i + 1]);
    }
    motion.centre_x /= static_cast<double>(points);
    motion.centre_y /= static_cast<double>(points);
    std::vector<double> centred(track.width);
    double qxx = 0.0, qxy = 0.0, qyy = 0.0, radius = 0.0;
    for (std::size_t i = 0; i < points; ++i) {
        const double x = static_cast<double>(track.numbers[2 * i]) - motion.centre_x;
        const double y = static_cast<double>(track.numbers[2 * i + 1]) - motion.centre_y;
        centred[2 * i] = x;
        centred[2 * i + 1] = y;
        qxx += x * x;
        qxy += x * y;
        qyy += y * y;
        radius = std::max(radius, std::hypot(x, y));
    }
    const double determinant = qxx * qyy - qxy * qxy;
    if (!(determinant > 0.0)) return std::nullopt;
    motion.parameters.width = kRigidWidth;
    motion.parameters.numbers.reserve(frame_count * kRigidWidth);
    motion.preimage.width = track.width;
    motion.preimage.numbers.reserve(track.numbers.size());
    double gain = 1.0;  // how much the maps can enlarge an error of the pre-image, per coordinate
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        const float* p = track.numbers.data() + frame * track.width;
        double mean_x = 0.0, mean_y = 0.0;
        for (std::size_t i = 0; i < points; ++i) {
            mean_x += static_cast<double>(p[2 * i]);
            mean_y += static_cast<double>(p[2 * i + 1]);
        }
        mean_x /= static_cast<double>(points);
        mean_y /= static_cast<double>(points);
        // Least squares M = (sum p q^T)(sum q q^T)^-1, with p and q both centred.
        double sxx = 0.0, sxy = 0.0, syx = 0.0, syy = 0.0;
        for (std::size_t i = 0; i < points; ++i) {
            const double px = static_cast<double>(p[2 * i]) - mean_x;
            const double py = static_cast<double>(p[2 * i + 1]) - mean_y;
            sxx += px * centred[2 * i];
            sxy += px * centred[2 * i + 1];
            syx += py * centred[2 * i];
            syy += py * centred[2 * i + 1];
        }
        const double m00 = (sxx * qyy - sxy * qxy) / determinant;
        const double m01 = (sxy * qxx - sxx * qxy) / determinant;
        const double m10 = (syx * qyy - syy * qxy) / determinant;
        const double m11 = (syy * qxx - syx * qxy) / determinant;
        const double map_determinant = m00 * m11 - m01 * m10;
        const double angle = std::atan2(m10, m00);
        const double scale_x = std::hypot(m00, m10);
        const double shear = std::cos(angle) * m01 + std::sin(angle) * m11;
        const double scale_y = -std::sin(angle) * m01 + std::cos(angle) * m11;
        if (!(scale_x > 0.0) || !(scale_y > 0.0) || !(map_determinant > 0.0)) return std::nullopt;
        gain = std::max({gain, std::abs(m00) + std::abs(m01), std::abs(m10) + std::abs(m11)});
        for (const double value : {mean_x - motion.centre_x, mean_y - motion.centre_y, angle * kDegreesPerRadian,
                                   std::atan(shear / scale_y) * kDegreesPerRadian, scale_x, scale_y}) {
            motion.parameters.numbers.push_back(static_cast<float>(value));
        }
        for (std::size_t i = 0; i < points; ++i) {
            const double px = static_cast<double>(p[2 * i]) - mean_x;
            const double py = static_cast<double>(p[2 * i + 1]) - mean_y;
            motion.preimage.numbers.push_back(static_cast<float>((m11 * px - m01 * py) / map_determinant));
            motion.preimage.numbers.push_back(static_cast<float>((m00 * py - m10 * px) / map_determinant));
        }
    }
    // A point at `radius` moves by the translation error plus radius times each other error (in
    // radians or relative scale), to first order: five equal parts of the map's share. The
    // pre-image is written in tenths of a pixel, as other animated values.
    const double share = (kMapShare * tolerance - kMapRoundingPx) / 5.0;
    const double preimage_share = (1.0 - kMapShare) * tolerance - 0.5 / kValueScale;
    if (!(share > 0.0) || !(preimage_share > 0.0)) return std::nullopt;
    const double angular = share / radius * kDegreesPerRadian;
    motion.tolerances = {share, share, angular, angular, share / radius, share / radius};
    motion.preimage_tolerance = preimage_share / gain;
    return motion;
}

// Numbers `first` .. `first + count` of a frame, separated by spaces.
std::string fixed_value(const Track& track, std::size_t frame, std::size_t first, std::size_t count,
                        int decimals) {
    std::string text;
    for (std::size_t k = first; k < first + count; ++k) {
        if (k > first) text += ' ';
        text += format_fixed(static_cast<double>(track.numbers[frame * track.width + k]), decimals);
    }
    return text;
}

// The pre-image of frame 0 as the attribute's value, the static translate to the centre, and the
// animations that follow the map (and the pre-image, where it moves).
struct RigidText {
    std::string value;
    std::string animations;
};

RigidText rigid_motion_text(RigidMotion motion, const Track& track, std::size_t frame_count, double duration_s) {
    motion.preimage.pieces = track.pieces;
    RigidText text;
    text.value = track_value(motion.preimage, 0) +
                 "\" transform=\"translate(" + format_fixed(motion.centre_x, 2) + " " +
                 format_fixed(motion.centre_y, 2) + ")";
    const std::vector<double> preimage_tolerances(track.width, motion.preimage_tolerance);
    const std::vector<std::size_t> preimage_keys = choose_key_frames(motion.preimage, frame_count, preimage_tolerances);
    // Two key frames within the tolerance of every frame, and equal within it: the map alone suffices.
    bool preimage_moves = preimage_keys.size() > 2;
    for (std::size_t k = 0; k < track.width && !preimage_moves; ++k) {
        preimage_moves = std::abs(motion.preimage.numbers[k] -
                                  motion.preimage.numbers[(frame_count - 1) * track.width + k]) >
                         motion.preimage_tolerance;
    }
    if (preimage_moves) {
        std::string values;
        for (std::size_t i = 0; i < preimage_keys.size(); ++i) {
            if (i > 0) values += ';';
            values += track_value(motion.preimage, preimage_keys[i]);
        }
        text.animations += "<animate attributeName=\"points\"" + attribute("dur", clock_value(duration_s)) +
                           attribute("values", values) +
                           attribute("keyTimes", key_times_of(preimage_keys, frame_count)) + " fill=\"freeze\"/>";
    }
    const std::vector<std::size_t> keys = choose_key_frames(motion.parameters, frame_count, motion.tolerances);
    const std::string key_times = key_times_of(keys, frame_count);
    struct Part {
        const char* type;
        std::size_t first, count;
        int decimals;
    };
    for (const Part& part : {Part{"translate", kTx, 2, kTranslateDecimals}, Part{"rotate", kAngle, 1, kAngleDecimals},
                             Part{"skewX", kSkew, 1, kAngleDecimals}, Part{"scale", kScaleX, 2, kScaleDecimals}}) {
        std::string values;
        for (std::size_t i = 0; i < keys.size(); ++i) {
            if (i > 0) values += ';';
            values += fixed_value(motion.parameters, keys[i], part.first, part.count, part.decimals);
        }
        text.animations += "<animateTransform attributeName=\"transform\"" + attribute("type", part.type) +
                           " additive=\"sum\"" + attribute("dur", clock_value(duration_s)) +
                           attribute("values", values) + attribute("keyTimes", key_times) + " fill=\"freeze\"/>";
    }
    return text;
}

// The name of the attribute whose value follows `literal` (`... d="` -> "d").
std::string_view attribute_name(std::string_view literal) {
    const std::size_t end = literal.size() - 2;  // before `="`
    std::size_t start = end;
    while (start > 0 && literal[start - 1] != ' ' && literal[start - 1] != '\n') --start;
    return literal.substr(start, end - start);
}

// The tag of the element whose start tag is open at the end of `literal`, if one opens in it.
std::string_view opened_tag(std::string_view literal) {
    const std::size_t open = literal.rfind('<');
    if (open == std::string_view::npos || open + 1 >= literal.size() || literal[open + 1] == '/') return {};
    std::size_t end = open + 1;
    while (end < literal.size() && literal[end] != ' ' && literal[end] != '>' && literal[end] != '/') ++end;
    return literal.substr(open + 1, end - open - 1);
}

// The first frame's document with an <animate> for every attribute that changes, written once all
// frames have come. Only the numbers of changing attributes are kept, not the frames' text.
class KeyframesEncoder {
public:
    // `expected_frames`: how many frames will come, so that each moving attribute's numbers are
    // allocated once instead of copied as they grow.
    KeyframesEncoder(double fps, const SvgAnimationOptions& options, std::size_t expected_frames)
        : fps_(fps), options_(options), expected_frames_(expected_frames) {}

    void add(std::string frame_text) {
        if (frame_count_++ == 0) {
            first_text_ = std::move(frame_text);
            first_ = split_attributes(first_text_);
            tracks_.resize(first_.values.size());
            return;
        }
        const std::size_t frame = frame_count_ - 1;
        const AttributeSplit split = split_attributes(frame_text);
        if (split.values.size() != tracks_.size()) {
            throw Error(ErrorCode::internal, "internal error (a bug in talkface): frame " + std::to_string(frame) +
                                                 " has " + std::to_string(split.values.size()) +
                                                 " attributes, frame 0 has " + std::to_string(tracks_.size()));
        }
        for (std::size_t slot = 0; slot < tracks_.size(); ++slot) {
            Track& track = tracks_[slot];
            const std::string_view value = split.values[slot];
            if (!track.varies) {
                if (value == first_.values[slot]) continue;
                start_track(slot, frame);
            }
            if (!read_matching_numbers(value, track.pieces, track.numbers)) {
                throw Error(ErrorCode::internal,
                            "internal error (a bug in talkface): frame " + std::to_string(frame) + " draws attribute " +
                                std::string(attribute_name(first_.literals[slot])) +
                                " with other path commands or another number of coordinates than frame 0");
            }
        }
    }

    // The next frame is the same as the one before.
    void add_repeat() {
        if (frame_count_++ == 0) throw Error(ErrorCode::internal, "internal error (a bug in talkface): no frame to repeat");
        for (Track& track : tracks_) {
            if (!track.varies) continue;
            const std::size_t last = track.numbers.size() - track.width;
            for (std::size_t k = 0; k < track.width; ++k) track.numbers.push_back(track.numbers[last + k]);
        }
    }

    std::string finish(const ProgressCallback& progress) const {
        const double duration_s = static_cast<double>(frame_count_ - 1) / fps_;
        std::string svg;
        svg.reserve(first_text_.size() * 4);
        std::string pending;  // <animate> elements of the element whose start tag is open
        std::string_view tag;
        for (std::size_t slot = 0; slot <= tracks_.size(); ++slot) {
            std::string_view literal = first_.literals[slot];
            if (!pending.empty()) {
                const std::size_t close = literal.find('>');
                if (close != std::string_view::npos) {
                    const bool self_closing = close > 0 && literal[close - 1] == '/';
                    svg.append(literal.substr(0, self_closing ? close - 1 : close));
                    svg += '>';
                    svg += pending;
                    if (self_closing) svg += "</" + std::string(tag) + ">";
                    pending.clear();
                    literal.remove_prefix(close + 1);
                }
            }
            svg.append(literal);
            const std::string_view opened = opened_tag(first_.literals[slot]);
            if (!opened.empty()) tag = opened;
            if (slot == tracks_.size()) break;
            const std::string_view name = attribute_name(first_.literals[slot]);
            std::optional<RigidMotion> rigid;
            if (tracks_[slot].varies && name == "points") {
                rigid = fit_rigid_motion(tracks_[slot], frame_count_, options_.tolerance_px);
            }
            std::string animation;
            if (tracks_[slot].varies) {
                animation = animate_element(name, tracks_[slot], frame_count_, duration_s, options_);
            }
            std::optional<RigidText> moved;
            if (rigid) {
                moved = rigid_motion_text(std::move(*rigid), tracks_[slot], frame_count_, duration_s);
            }
            if (moved && moved->value.size() + moved->animations.size() <
                             first_.values[slot].size() + animation.size()) {
                svg += moved->value;
                pending += moved->animations;
            } else {
                svg.append(first_.values[slot]);
                pending += animation;
            }
            if (slot % 16 == 0) {
                report(progress, kFramesShare + (1.0 - kFramesShare) * static_cast<double>(slot) /
                                                    static_cast<double>(tracks_.size()),
                       "encoding", frame_count_);
            }
        }
        return svg;
    }

private:
    // The attribute at `slot` first differs from frame 0 at `frame`: from now on its numbers are
    // kept, with frame 0's for every frame before.
    void start_track(std::size_t slot, std::size_t frame) {
        Track& track = tracks_[slot];
        track.varies = true;
        std::vector<float> numbers;
        read_numbers(first_.values[slot], numbers, &track.pieces);
        track.width = numbers.size();
        track.numbers.reserve(expected_frames_ * track.width);
        for (std::size_t earlier = 0; earlier < frame; ++earlier) {
            track.numbers.insert(track.numbers.end(), numbers.begin(), numbers.end());
        }
    }

    double fps_;
    SvgAnimationOptions options_;
    std::size_t expected_frames_;
    std::size_t frame_count_ = 0;
    std::string first_text_;
    AttributeSplit first_;
    std::vector<Track> tracks_;
};

}  // namespace

std::string open_svg_root(const SvgCanvas& canvas, int decimals, const std::string& class_name) {
    auto number = [&](double value) { return format_fixed(value, decimals); };
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\"";
    svg += " version=\"1.1\"";
    if (!class_name.empty()) svg += attribute("class", class_name);
    svg += attribute("width", std::to_string(canvas.width_px)) +
           attribute("height", std::to_string(canvas.height_px)) +
           attribute("viewBox", number(canvas.box.x) + " " + number(canvas.box.y) + " " +
                                    number(canvas.box.width) + " " + number(canvas.box.height)) +
           ">\n";
    return svg;
}

std::string draw_background_layer(const SvgCanvas& canvas, const std::optional<Rgb>& colour, int decimals) {
    auto number = [&](double value) { return format_fixed(value, decimals); };
    std::string svg = "<g id=\"background\">\n";
    if (colour) {
        svg += "<rect" + attribute("x", number(canvas.box.x)) + attribute("y", number(canvas.box.y)) +
               attribute("width", number(canvas.box.width)) + attribute("height", number(canvas.box.height)) +
               attribute("fill", to_hex(*colour)) + "/>\n";
    }
    return svg + "</g>\n";
}

std::string render_animation(const FaceModel& face, const SvgOptions& svg_options, const SvgCanvas& canvas,
                             const Animation& animation, const SvgAnimationOptions& options,
                             const ProgressCallback& progress) {
    validate(animation, options);
    const std::size_t frame_count = animation.frames.size();
    // The hair and face layers of every frame; the clothes hang from O and d, which no state moves
    // (the body does not turn with the head), so they are drawn once, between the two as in
    // render_svg() (thesis 6.3.1: background, hair, clothes, face).
    std::size_t group_counter = 0;
    FramesEncoder hair_frames("hair", animation.fps, group_counter);
    FramesEncoder face_frames("face", animation.fps, group_counter);
    KeyframesEncoder keyframes(animation.fps, options,
                               options.encoding == AnimationEncoding::frames ? 0 : frame_count);
    const bool is_frames = options.encoding == AnimationEncoding::frames;
    std::string clothes_layer;
    std::string hair;
    std::string face_layer;
    const FaceState* previous = nullptr;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        if (frame % kProgressEveryFrames == 0) {
            report(progress, kFramesShare * static_cast<double>(frame) / static_cast<double>(frame_count), "frames",
                   frame);
        }
        const FaceState& state = animation.frames[frame];
        // Holds (pauses, a held head) repeat a frame exactly: draw it once.
        const bool is_repeat = previous != nullptr && state.pose == previous->pose &&
                               state.expression == previous->expression && state.mouth == previous->mouth;
        if (!is_repeat) {
            previous = &state;
            ProjectedFace projected;
            try {
                projected = project_face(face, state);
            } catch (const Error&) {
                std::throw_with_nested(InvalidArgument(
                    "animation.frames[" + std::to_string(frame) + "]",
                    "the face cannot be drawn at " + format_fixed(static_cast<double>(frame) / animation.fps, 3) +
                        " s"));
            }
            const LayerStyle style{svg_options.decimals, svg_options.stroke_width_in_d * projected.d};
            if (frame == 0) {
                // The clothes hang from O and d, which no state moves (the body does not turn with
                // the head): drawn once, between hair and face as in render_svg() (thesis 6.3.1).
                clothes_layer = "<g id=\"clothes\">\n" +
                                (svg_options.draw_clothes
                                     ? draw_clothes_layer(projected, canvas.box, svg_options.clothes, style)
                                     : std::string()) +
                                "</g>\n";
            }
            hair = draw_hair_layer(projected, style);
            face_layer = draw_face_layer(projected, style);
        }
        if (is_frames) {
            hair_frames.add(hair);
            face_frames.add(face_layer);
        } else if (is_repeat) {
            keyframes.add_repeat();
        } else {
            keyframes.add("<g id=\"hair\">\n" + hair + "</g>\n" + clothes_layer + "<g id=\"face\">\n" + face_layer +
                          "</g>\n");
        }
    }
    report(progress, kFramesShare, "encoding", frame_count);

    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    svg += open_svg_root(canvas, svg_options.decimals, "tf-animation");
    svg += draw_background_layer(canvas, svg_options.background, svg_options.decimals);
    if (is_frames) {
        svg += hair_frames.finish() + clothes_layer + face_frames.finish();
    } else {
        svg += keyframes.finish(progress);
    }
    svg += "</svg>\n";
    report(progress, 1.0, "encoding", frame_count);
    return svg;
}

}  // namespace talkface::detail
