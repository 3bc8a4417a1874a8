// The temporal half of thesis 6.3.2: every frame of an Animation drawn as by the spatial half, then
// written either as one group per frame (the thesis's <set> frames) or as one face whose moving
// attributes are SMIL <animate> elements over key frames chosen per attribute.
//
// The key frames come from the drawn frames themselves, not from the mouth key frames and events:
// whatever moves (lips, jaw, lids, eyeballs, the whole head) gets exactly the key frames it needs
// for linear interpolation to stay within the tolerance of every frame, and whatever holds still
// gets none. The head's tilt is taken out first: one rotate of the head's groups (head_tilt.hpp),
// the layers drawn in the groups' frame. This relies on each frame's document having the same
// elements and the same path commands, only other numbers: the layers draw a fixed number of
// points at every pose (contour substitution changes which points, not how many). A frame that
// breaks this is a bug, reported as one.
#include "render/svg_animation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/number_format.hpp"
#include "render/head_tilt.hpp"
#include "render/key_frames.hpp"
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

// Reads the number at `begin`, as append_fixed() writes them (-12.34): a third of the time of
// std::from_chars, which reads any form; it takes over if an exponent follows.
const char* read_number(const char* begin, const char* end, double& value) {
    const char* p = begin;
    const bool is_negative = p < end && *p == '-';
    if (is_negative) ++p;
    long long whole = 0;
    for (; p < end && *p >= '0' && *p <= '9'; ++p) whole = whole * 10 + (*p - '0');
    double result = static_cast<double>(whole);
    if (p < end && *p == '.') {
        long long fraction = 0;
        long long scale = 1;
        for (++p; p < end && *p >= '0' && *p <= '9' && scale < 1000000000; ++p) {
            fraction = fraction * 10 + (*p - '0');
            scale *= 10;
        }
        result += static_cast<double>(fraction) / static_cast<double>(scale);
    }
    if (p < end && (*p == 'e' || *p == 'E' || (*p >= '0' && *p <= '9'))) {
        return std::from_chars(begin, end, value).ptr;
    }
    value = is_negative ? -result : result;
    return p;
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
        const char* after = read_number(text.data() + i, text.data() + text.size(), value);
        if (pieces != nullptr) pieces->emplace_back(text.substr(piece_start, i - piece_start));
        numbers.push_back(static_cast<float>(value));
        i = static_cast<std::size_t>(after - text.data());
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
        const char* after = read_number(text.data() + i, text.data() + text.size(), value);
        numbers.push_back(static_cast<float>(value));
        i = static_cast<std::size_t>(after - text.data());
    }
    return i == text.size();
}

// The head's layers are drawn in tenths of a pixel (head_tilt.hpp), and animated values are written
// rounded to whole tenths: 0.05 px of rounding on top of the tolerance, far below what shows. Every
// length below is in these units.
constexpr double kUnitsPerPx = kHeadUnitsPerPx;

void append_whole(std::string& text, long value) {
    // A minus sign separates numbers by itself in SVG's number lists and path data.
    if (!text.empty() && value >= 0) {
        const char last = text.back();
        if (last >= '0' && last <= '9') text += ' ';
    }
    text += std::to_string(value);
}

std::vector<long> rounded_values(const Track& track, std::size_t frame) {
    std::vector<long> values(track.width);
    for (std::size_t k = 0; k < track.width; ++k) {
        values[k] = std::lround(static_cast<double>(track.numbers[frame * track.width + k]));
    }
    return values;
}

// A value with the frame's numbers, in the text of frame 0 (a point list, a coordinate).
std::string track_value(const Track& track, std::size_t frame) {
    const std::vector<long> values = rounded_values(track, frame);
    std::string text;
    for (std::size_t k = 0; k < track.width; ++k) {
        text += track.pieces[k];
        text += std::to_string(values[k]);
    }
    text += track.pieces[track.width];
    return text;
}

