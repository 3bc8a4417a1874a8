#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "pose/test_faces.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression.hpp"
#include "talkface/face_lift.hpp"

using namespace talkface;

namespace {

const char* const kBrowIds[] = {"4.2", "4.4", "4.4a", "4.6", "4.1", "4.3", "4.3a", "4.5"};

double eye_gap(const FaceModel& face, const char* upper, const char* lower) {
    return face.point(lower).y - face.point(upper).y;
}

}  // namespace

TEST_SUITE("expression") {
    TEST_CASE("no expression leaves the face exactly as it was") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            CHECK(apply_expression(face, Expression{}) == face);
        }
    }

    TEST_CASE("a full blink closes the lids") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            for (double smile : {0.0, 0.5, 1.0}) {
                CAPTURE(smile);
                const FaceModel closed = apply_expression(face, Expression{1.0, 1.0, smile, 0.0});
                CHECK(std::abs(eye_gap(closed, "3.2", "3.4")) <= 1e-9);
                CHECK(std::abs(eye_gap(closed, "3.1", "3.3")) <= 1e-9);
            }
        }
    }

    TEST_CASE("a blink closes the eye mostly from above, monotonically in the amount") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            double previous_gap = eye_gap(face, "3.2", "3.4");
            for (int step = 1; step <= 10; ++step) {
                const double amount = step / 10.0;
                CAPTURE(amount);
                const FaceModel blinking = apply_expression(face, Expression{amount, 0.0, 0.0, 0.0});
                const double gap = eye_gap(blinking, "3.2", "3.4");
                CHECK(gap < previous_gap);
                CHECK(gap >= -1e-9);
                previous_gap = gap;
                // Thesis 2.4.2: the eye height scales by (1 - amount).
                CHECK(gap == doctest::Approx((1.0 - amount) * eye_gap(face, "3.2", "3.4")));
                const double upper_drop = blinking.point("3.2").y - face.point("3.2").y;
                const double lower_rise = face.point("3.4").y - blinking.point("3.4").y;
                CHECK(upper_drop > 0.0);
                CHECK(lower_rise > 0.0);
                CHECK(upper_drop > lower_rise);
                // blink_left is the image-left eye only.
                CHECK(blinking.point("3.1") == face.point("3.1"));
                CHECK(blinking.point("3.3") == face.point("3.3"));
                CHECK(blinking.point("3.2").x == face.point("3.2").x);
            }
        }
    }

    TEST_CASE("raised brows move all 8 brow points up by EyebrowH times the amount") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            for (double amount : {0.25, 1.0}) {
                CAPTURE(amount);
                const FaceModel raised = apply_expression(face, Expression{0.0, 0.0, 0.0, amount});
                for (const char* id : kBrowIds) {
                    CAPTURE(id);
                    CHECK(raised.point(id).x == face.point(id).x);
                    CHECK(face.point(id).y - raised.point(id).y ==
                          doctest::Approx(amount * face.fapu("EyebrowH")));
                }
                // The lift hangs F G H I below the brows, so they rise with them.
                const LiftedFace before = lift_face(face);
                const LiftedFace after = lift_face(raised);
                for (const char* id : {"F", "G", "H", "I"}) {
                    CAPTURE(id);
                    CHECK(after.local(id).y - before.local(id).y ==
                          doctest::Approx(amount * face.fapu("EyebrowH")));
                }
                for (const std::string& id : FaceModel::point_ids()) {
                    if (id.rfind("4.", 0) == 0) continue;
                    CAPTURE(id);
                    CHECK(raised.point(id) == face.point(id));
                }
            }
        }
    }

    TEST_CASE("a smile lifts the mouth corners outward and squints the lower lids") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            for (double amount : {0.5, 1.0}) {
                CAPTURE(amount);
                const FaceModel smiling = apply_expression(face, Expression{0.0, 0.0, amount, 0.0});
                const double lift = amount * face.fapu("UpperLipH");
                CHECK(face.point("8.4").y - smiling.point("8.4").y == doctest::Approx(lift));
                CHECK(face.point("8.3").y - smiling.point("8.3").y == doctest::Approx(lift));
                CHECK(smiling.point("8.4").x < face.point("8.4").x);
                CHECK(smiling.point("8.3").x > face.point("8.3").x);
                // Squint: the lower lids rise, the upper lids stay.
                CHECK(smiling.point("3.4").y < face.point("3.4").y);
                CHECK(smiling.point("3.3").y < face.point("3.3").y);
                CHECK(smiling.point("3.2") == face.point("3.2"));
                CHECK(smiling.point("3.1") == face.point("3.1"));
                CHECK(eye_gap(smiling, "3.2", "3.4") > 0.0);
            }
        }
    }

    TEST_CASE("an amount outside 0..1 or not finite is refused and named") {
        const FaceModel face = FaceModel::default_face();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (double bad : {-0.1, 1.0001, nan, std::numeric_limits<double>::infinity()}) {
            CAPTURE(bad);
            CHECK_THROWS_WITH_AS(apply_expression(face, Expression{bad, 0, 0, 0}),
                                 doctest::Contains("expression.blink_left"), InvalidArgument);
            CHECK_THROWS_WITH_AS(apply_expression(face, Expression{0, bad, 0, 0}),
                                 doctest::Contains("expression.blink_right"), InvalidArgument);
            CHECK_THROWS_WITH_AS(apply_expression(face, Expression{0, 0, bad, 0}),
                                 doctest::Contains("expression.smile"), InvalidArgument);
            CHECK_THROWS_WITH_AS(apply_expression(face, Expression{0, 0, 0, bad}),
                                 doctest::Contains("expression.brows"), InvalidArgument);
        }
        CHECK_THROWS_WITH_AS(apply_expression(face, Expression{0, 0, 1.5, 0}), doctest::Contains("1.5"),
                             InvalidArgument);
    }

    TEST_CASE("all four expressions at once still make a valid face") {
        for (const auto& [name, face] : test::test_faces()) {
            CAPTURE(name);
            for (double amount : {0.5, 1.0}) {
                CAPTURE(amount);
                const FaceModel all = apply_expression(face, Expression{amount, amount, amount, amount});
                CHECK(eye_gap(all, "3.2", "3.4") >= -1e-9);
                CHECK(eye_gap(all, "3.1", "3.3") >= -1e-9);
                CHECK(all.point("8.4").x < all.point("8.3").x);
                // The brows stay above the lids, the corners below the nose.
                CHECK(all.point("4.4").y < all.point("3.2").y);
                CHECK(all.point("4.3").y < all.point("3.1").y);
                CHECK(all.point("8.4").y > all.point("9.15").y);
                CHECK(all.point("8.3").y > all.point("9.15").y);
                // Amounts add: each expression moves its own points by the same amount as alone.
                const FaceModel brows_only = apply_expression(face, Expression{0, 0, 0, amount});
                CHECK(all.point("4.4") == brows_only.point("4.4"));
                const FaceModel smile_only = apply_expression(face, Expression{0, 0, amount, 0});
                CHECK(all.point("8.4") == smile_only.point("8.4"));
            }
        }
    }
}
