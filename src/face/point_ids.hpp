// The fixed tables of a face: the 72 point ids and the 12 FAPU names, and their indices.
#ifndef TALKFACE_FACE_POINT_IDS_HPP
#define TALKFACE_FACE_POINT_IDS_HPP

#include <cstddef>
#include <optional>
#include <string_view>

namespace talkface::detail {

// The index of a point id in FaceModel::point_ids(), or nullopt.
std::optional<std::size_t> point_index(std::string_view id);
// The index of a FAPU name in FaceModel::fapu_names(), or nullopt.
std::optional<std::size_t> fapu_index(std::string_view name);

// FAPU indices (FaceModel::fapu_names() order), for code that reads them by name at compile time.
enum FapuIndex : std::size_t {
    kFapuD, kFapuEyebrowH, kFapuEyebrowH2, kFapuLeftEyeH, kFapuRightEyeH, kFapuUpperLipH,
    kFapuLowerLipH, kFapuMNS0, kFapuMW0, kFapuJawH, kFapuR1, kFapuR2
};

inline constexpr std::size_t kHairPointCount = 23;

}  // namespace talkface::detail

#endif
