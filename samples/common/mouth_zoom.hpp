// The lower face as the mouth's sample sheets show it (samples/mouth_shapes, samples/syllable_strip):
// from just above the nose tip to below the lowest chin of all 12 mouth shapes, centred on the mouth.
#ifndef TALKFACE_SAMPLES_MOUTH_ZOOM_HPP
#define TALKFACE_SAMPLES_MOUTH_ZOOM_HPP

#include <algorithm>
#include <string>

#include <talkface/talkface.hpp>

#include "common/nested_svg.hpp"

namespace talkface_samples {

struct MouthZoom {
    std::string view_box;  // in the face's image space, which is the documents' user space
    double width = 0.0;
    double height = 0.0;
};

inline MouthZoom mouth_zoom(const talkface::FaceModel& face) {
    const double d = face.fapu("d");
    double chin_y = face.point("2.1").y;
    for (talkface::MouthShape shape : talkface::all_mouth_shapes()) {
        talkface::FaceState state;
        state.mouth = talkface::mouth_controls(face, shape);
        chin_y = std::max(chin_y, talkface::project_face(face, state).point("2.1").y);
    }
    const double top = face.point("9.15").y - 0.45 * d;
    MouthZoom zoom;
    zoom.height = chin_y + 0.2 * d - top;
    zoom.width = zoom.height * 1.25;
    const double centre_x = (face.point("8.4").x + face.point("8.3").x) / 2.0;
    zoom.view_box = svg_number(centre_x - zoom.width / 2) + " " + svg_number(top) + " " + svg_number(zoom.width) +
                    " " + svg_number(zoom.height);
    return zoom;
}

}  // namespace talkface_samples

#endif