// Where each point of a path track stands: its command and its place in the command's segment.
// Our paths use M, L, C, Q and Z only, each command letter written before its points.
struct PathPoint {
    char command = 'M';
    int place = 0;  // 0 .. 2 in a C segment (c1, c2, end), 0 .. 1 in a Q, else 0
    // The first control point of a segment that is the previous one's last control point reflected
    // through the pen, left to an S (after a C) or a T (after a Q).
    bool is_implied_control = false;
    bool closes_before = false;  // a Z comes before this point
};

int points_per_segment(char command) {
    return command == 'C' ? 3 : command == 'Q' ? 2 : 1;
}

// The largest gap between a control point and the reflection of the previous one for which it is
// left to an S or T command: the frames' own rounding (three coordinates at 0.005 px), no more.
constexpr double kReflectionGap = 0.02 * kUnitsPerPx;

// The layout of a path track, with every control point that is the previous one reflected through
// the pen in every frame marked to be left implicit. The joins of a Catmull-Rom arc are such (S: a
// third fewer numbers), and so is every join of a corner-cut outline, the quadratic B-spline of a
// polygon (T: half the numbers): the pen is the middle of an edge, the controls its two corners.
std::vector<PathPoint> path_layout(const Track& track, std::size_t frame_count) {
    std::vector<PathPoint> layout(track.width / 2);
    char command = 'M';
    int place = 0;
    for (std::size_t j = 0; j < layout.size(); ++j) {
        for (const char c : track.pieces[2 * j]) {
            if (c == 'Z') layout[j].closes_before = true;
            if (c == 'M' || c == 'L' || c == 'C' || c == 'Q') {
                command = c;
                place = 0;
            }
        }
        layout[j].command = command;
        layout[j].place = place % points_per_segment(command);
        ++place;
    }
    for (std::size_t j = 2; j < layout.size(); ++j) {
        const char segment_command = layout[j].command;
        const bool is_curve = segment_command == 'C' || segment_command == 'Q';
        const bool follows_same_curve = layout[j - 1].command == segment_command &&
                                        layout[j - 1].place + 1 == points_per_segment(segment_command);
        if (!is_curve || layout[j].place != 0 || !follows_same_curve || layout[j].closes_before) continue;
        bool is_reflection = true;
        for (std::size_t frame = 0; frame < frame_count && is_reflection; ++frame) {
            const float* n = track.numbers.data() + frame * track.width;
            for (std::size_t axis = 0; axis < 2; ++axis) {
                const double reflected = 2.0 * n[2 * (j - 1) + axis] - n[2 * (j - 2) + axis];
                is_reflection = is_reflection && std::abs(n[2 * j + axis] - reflected) <= kReflectionGap;
            }
        }
        layout[j].is_implied_control = is_reflection;
    }
    return layout;
}

// A T's control point is the previous control reflected through the pen, and that one may be a T's
// too: rounding would add up along the chain. So the end point before a T is rounded to where it
// makes the T's control nearest to the frame's, which keeps that control within 0.1 px (a grid step)
// of the interpolated frame's, and the end point itself within 0.11 px: 0.06 px more than rounding to
// the nearest tenth, which the key frames of such a path leave over from the tolerance.
constexpr double kChainRounding = 0.06 * kUnitsPerPx;

double chain_rounding(const std::vector<PathPoint>& layout) {
    for (const PathPoint& point : layout) {
        if (point.is_implied_control && point.command == 'Q') return kChainRounding;
    }
    return 0.0;
}

