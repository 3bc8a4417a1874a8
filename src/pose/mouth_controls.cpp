// The mouth's control points and the whole mouth they make (thesis 5.2.2, SPEC "Mouth shapes"). The
// pose stage owns them: a face is drawn at a pose with its mouth set, whichever shape set it.
#include "talkface/mouth_controls.hpp"

#include <algorithm>

#include "face/point_ids.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using detail::point_at;
// The mouth's points, at indices found when this is compiled: every frame sets its mouth.
constexpr std::size_t k8_9 = point_at("8.9"), k8_2 = point_at("8.2"), k8_4 = point_at("8.4"),
                      k8_3 = point_at("8.3"), k8_1 = point_at("8.1"), k8_10 = point_at("8.10"),
                      k2_2 = point_at("2.2"), k2_3 = point_at("2.3"), k2_1 = point_at("2.1");

void set(FaceModel& face, std::size_t index, Point2 image_xy) {
    detail::FacePointEditor::set_point(face, index, image_xy);
}

Point2 moved(Point2 p, double dx, double dy) {
    return Point2{p.x + dx, p.y + dy};
}

Point2 offset(Point2 to, Point2 from) {
    return Point2{to.x - from.x, to.y - from.y};
}

}  // namespace

MouthControls neutral_mouth_controls(const FaceModel& neutral) {
    const auto& p = neutral.points();
    return MouthControls{p[k8_9], p[k8_2], p[k8_4], p[k8_3]};
}

FaceModel apply_mouth(const FaceModel& neutral, const MouthControls& controls) {
    const MouthControls rest = neutral_mouth_controls(neutral);
    const auto& p = neutral.points();
    FaceModel face = neutral;
    set(face, k8_9, controls.up);
    set(face, k8_2, controls.down);
    set(face, k8_4, controls.left);
    set(face, k8_3, controls.right);

    // The thesis draws the upper lip as arc(8.1, 8.9, 8.4) and arc(8.3, 8.10, 8.1) but moves only 8.9
    // (2.2: the control points "by which other mouth feature points are computed", not saying how).
    // Moving 8.1 and 8.10 rigidly with 8.9 keeps the upper lip's thickness (UpperLipH) and its two peaks
    // level.
    const Point2 up_offset = offset(controls.up, rest.up);
    for (const std::size_t index : {k8_1, k8_10}) set(face, index, moved(p[index], up_offset.x, up_offset.y));

    // The inner lips (thesis silent): the upper one rides on the upper lip, the lower one on the lower
    // lip, so each lip keeps its thickness; both stay on the mouth's centre line between the corners.
    // Shape f lifts 8.2 by half the lower lip, which would put 2.3 above 2.2: the lower lip then tucks
    // behind the upper one, so the lips stay closed (2.3 = 2.2) instead of passing through each other.
    const double centre_dx = (controls.left.x + controls.right.x) / 2.0 - (rest.left.x + rest.right.x) / 2.0;
    const Point2 inner_upper = moved(p[k2_2], centre_dx, up_offset.y);
    const Point2 inner_lower_free = moved(p[k2_3], centre_dx, controls.down.y - rest.down.y);
    set(face, k2_2, inner_upper);
    set(face, k2_3, Point2{inner_lower_free.x, std::max(inner_lower_free.y, inner_upper.y)});

    // Thesis 5.2.2: the jaw point moves with 8.2.
    set(face, k2_1, Point2{controls.down.x, controls.down.y + neutral.fapus()[detail::kFapuJawH]});
    return face;
}

}  // namespace v0
}  // namespace talkface
