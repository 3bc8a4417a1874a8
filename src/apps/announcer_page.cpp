// The virtual announcer (thesis 7.2): the talking face on a stage, in front of a background colour
// or picture, moved to any place and scaled to any size by its rotation origin and eye distance
// (7.2.3: "the location of cartoon faces can be easily changed" by moving the origin).
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>

#include "apps/apps.hpp"
#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "render/html_text.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_pose.hpp"

namespace talkface::detail {

namespace {

struct Box {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
};

// The viewBox of the animation's root element, which render_animation_svg() always writes.
Box view_box_of(const std::string& svg) {
    const std::size_t start = svg.find("viewBox=\"");
    if (start == std::string::npos) {
        throw Error(ErrorCode::internal, "internal error (a bug in talkface): the animation has no viewBox");
    }
    Box box;
    const char* text = svg.c_str() + start + 9;
    double* fields[] = {&box.x, &box.y, &box.width, &box.height};
    for (double* field : fields) {
        char* end = nullptr;
        *field = std::strtod(text, &end);
        text = end;
    }
    return box;
}

std::string number(double value) { return format_fixed(value, 2); }

// The animation's root start tag with its size replaced by a place on the stage.
std::string placed(const std::string& animation_svg, const Box& place) {
    const std::size_t tag_end = animation_svg.find('>');
    std::string tag = animation_svg.substr(0, tag_end);
    for (const char* name : {" width=\"", " height=\""}) {
        const std::size_t start = tag.find(name);
        if (start == std::string::npos) continue;
        const std::size_t end = tag.find('"', start + std::char_traits<char>::length(name));
        tag.erase(start, end + 1 - start);
    }
    tag += " x=\"" + number(place.x) + "\" y=\"" + number(place.y) + "\" width=\"" + number(place.width) +
           "\" height=\"" + number(place.height) + "\"";
    return tag + animation_svg.substr(tag_end);
}

}  // namespace

PageParts announcer_page(const std::string& animation_svg, const FaceModel& face, const WebPageOptions& options,
                         const std::string& title, const std::string& audio_element) {
    const double stage_width = options.stage_width_px;
    const double stage_height = options.stage_height_px;
    const Box canvas = view_box_of(animation_svg);
    const ProjectedFace neutral = project_face(face, FaceState{});
    const Point2 origin = neutral.origin;

    // Unset: the face as tall as the stage, its canvas standing on the stage's bottom edge.
    const double scale = options.face_d_px > 0.0 ? options.face_d_px / neutral.d : stage_height / canvas.height;
    const Point2 stage_origin =
        options.face_origin_px.value_or(Point2{0.5 * stage_width, stage_height - (canvas.y + canvas.height - origin.y) * scale});
    const Box place{stage_origin.x - (origin.x - canvas.x) * scale, stage_origin.y - (origin.y - canvas.y) * scale,
                    canvas.width * scale, canvas.height * scale};

    std::string background = "<rect width=\"" + number(stage_width) + "\" height=\"" + number(stage_height) +
                             "\" fill=\"" + to_hex(options.stage_colour) + "\"/>\n";
    if (!options.background_image_path.empty()) {
        const std::string mime = image_mime_type(options.background_image_path);
        if (mime.empty()) {
            throw InvalidArgument("background_image_path",
                                  "expected a .png, .jpg, .jpeg, .gif, .webp or .svg file, found \"" +
                                      options.background_image_path + "\"");
        }
        // Covers the stage whatever its shape, cropping the picture's overflow (CSS "cover").
        background += "<image width=\"" + number(stage_width) + "\" height=\"" + number(stage_height) +
                      "\" preserveAspectRatio=\"xMidYMid slice\" href=\"" +
                      data_uri(mime, read_file(options.background_image_path)) + "\"/>\n";
    }
    std::string caption;
    if (!title.empty()) {
        // A news programme's lower third, in front of the shoulders.
        const double bar_height = 0.11 * stage_height;
        caption = "<g class=\"tf-caption\"><rect x=\"0\" y=\"" + number(stage_height - 1.6 * bar_height) +
                  "\" width=\"" + number(0.62 * stage_width) + "\" height=\"" + number(bar_height) +
                  "\" fill=\"#b91c1c\" fill-opacity=\"0.92\"/><text x=\"" + number(0.03 * stage_width) + "\" y=\"" +
                  number(stage_height - 0.93 * bar_height) + "\" font-size=\"" + number(0.45 * bar_height) +
                  "\" fill=\"#ffffff\" font-family=\"sans-serif\">" + escape_html(title) + "</text></g>\n";
    }

    PageParts parts;
    parts.style =
        "body{margin:0;background:#0f172a;color:#e2e8f0;font-family:sans-serif}"
        ".tf-announcer{max-width:" + std::to_string(options.stage_width_px) + "px;margin:0 auto;padding:16px}"
        ".tf-stage{display:block;width:100%;height:auto;border-radius:6px;box-shadow:0 4px 24px #0008}"
        "audio{display:block;width:100%;margin-top:12px}";
    parts.body = "<main class=\"tf-announcer\">\n<svg class=\"tf-stage\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " +
                 number(stage_width) + " " + number(stage_height) + "\" width=\"" + number(stage_width) +
                 "\" height=\"" + number(stage_height) + "\" role=\"img\" aria-label=\"" + escape_html(title) +
                 "\">\n" + background + placed(animation_svg, place) + caption + "</svg>\n" + audio_element +
                 "</main>\n";
    return parts;
}

}  // namespace talkface::detail