// Path data with relative commands: the same shape in fewer bytes (small offsets instead of full
// coordinates), and interpolating offsets is interpolating coordinates, since the map between them
// is linear. Offsets are taken between rounded coordinates, so rounding never accumulates along the
// path. A c1 left to an S is interpolated as the reflection of interpolated points, which is the
// interpolated reflection: it strays no further than the points it is made of (three of them, so
// three times their rounding), or for a T, than the chain's rounding allows (kChainRounding).
std::string relative_path_value(const Track& track, const std::vector<PathPoint>& layout, std::size_t frame) {
    std::vector<long> rounded = rounded_values(track, frame);
    const float* exact = track.numbers.data() + frame * track.width;
    std::string text;
    long current_x = 0, current_y = 0, start_x = 0, start_y = 0;
    long reference_x = 0, reference_y = 0;
    long control_x = 0, control_y = 0;  // the last quadratic control point, as drawn
    // SVG repeats a command for as many numbers as follow it: a letter like the one before (other
    // than a move, whose repeats draw lines) is left out.
    char last_command = 'z';
    auto write_command = [&](char command) {
        if (command != last_command || command == 'M' || command == 'm' || command == 'z') text += command;
        last_command = command;
    };
    for (std::size_t j = 0; j < layout.size(); ++j) {
        const PathPoint& point = layout[j];
        if (point.closes_before) {
            write_command('z');
            current_x = start_x;
            current_y = start_y;
        }
        if (point.is_implied_control) {
            write_command(point.command == 'C' ? 's' : 't');
            control_x = 2 * current_x - control_x;
            control_y = 2 * current_y - control_y;
            continue;
        }
        const bool starts_command = point.place == 0 && !(j > 0 && layout[j - 1].is_implied_control);
        if (starts_command) write_command(j == 0 ? 'M' : static_cast<char>(point.command - 'A' + 'a'));
        // Every point of a curve segment is relative to where the segment starts (SVG "c", "s", "q", "t").
        if (point.place == 0 || (point.place == 1 && layout[j - 1].is_implied_control)) {
            reference_x = j == 0 ? 0 : current_x;
            reference_y = j == 0 ? 0 : current_y;
        }
        if (point.command == 'Q' && point.place == 0) {
            control_x = rounded[2 * j];
            control_y = rounded[2 * j + 1];
        }
        if (point.command == 'Q' && point.place == 1 && j + 1 < layout.size() &&
            layout[j + 1].is_implied_control) {
            rounded[2 * j] = std::lround((static_cast<double>(control_x) + exact[2 * j + 2]) / 2.0);
            rounded[2 * j + 1] = std::lround((static_cast<double>(control_y) + exact[2 * j + 3]) / 2.0);
        }
        const long x = rounded[2 * j];
        const long y = rounded[2 * j + 1];
        append_whole(text, x - reference_x);
        append_whole(text, y - reference_y);
        if (point.place + 1 == points_per_segment(point.command)) {
            current_x = x;
            current_y = y;
            if (point.command == 'M') {
                start_x = x;
                start_y = y;
            }
        }
    }
    if (track.pieces[track.width].find('Z') != std::string::npos) text += 'z';
    return text;
}

// --- outlines that move as a whole -------------------------------------------------------------
//
// A turn or a nod moves each feature mostly as a whole: its points shift with their depth (SPEC
// "Pose": rotation and orthographic projection; the tilt is the head groups' own). So an outline can
// be written as its points about their mean, under an animated translate that carries the mean: two
// numbers a key frame for the motion, and the outline's own key frames only where its shape changes
// beyond its share of the tolerance (the jaw opens, a lid closes, a brow rises, the turn bends it).
// The encoder keeps this or the plain animation, whichever is shorter. (A full affine map per
// outline was tried before: its four transform animations, each with its own key times, cost more
// than they saved. One affine map for the whole head, the turn's and nod's linear part, saves
// nothing either: what is left is each point's own depth.)

struct MovedOutline {
    double centre_x = 0.0, centre_y = 0.0;  // the mean of the first frame's points
    Track offset;                           // the mean of each frame's points less the centre
    Track outline;                          // each frame's points less their mean
};

// The translate's share of the tolerance; the outline has the rest, less the rounding of both.
constexpr double kOffsetShare = 1.0 / 3.0;
constexpr int kOffsetDecimals = 1;
constexpr double kOffsetRounding = 0.05;

