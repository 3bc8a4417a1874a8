// The mouth's control points and the whole mouth they make (thesis 5.2.2, SPEC "Mouth shapes"). The
// pose stage owns them: a face is drawn at a pose with its mouth set, whichever shape set it.
#include "talkface/mouth_controls.hpp"

#include <algorithm>

namespace talkface {
inline namespace v0 {

namespace {

Point2 moved(Point2 p, double dx, double dy) {
    return Point2{p.x + dx, p.y + dy};
}

Point2 offset(Point2 to, Point2 from) {
    return Point2{to.x - from.x, to.y - from.y};
}

}  // namespace

MouthControls neutral_mouth_controls(const FaceModel& neutral) {
    return MouthControls{neutral.point("8.9"), neutral.point("8.2"), neutral.point("8.4"),
                         neutral.point("8.3")};
}

FaceModel apply_mouth(const FaceModel& neutral, const MouthControls& controls) {
    const MouthControls rest = neutral_mouth_controls(neutral);
    FaceModel face = neutral;
    face.set_point("8.9", controls.up);
    face.set_point("8.2", controls.down);
    face.set_point("8.4", controls.left);
    face.set_point("8.3", controls.right);

    // The thesis draws the upper lip as arc(8.1, 8.9, 8.4) and arc(8.3, 8.10, 8.1) but moves only 8.9
    // (2.2: the control points "by which other mouth feature points are computed", not saying how).
    // Moving 8.1 and 8.10 rigidly with 8.9 keeps the upper lip's thickness (UpperLipH) and its two peaks
    // level.
    const Point2 up_offset = offset(controls.up, rest.up);
    for (const char* id : {"8.1", "8.10"}) {
        face.set_point(id, moved(neutral.point(id), up_offset.x, up_offset.y));
    }

    // The inner lips (thesis silent): the upper one rides on the upper lip, the lower one on the lower
    // lip, so each lip keeps its thickness; both stay on the mouth's centre line between the corners.
    // Shape f lifts 8.2 by half the lower lip, which would put 2.3 above 2.2: the lower lip then tucks
    // behind the upper one, so the lips stay closed (2.3 = 2.2) instead of passing through each other.
    const double centre_dx = (controls.left.x + controls.right.x) / 2.0 - (rest.left.x + rest.right.x) / 2.0;
    const Point2 inner_upper = moved(neutral.point("2.2"), centre_dx, up_offset.y);
    const Point2 inner_lower_free = moved(neutral.point("2.3"), centre_dx, controls.down.y - rest.down.y);
    face.set_point("2.2", inner_upper);
    face.set_point("2.3", Point2{inner_lower_free.x, std::max(inner_lower_free.y, inner_upper.y)});

    // Thesis 5.2.2: the jaw point moves with 8.2.
    face.set_point("2.1", Point2{controls.down.x, controls.down.y + neutral.fapu("JawH")});
    return face;
}

}  // namespace v0
}  // namespace talkface
