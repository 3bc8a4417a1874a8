// Renders the default face through the installed C++ API.
#include <cstdio>
#include <talkface/talkface.hpp>

int main() {
    const talkface::FaceModel face = talkface::FaceModel::default_face();
    talkface::FaceState state;
    state.pose.beta_deg = 10.0;
    const std::string svg = talkface::SvgAnimator(face).render_svg(state);
    std::printf("C++: talkface %s, d = %g px, %zu bytes of SVG\n", talkface::version(), face.fapu("d"), svg.size());
    return svg.rfind("<?xml", 0) == 0 && std::string(talkface::version()) == TALKFACE_VERSION_STRING ? 0 : 1;
}