MovedOutline split_motion(const Track& track, std::size_t frame_count) {
    const std::size_t points = track.width / 2;
    MovedOutline moved;
    moved.offset.width = 2;
    moved.offset.numbers.reserve(2 * frame_count);
    moved.outline.width = track.width;
    moved.outline.pieces = track.pieces;
    moved.outline.numbers.reserve(track.numbers.size());
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        const float* p = track.numbers.data() + frame * track.width;
        double mean_x = 0.0, mean_y = 0.0;
        for (std::size_t i = 0; i < points; ++i) {
            mean_x += static_cast<double>(p[2 * i]);
            mean_y += static_cast<double>(p[2 * i + 1]);
        }
        mean_x /= static_cast<double>(points);
        mean_y /= static_cast<double>(points);
        if (frame == 0) {
            moved.centre_x = mean_x;
            moved.centre_y = mean_y;
        }
        moved.offset.numbers.push_back(static_cast<float>(mean_x - moved.centre_x));
        moved.offset.numbers.push_back(static_cast<float>(mean_y - moved.centre_y));
        for (std::size_t i = 0; i < points; ++i) {
            moved.outline.numbers.push_back(static_cast<float>(static_cast<double>(p[2 * i]) - mean_x));
            moved.outline.numbers.push_back(static_cast<float>(static_cast<double>(p[2 * i + 1]) - mean_y));
        }
    }
    return moved;
}

// The layout of an attribute's track: a path's (path_layout()), none for other point lists.
std::vector<PathPoint> layout_of(std::string_view attribute_name, const Track& track,
                                 std::size_t frame_count) {
    return attribute_name == "d" ? path_layout(track, frame_count) : std::vector<PathPoint>();
}

// The values of an attribute over its key frames: path data relative (with `layout`, which says
// which control points are left implicit), other point lists as they are.
std::string key_values(std::string_view attribute_name, const std::vector<PathPoint>& layout,
                       const KeyFrames& keys) {
    const bool is_path = attribute_name == "d";
    std::string values;
    for (std::size_t i = 0; i < keys.positions.size(); ++i) {
        if (i > 0) values += ';';
        values += is_path ? relative_path_value(keys.values, layout, i) : track_value(keys.values, i);
    }
    return values;
}

std::string animate_element(std::string_view attribute_name, const Track& track, std::size_t frame_count,
                            double duration_s, double tolerance) {
    const std::vector<PathPoint> layout = layout_of(attribute_name, track, frame_count);
    const KeyFrames keys = choose_key_frames(
        track, frame_count, std::vector<double>(track.width, tolerance - chain_rounding(layout)));
    return "<animate attributeName=\"" + std::string(attribute_name) + "\"" +
           attribute("dur", clock_value(duration_s)) +
           attribute("values", key_values(attribute_name, layout, keys)) +
           attribute("keyTimes", key_times_of(keys, frame_count)) + " fill=\"freeze\"/>";
}

// The outline of the first frame about its mean as the attribute's value, the static translate to
// the mean, and the animations of the translate and (where its shape changes) of the outline.
struct MovedText {
    std::string value;
    std::string animations;
};

