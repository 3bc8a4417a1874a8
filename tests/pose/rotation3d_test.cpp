#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "pose/test_faces.hpp"
#include "talkface/errors.hpp"
#include "talkface/rotation3d.hpp"

using namespace talkface;

namespace {

constexpr double kPi = 3.14159265358979323846;

double entry(const Rotation3D& r, int row, int column) {
    return r.matrix()[static_cast<std::size_t>(3 * row + column)];
}

double determinant(const Rotation3D& r) {
    auto m = [&](int row, int column) { return entry(r, row, column); };
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
           m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

// Thesis 2.4.3.1 step by step (Y, then X, then Z), with SPEC's sign fix in z2.
Point3 thesis_rotation(Point3 p, double alpha_deg, double beta_deg, double gamma_deg) {
    const double a = alpha_deg * kPi / 180.0, b = beta_deg * kPi / 180.0, g = gamma_deg * kPi / 180.0;
    const double x1 = p.x * std::cos(b) + p.z * std::sin(b);
    const double y1 = p.y;
    const double z1 = -p.x * std::sin(b) + p.z * std::cos(b);
    const double x2 = x1;
    const double y2 = y1 * std::cos(a) - z1 * std::sin(a);
    const double z2 = y1 * std::sin(a) + z1 * std::cos(a);
    return Point3{x2 * std::cos(g) - y2 * std::sin(g), x2 * std::sin(g) + y2 * std::cos(g), z2};
}

}  // namespace

TEST_SUITE("Rotation3D") {
    TEST_CASE("every pose of the grid is a proper rotation: R R^T = I and det R = 1") {
        test::for_each_grid_pose([&](double alpha_deg, double beta_deg, double gamma_deg) {
            const Rotation3D r(alpha_deg, beta_deg, gamma_deg);
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) {
                    double dot = 0.0;
                    for (int k = 0; k < 3; ++k) dot += entry(r, i, k) * entry(r, j, k);
                    CHECK(std::abs(dot - (i == j ? 1.0 : 0.0)) <= 1e-12);
                }
            }
            CHECK(std::abs(determinant(r) - 1.0) <= 1e-12);
        });
    }

    TEST_CASE("rotate then unrotate gives the point back") {
        const Point3 points[] = {
            {0, 0, 0}, {120.5, -33.25, 90.0}, {-200.0, 180.0, -40.0}, {1e-3, 2e-3, 3e-3}};
        test::for_each_grid_pose([&](double alpha_deg, double beta_deg, double gamma_deg) {
            const Rotation3D r(alpha_deg, beta_deg, gamma_deg);
            for (const Point3& p : points) {
                const Point3 there = r.rotate(p);
                const Point3 back = r.unrotate(there);
                CHECK(std::abs(back.x - p.x) <= 1e-12 * 300.0);
                CHECK(std::abs(back.y - p.y) <= 1e-12 * 300.0);
                CHECK(std::abs(back.z - p.z) <= 1e-12 * 300.0);
                // A rotation keeps lengths.
                CHECK(std::hypot(there.x, there.y, there.z) ==
                      doctest::Approx(std::hypot(p.x, p.y, p.z)).epsilon(1e-12));
            }
        });
    }

    TEST_CASE("the matrix is the thesis's Y, X, Z formulas with SPEC's sign in z2") {
        const Point3 p{37.0, -52.5, 81.25};
        test::for_each_grid_pose([&](double alpha_deg, double beta_deg, double gamma_deg) {
            const Point3 got = Rotation3D(alpha_deg, beta_deg, gamma_deg).rotate(p);
            const Point3 want = thesis_rotation(p, alpha_deg, beta_deg, gamma_deg);
            CHECK(std::abs(got.x - want.x) <= 1e-12);
            CHECK(std::abs(got.y - want.y) <= 1e-12);
            CHECK(std::abs(got.z - want.z) <= 1e-12);
        });
    }

    TEST_CASE("zero angles are the identity, bit for bit") {
        const Rotation3D zero(0.0, 0.0, 0.0);
        CHECK(zero == Rotation3D());
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) CHECK(entry(zero, i, j) == (i == j ? 1.0 : 0.0));
        }
        const Point3 p{123.456, -0.1, 78.9};
        CHECK(zero.rotate(p) == p);
        CHECK(zero.unrotate(p) == p);
        CHECK(Rotation3D(0.0, 5.0, 0.0) != zero);
    }

    TEST_CASE("each angle turns the face the way rotation3d.hpp says") {
        // Local frame: x towards the image left, y up, z towards the viewer.
        const Point3 nose_tip{0.0, 40.0, 100.0};
        const Point3 head_top{0.0, 150.0, 0.0};
        for (double angle_deg : {5.0, 10.0, 15.0}) {
            CAPTURE(angle_deg);
            // beta > 0: the nose tip goes towards the image left (+x); beta < 0 to the right.
            CHECK(Rotation3D(0.0, angle_deg, 0.0).rotate(nose_tip).x > 0.0);
            CHECK(Rotation3D(0.0, -angle_deg, 0.0).rotate(nose_tip).x < 0.0);
            // alpha > 0: a nod down, the nose tip drops.
            CHECK(Rotation3D(angle_deg, 0.0, 0.0).rotate(nose_tip).y < nose_tip.y);
            CHECK(Rotation3D(-angle_deg, 0.0, 0.0).rotate(nose_tip).y > nose_tip.y);
            // gamma > 0: the top of the head tilts towards the image right (-x).
            CHECK(Rotation3D(0.0, 0.0, angle_deg).rotate(head_top).x < 0.0);
            CHECK(Rotation3D(0.0, 0.0, -angle_deg).rotate(head_top).x > 0.0);
        }
    }

    TEST_CASE("an angle that is not finite is refused and named") {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        CHECK_THROWS_WITH_AS(Rotation3D(nan, 0.0, 0.0), doctest::Contains("alpha_deg"), InvalidArgument);
        CHECK_THROWS_WITH_AS(Rotation3D(0.0, inf, 0.0), doctest::Contains("beta_deg"), InvalidArgument);
        CHECK_THROWS_WITH_AS(Rotation3D(0.0, 0.0, -inf), doctest::Contains("gamma_deg"), InvalidArgument);
        try {
            Rotation3D(0.0, nan, 0.0);
            FAIL("NaN accepted");
        } catch (const InvalidArgument& error) {
            CHECK(error.parameter() == "beta_deg");
        }
    }

    TEST_CASE("any finite angle is a rotation, the angles read back in degrees") {
        const Rotation3D r(90.0, -200.0, 30.0);
        CHECK(r.alpha_deg() == 90.0);
        CHECK(r.beta_deg() == -200.0);
        CHECK(r.gamma_deg() == 30.0);
        CHECK(std::abs(determinant(r) - 1.0) <= 1e-12);
    }
}
