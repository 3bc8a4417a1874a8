// The faces the pose and lips tests run on: the built-in default face and the sample faces
// samples/faces/male.xml and female.xml (each skipped, with a message, while it does not exist).
#ifndef TALKFACE_TESTS_POSE_TEST_FACES_HPP
#define TALKFACE_TESTS_POSE_TEST_FACES_HPP

#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/test_paths.hpp"
#include "talkface/face_model.hpp"

namespace talkface::test {

struct NamedFace {
    std::string name;
    FaceModel face;
};

inline std::vector<NamedFace> test_faces() {
    std::vector<NamedFace> faces{{"default", FaceModel::default_face()}};
    for (const char* sample : {"samples/faces/male.xml", "samples/faces/female.xml"}) {
        const std::string path = source_path(sample);
        if (std::filesystem::exists(path)) {
            faces.push_back({sample, FaceModel::load(path)});
        } else {
            MESSAGE("skipped, not there yet: " << sample);
        }
    }
    return faces;
}

// Calls `check(alpha_deg, beta_deg, gamma_deg)` for every pose of the grid of STYLE.md section 6
// (-15, -10, ..., 15 degrees on each axis), with the angles captured for any failure's message.
template <typename Check>
void for_each_grid_pose(Check&& check) {
    constexpr double kAnglesDeg[] = {-15.0, -10.0, -5.0, 0.0, 5.0, 10.0, 15.0};
    for (const double alpha_deg : kAnglesDeg) {
        for (const double beta_deg : kAnglesDeg) {
            for (const double gamma_deg : kAnglesDeg) {
                CAPTURE(alpha_deg);
                CAPTURE(beta_deg);
                CAPTURE(gamma_deg);
                check(alpha_deg, beta_deg, gamma_deg);
            }
        }
    }
}

}  // namespace talkface::test

#endif
