// Stage 3 + 7: a contact sheet of poses x expressions, like thesis Figure 2.20.
//
//   pose_sheet OUT.svg [FACE.xml [LOOK]]   the built-in face for no file or "default"; LOOK: outlined
//                                          (the default) or flat
#include <cstdio>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include <talkface/talkface.hpp>

#include "common/nested_svg.hpp"

namespace {

struct Row {
    const char* label;
    talkface::Pose pose;
};

struct Column {
    const char* label;
    talkface::Expression expression;
    bool is_talking;
};

constexpr double kCellWidth = 180.0;
constexpr double kLabelWidth = 170.0;
constexpr double kHeaderHeight = 36.0;

std::string text(double x, double y, const std::string& content, const char* anchor) {
    return "<text x=\"" + talkface_samples::svg_number(x) + "\" y=\"" + talkface_samples::svg_number(y) +
           "\" text-anchor=\"" + anchor + "\">" + talkface_samples::escape_xml(content) + "</text>\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::cerr << "usage: pose_sheet OUT.svg [FACE.xml|default [outlined|flat]]\n";
        return 2;
    }
    try {
        const talkface::FaceModel face =
            argc >= 3 && std::string(argv[2]) != "default" ? talkface::FaceModel::load(argv[2])
                                                           : talkface::FaceModel::default_face();
        talkface::SvgOptions options;
        if (argc == 4) options.look = talkface::face_look_from_name(argv[3]);
        const std::vector<Row> rows{
            {"frontal", {0, 0, 0}},           {"turn beta +15", {0, 15, 0}},
            {"turn beta -15", {0, -15, 0}},   {"nod alpha +15", {15, 0, 0}},
            {"nod alpha -15", {-15, 0, 0}},   {"tilt gamma +15", {0, 0, 15}},
            {"tilt gamma -15", {0, 0, -15}},  {"10, -12, 8", {10, -12, 8}},
        };
        talkface::Expression blink;
        blink.blink_left = blink.blink_right = 1.0;
        talkface::Expression smile;
        smile.smile = 1.0;
        talkface::Expression brows;
        brows.brows = 1.0;
        const std::vector<Column> columns{{"neutral", {}, false},
                                          {"blink", blink, false},
                                          {"smile", smile, false},
                                          {"brows raised", brows, false},
                                          {"talking (a)", {}, true}};

        const talkface::SvgAnimator animator(face, options);
        // Every state of one face shares the canvas, so one cell size fits all.
        const std::string first = animator.render_svg({});
        const auto size_of = [&](const char* name) {
            const std::size_t at = first.find(std::string(" ") + name + "=\"") + std::string(name).size() + 3;
            return std::stod(first.substr(at));
        };
        const double cell_height = kCellWidth * size_of("height") / size_of("width");
        const double width = kLabelWidth + kCellWidth * static_cast<double>(columns.size());
        const double height = kHeaderHeight + cell_height * static_cast<double>(rows.size());

        std::string sheet = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                            "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                            "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"" +
                            talkface_samples::svg_number(width) + "\" height=\"" +
                            talkface_samples::svg_number(height) + "\">\n" +
                            "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
                            "<g font-family=\"sans-serif\" font-size=\"17\" fill=\"#222222\">\n";
        sheet += text(10, 24, "face: " + face.name(), "start");
        for (std::size_t c = 0; c < columns.size(); ++c) {
            sheet += text(kLabelWidth + kCellWidth * (static_cast<double>(c) + 0.5), 24, columns[c].label, "middle");
        }
        for (std::size_t r = 0; r < rows.size(); ++r) {
            sheet += text(10, kHeaderHeight + cell_height * (static_cast<double>(r) + 0.5), rows[r].label, "start");
        }
        sheet += "</g>\n";
        for (std::size_t r = 0; r < rows.size(); ++r) {
            for (std::size_t c = 0; c < columns.size(); ++c) {
                talkface::FaceState state;
                state.pose = rows[r].pose;
                state.expression = columns[c].expression;
                if (columns[c].is_talking) state.mouth = talkface::mouth_controls(face, talkface::MouthShape::a);
                const talkface_samples::Cell cell{kLabelWidth + kCellWidth * static_cast<double>(c),
                                                  kHeaderHeight + cell_height * static_cast<double>(r),
                                                  kCellWidth, cell_height, ""};
                const std::string prefix = "r" + std::to_string(r) + "c" + std::to_string(c) + "-";
                sheet += talkface_samples::nest_svg(animator.render_svg(state), cell, prefix);
            }
        }
        sheet += "</svg>\n";

        std::ofstream out(argv[1], std::ios::binary);
        out << sheet;
        if (!out.flush()) throw std::runtime_error(std::string("cannot write ") + argv[1]);
        std::printf("wrote %s: %zu poses x %zu expressions\n", argv[1], rows.size(), columns.size());
    } catch (const std::exception& error) {
        std::cerr << "pose_sheet: error: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
