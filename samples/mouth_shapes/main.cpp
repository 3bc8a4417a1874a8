// Stage 6 + 7: the 12 basic mouth shapes of thesis 5.2.2, like Figures 5.4 (initials, top row)
// and 5.5 (finals, bottom row), each zoomed on the lower face.
//
//   mouth_shapes OUT.svg [FACE.xml]     the built-in default face when no file is given
#include <cstdio>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <iostream>
#include <string>

#include <talkface/talkface.hpp>

#include "common/mouth_zoom.hpp"
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
        const talkface_samples::MouthZoom zoom = talkface_samples::mouth_zoom(face);
        const double cell_height = kCellWidth * zoom.height / zoom.width;
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
            const talkface_samples::Cell cell{x, y, kCellWidth, cell_height, zoom.view_box};
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
