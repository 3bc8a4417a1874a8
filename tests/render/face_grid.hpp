// The faces and poses the render tests check their properties over: the built-in face and every
// sample face file, at -15..15 degrees on each axis, and a talking head's frames at those poses.
#ifndef TALKFACE_TESTS_RENDER_FACE_GRID_HPP
#define TALKFACE_TESTS_RENDER_FACE_GRID_HPP

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/test_paths.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/mouth_shape.hpp"

namespace talkface::test {

// "default" for the built-in face, then samples/faces/*.xml by path, in sorted order.
inline std::vector<std::pair<std::string, FaceModel>> bundled_faces() {
    std::vector<std::pair<std::string, FaceModel>> faces{{"default", FaceModel::default_face()}};
    std::set<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator(source_path("samples/faces"))) {
        if (entry.path().extension() == ".xml") paths.insert(entry.path().string());
    }
    for (const std::string& path : paths) faces.emplace_back(path, FaceModel::load(path));
    return faces;
}

// 125 poses: each of alpha, beta, gamma in {-15, -7.5, 0, 7.5, 15} degrees.
inline std::vector<Pose> pose_grid() {
    std::vector<Pose> poses;
    const double angles[] = {-15.0, -7.5, 0.0, 7.5, 15.0};
    for (double alpha : angles) {
        for (double beta : angles) {
            for (double gamma : angles) poses.push_back({alpha, beta, gamma});
        }
    }
    return poses;
}

// A talking head: every mouth shape at every pose of the grid.
inline std::vector<FaceState> talking_frames(const FaceModel& face) {
    std::vector<FaceState> frames;
    for (const Pose& pose : pose_grid()) {
        for (MouthShape shape : all_mouth_shapes()) {
            FaceState state;
            state.pose = pose;
            state.mouth = mouth_controls(face, shape);
            frames.push_back(state);
        }
    }
    return frames;
}

}  // namespace talkface::test

#endif
