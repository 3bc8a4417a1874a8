// Stage 6 + 7: the 12 basic mouth shapes of thesis 5.2.2, like Figures 5.4 (initials, top row)
// and 5.5 (finals, bottom row), each zoomed on the lower face.
//
//   mouth_shapes OUT.svg [FACE.xml]     the built-in default face when no file is given
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <iostream>
#include <string>

#include <talkface/talkface.hpp>

#include "common/nested_svg.hpp"

namespace {

constexpr int kColumns = 6;
constexpr double kCellWidth = 200.0;
constexpr double kLabelHeight = 30.0;
constexpr double kGap = 8.0;

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: mouth_shapes OUT.svg [FACE.xml]\n";
        return 2;
    }
    try {
        const talkface::FaceModel face =
            argc == 3 ? talkface::FaceModel::load(argv[2]) : talkface::FaceModel::default_face();
        const double d = face.fapu("d");

        // The zoom: from just above the nose tip to below the lowest chin of all 12 shapes, centred on
        // the mouth. The documents' user space is the face's image space, so face points place it.
        double chin_y = face.point("2.1").y;
        for (talkface::MouthShape shape : talkface::all_mouth_shapes()) {
            talkface::FaceState state;
            state.mouth = talkface::mouth_controls(face, shape);
            chin_y = std::max(chin_y, talkface::project_face(face, state).point("2.1").y);
        }
        const double top = face.point("9.15").y - 0.45 * d;
        const double zoom_height = chin_y + 0.2 * d - top;
        const double zoom_width = zoom_height * 1.25;
        const double centre_x = (face.point("8.4").x + face.point("8.3").x) / 2.0;
        const std::string view_box = talkface_samples::svg_number(centre_x - zoom_width / 2) + " " +
                                     talkface_samples::svg_number(top) + " " +
                                     talkface_samples::svg_number(zoom_width) + " " +
                                     talkface_samples::svg_number(zoom_height);
        const double cell_height = kCellWidth * zoom_height / zoom_width;
        const double row_height = cell_height + kLabelHeight + kGap;
        const double width = kColumns * (kCellWidth + kGap) + kGap;
        const double height = 2 * row_height + kGap;

        std::string sheet = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                            "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                            "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"" +
                            talkface_samples::svg_number(width) + "\" height=\"" +
                            talkface_samples::svg_number(height) + "\">\n" +
                            "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
        const talkface::SvgAnimator animator(face);
        int index = 0;
        for (talkface::MouthShape shape : talkface::all_mouth_shapes()) {
            const int row = index / kColumns;
            const int column = index % kColumns;
            const double x = kGap + column * (kCellWidth + kGap);
            const double y = kGap + row * row_height;
            talkface::FaceState state;
            state.mouth = talkface::mouth_controls(face, shape);
            const talkface_samples::Cell cell{x, y, kCellWidth, cell_height, view_box};
            sheet += talkface_samples::nest_svg(animator.render_svg(state), cell,
                                                "shape" + std::to_string(index) + "-");
            sheet += "<text x=\"" + talkface_samples::svg_number(x + kCellWidth / 2) + "\" y=\"" +
                     talkface_samples::svg_number(y + cell_height + 22) +
                     "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"20\" fill=\"#222222\">" +
                     talkface_samples::escape_xml(talkface::mouth_shape_name(shape)) + "</text>\n";
            ++index;
        }
        sheet += "</svg>\n";

        std::ofstream out(argv[1], std::ios::binary);
        out << sheet;
        if (!out.flush()) throw std::runtime_error(std::string("cannot write ") + argv[1]);
        std::printf("wrote %s: 12 mouth shapes\n", argv[1]);
    } catch (const std::exception& error) {
        std::cerr << "mouth_shapes: error: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