MovedText moved_outline_text(const MovedOutline& moved, std::string_view attribute_name,
                             std::size_t frame_count, double duration_s, double tolerance) {
    const std::string dur = attribute("dur", clock_value(duration_s));
    KeyFrames first_frame;
    first_frame.positions = {0.0};
    first_frame.values.width = moved.outline.width;
    first_frame.values.pieces = moved.outline.pieces;
    first_frame.values.numbers.assign(
        moved.outline.numbers.begin(),
        moved.outline.numbers.begin() + static_cast<std::ptrdiff_t>(moved.outline.width));
    MovedText text;
    const std::vector<PathPoint> layout = layout_of(attribute_name, moved.outline, frame_count);
    text.value = key_values(attribute_name, layout, first_frame) + "\" transform=\"translate(" +
                 format_fixed(moved.centre_x, kOffsetDecimals) + " " +
                 format_fixed(moved.centre_y, kOffsetDecimals) + ")";
    const double outline_tolerance = (1.0 - kOffsetShare) * tolerance - 0.5 - chain_rounding(layout);
    const KeyFrames outline_keys = choose_key_frames(
        moved.outline, frame_count, std::vector<double>(moved.outline.width, outline_tolerance));
    // Two key frames that agree within the tolerance: the outline holds its shape.
    bool is_reshaped = outline_keys.positions.size() > 2;
    for (std::size_t k = 0; k < moved.outline.width && !is_reshaped; ++k) {
        is_reshaped =
            std::abs(moved.outline.numbers[k] -
                     moved.outline.numbers[(frame_count - 1) * moved.outline.width + k]) > outline_tolerance;
    }
    if (is_reshaped) {
        text.animations += "<animate attributeName=\"" + std::string(attribute_name) + "\"" + dur +
                           attribute("values", key_values(attribute_name, layout, outline_keys)) +
                           attribute("keyTimes", key_times_of(outline_keys, frame_count)) +
                           " fill=\"freeze\"/>";
    }
    const double offset_tolerance = kOffsetShare * tolerance - kOffsetRounding;
    const KeyFrames keys = choose_key_frames(moved.offset, frame_count, {offset_tolerance, offset_tolerance});
    std::string values;
    for (std::size_t i = 0; i < keys.positions.size(); ++i) {
        if (i > 0) values += ';';
        for (std::size_t k = 0; k < 2; ++k) {
            if (k > 0) values += ' ';
            values += format_fixed(static_cast<double>(keys.values.numbers[i * 2 + k]), kOffsetDecimals);
        }
    }
    text.animations += "<animateTransform attributeName=\"transform\" type=\"translate\" additive=\"sum\"" +
                       dur + attribute("values", values) +
                       attribute("keyTimes", key_times_of(keys, frame_count)) + " fill=\"freeze\"/>";
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
    // `tolerance`: SvgAnimationOptions::tolerance_px in the drawing's units.
    KeyframesEncoder(double fps, double tolerance, std::size_t expected_frames)
        : fps_(fps), tolerance_(tolerance), expected_frames_(expected_frames) {}

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

    // The layer's text; progress goes from `from` to `to` as the attributes are written.
    std::string finish(const ProgressCallback& progress, double from, double to) const {
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
            const Track& track = tracks_[slot];
            std::string animation;
            std::optional<MovedText> moved;
            if (track.varies) {
                animation = animate_element(name, track, frame_count_, duration_s, tolerance_);
                // Outlines only: their numbers are points, and the element takes a transform.
                if ((name == "points" || name == "d") && track.width % 2 == 0) {
                    moved = moved_outline_text(split_motion(track, frame_count_), name, frame_count_,
                                               duration_s, tolerance_);
                }
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
                report(progress,
                       from + (to - from) * static_cast<double>(slot) / static_cast<double>(tracks_.size()),
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
    double tolerance_;
    std::size_t expected_frames_;
    std::size_t frame_count_ = 0;
    std::string first_text_;
    AttributeSplit first_;
    std::vector<Track> tracks_;
};

// The tilt's share of the tolerance at the farthest point from O: what its key frames leave over is
// left to the layers' own key frames (head_tilt.hpp), so it is kept small enough that outlines
// which only the tilt moves still hold still.
constexpr double kTiltShare = 1.0 / 6.0;

// The farthest any drawn point can be from `origin`: a corner of the canvas, which holds the face
// at every pose.
double reach_px(const CanvasBox& box, Point2 origin) {
    double reach = 0.0;
    for (const double x : {box.x, box.x + box.width}) {
        for (const double y : {box.y, box.y + box.height})
            reach = std::max(reach, std::hypot(x - origin.x, y - origin.y));
    }
    return reach;
}

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
    const bool is_frames = options.encoding == AnimationEncoding::frames;
    const std::size_t expected_frames = is_frames ? 0 : frame_count;
    KeyframesEncoder hair_keyframes(animation.fps, options.tolerance_px * kUnitsPerPx, expected_frames);
    KeyframesEncoder face_keyframes(animation.fps, options.tolerance_px * kUnitsPerPx, expected_frames);
    std::string clothes_layer;
    std::string hair;
    std::string face_layer;
    std::vector<Point2> hair_points;
    // The look of the face: its d, hence the stroke, is the same at every state.
    FaceLook look;
    HeadTilt tilt;
    const FaceState* previous = nullptr;
    double previous_angle_deg = 0.0;
    for (std::size_t frame = 0; frame < frame_count; ++frame) {
        if (frame % kProgressEveryFrames == 0) {
            report(progress, kFramesShare * static_cast<double>(frame) / static_cast<double>(frame_count), "frames",
                   frame);
        }
        const FaceState& state = animation.frames[frame];
        const double angle_deg = tilt.angle_deg.empty() ? 0.0 : tilt.angle_deg[frame];
        // Holds (pauses, a held head) repeat a frame exactly: draw it once.
        const bool is_repeat = previous != nullptr && state.pose == previous->pose &&
                               state.expression == previous->expression && state.mouth == previous->mouth &&
                               angle_deg == previous_angle_deg;
        // The hair holds still whenever its points do (the mouth and the eyes move without it).
        bool is_hair_repeat = is_repeat;
        if (!is_repeat) {
            previous = &state;
            // Built in place: a default ProjectedFace would build the default face first.
            const ProjectedFace projected = [&] {
                try {
                    return project_face(face, state);
                } catch (const Error&) {
                    std::throw_with_nested(InvalidArgument(
                        "animation.frames[" + std::to_string(frame) + "]",
                        "the face cannot be drawn at " +
                            format_fixed(static_cast<double>(frame) / animation.fps, 3) + " s"));
                }
            }();
            if (frame == 0) {
                const LayerStyle style{svg_options.decimals, svg_options.stroke_width_in_d * projected.d};
                if (is_frames) {
                    look = make_face_look(projected, style);
                } else {
                    // A decimal less in tenths of a pixel is the same precision.
                    look = make_face_look(projected, LayerStyle{std::max(0, style.decimals - 1),
                                                                style.stroke_px * kUnitsPerPx});
                    tilt = plan_head_tilt(animation, projected.origin, reach_px(canvas.box, projected.origin),
                                          kTiltShare * options.tolerance_px);
                }
                clothes_layer = "<g id=\"clothes\">\n" +
                                (svg_options.draw_clothes
                                     ? draw_clothes_layer(projected, canvas.box, svg_options.clothes, style)
                                     : std::string()) +
                                "</g>\n";
            }
            if (!is_frames) {
                previous_angle_deg = tilt.angle_deg[frame];
                look.view = ViewMap(tilt.origin, previous_angle_deg, kUnitsPerPx);
            }
            std::vector<Point2> new_hair_points = hair_polygon_in_view(projected, look);
            is_hair_repeat = frame > 0 && new_hair_points == hair_points;
            if (!is_hair_repeat) {
                hair_points = std::move(new_hair_points);
                hair = draw_hair_layer(projected, look);
            }
            face_layer = draw_face_layer(projected, look);
        }
        if (is_frames) {
            hair_frames.add(hair);
            face_frames.add(face_layer);
            continue;
        }
        if (is_hair_repeat) {
            hair_keyframes.add_repeat();
        } else {
            hair_keyframes.add(hair);
        }
        if (is_repeat) {
            face_keyframes.add_repeat();
        } else {
            face_keyframes.add(face_layer);
        }
    }
    report(progress, kFramesShare, "encoding", frame_count);

    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    svg += open_svg_root(canvas, svg_options.decimals, "tf-animation");
    svg += draw_background_layer(canvas, svg_options.background, svg_options.decimals);
    if (is_frames) {
        svg += hair_frames.finish() + clothes_layer + face_frames.finish();
    } else {
        const double hair_done = kFramesShare + 0.3 * (1.0 - kFramesShare);
        svg += open_head_group(tilt, "hair") + hair_keyframes.finish(progress, kFramesShare, hair_done) +
               "</g>\n" + clothes_layer + open_head_group(tilt, "face") +
               face_keyframes.finish(progress, hair_done, 1.0) + "</g>\n";
    }
    svg += "</svg>\n";
    report(progress, 1.0, "encoding", frame_count);
    return svg;
}

}  // namespace talkface::detail
