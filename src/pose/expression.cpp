// The basic facial expressions of thesis 2.4.2: blink, smile with squint, eyebrow raise.
#include "talkface/expression.hpp"

#include <cmath>
#include <string>

#include "common/number_format.hpp"
#include "face/point_ids.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Thesis 2.4.2 names the points and FAPUs of each expression but no amounts; these are ours.
// A blink closes the eye mostly from above, as real eyelids do: the upper lid travels this share of
// the eye height and the lower lid the rest, so at blink 1 they meet.
constexpr double kBlinkUpperLidShare = 0.8;
// A full smile lifts the lower lids by this share of the eye height (the squint of 2.4.2).
constexpr double kSquintShare = 0.25;
// A full smile pulls each corner outward by MW0 / 16 as it lifts it by UpperLipH (FACS AU 12, lip
// corner puller, pulls up and out).
constexpr double kSmileOutwardMw0 = 1.0 / 16.0;

void require_amount(double amount, const char* field) {
    if (!std::isfinite(amount) || amount < 0.0 || amount > 1.0) {
        throw InvalidArgument(field,
                              "an expression amount must be in 0..1, got " + detail::format_shortest(amount));
    }
}

using detail::point_at;
// The points an expression moves, at indices found when this is compiled: every frame has one.
constexpr std::size_t k3_2 = point_at("3.2"), k3_4 = point_at("3.4"), k3_1 = point_at("3.1"),
                      k3_3 = point_at("3.3"), k8_4 = point_at("8.4"), k8_3 = point_at("8.3");
constexpr std::size_t kBrowPoints[] = {point_at("4.2"), point_at("4.4"), point_at("4.4a"), point_at("4.6"),
                                       point_at("4.1"), point_at("4.3"), point_at("4.3a"), point_at("4.5")};

void move_y(FaceModel& face, std::size_t index, double dy) {
    const Point2 p = face.points()[index];
    detail::FacePointEditor::set_point(face, index, Point2{p.x, p.y + dy});
}

// One eye: the lower lid squints up first, then the lids close over what is left of the eye height.
// The eye height is measured from the lids themselves (LeftEyeH / RightEyeH are defined as that gap,
// see face/fapu_measure.hpp), so the lids meet at blink 1 even on a face whose file states another
// value. Both lids move by offsets, so zero amounts leave the face exactly as it was.
void close_eye(FaceModel& face, std::size_t upper, std::size_t lower, double blink, double smile) {
    const double eye_height = face.points()[lower].y - face.points()[upper].y;
    const double squint_rise = kSquintShare * smile * eye_height;
    const double closing = blink * (eye_height - squint_rise);
    move_y(face, upper, kBlinkUpperLidShare * closing);
    move_y(face, lower, -(squint_rise + (1.0 - kBlinkUpperLidShare) * closing));
}

}  // namespace

FaceModel apply_expression(const FaceModel& face, const Expression& expression) {
    require_amount(expression.blink_left, "expression.blink_left");
    require_amount(expression.blink_right, "expression.blink_right");
    require_amount(expression.smile, "expression.smile");
    require_amount(expression.brows, "expression.brows");

    FaceModel result = face;
    // The FAPUs stay those of the neutral face: they are the units every other stage measures in,
    // and a closed eye has no positive LeftEyeH to store.
    close_eye(result, k3_2, k3_4, expression.blink_left, expression.smile);
    close_eye(result, k3_1, k3_3, expression.blink_right, expression.smile);

    const double lift_px = expression.smile * face.fapus()[detail::kFapuUpperLipH];
    const double outward_px = expression.smile * kSmileOutwardMw0 * face.fapus()[detail::kFapuMW0];
    const Point2 left = face.points()[k8_4];
    const Point2 right = face.points()[k8_3];
    detail::FacePointEditor::set_point(result, k8_4, Point2{left.x - outward_px, left.y - lift_px});
    detail::FacePointEditor::set_point(result, k8_3, Point2{right.x + outward_px, right.y - lift_px});

    // The lift's F G H I hang below 4.4a 4.4 4.3 4.3a (Algorithm 2.1), so they rise with them.
    const double brow_lift_px = expression.brows * face.fapus()[detail::kFapuEyebrowH];
    for (const std::size_t index : kBrowPoints) move_y(result, index, -brow_lift_px);
    return result;
}

}  // namespace v0
}  // namespace talkface
