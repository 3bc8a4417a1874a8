// The fixed tables of a face: the 72 point ids and the 12 FAPU names, and their indices.
//
// Code that names a point in its source (the pose's expressions and mouth, the lift, the drawing)
// resolves the name once, when it is compiled: `constexpr std::size_t k = point_at("8.4");` is a
// compile error for an id that is not one of the 72, and costs nothing at run time. point_index()
// is the search by name for names that arrive at run time (the face file, FaceModel::point()).
#ifndef TALKFACE_FACE_POINT_IDS_HPP
#define TALKFACE_FACE_POINT_IDS_HPP

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace talkface {
inline namespace v0 {
class FaceModel;
struct Point2;
}  // namespace v0

namespace detail {

inline constexpr std::size_t kHairPointCount = 23;

// The 72 point ids in file order (FaceModel::point_ids() is made from this): the hair first.
inline constexpr std::array<std::string_view, 72> kPointIds{
    "hair.1",  "hair.2",  "hair.3",  "hair.4",  "hair.5",  "hair.6",  "hair.7",      "hair.8",
    "hair.9",  "hair.10", "hair.11", "hair.12", "hair.13", "hair.14", "hair.15",     "hair.16",
    "hair.17", "hair.18", "hair.19", "hair.20", "hair.21", "hair.22", "hair.23",     "11.1",
    "11.2a",   "11.3a",   "11.2",    "11.3",    "10.2",    "10.8",    "10.1",        "10.7",
    "10.10",   "10.9",    "2.1",     "2.14",    "2.13",    "2.2",     "2.3",         "3.2",
    "3.4",     "3.8",     "3.12",    "3.1",     "3.3",     "3.7",     "3.11",        "4.2",
    "4.4",     "4.4a",    "4.6",     "4.1",     "4.3",     "4.3a",    "4.5",         "8.1",
    "8.9",     "8.10",    "8.2",     "8.4",     "8.3",     "9.6",     "9.7",         "9.14",
    "9.13",    "9.2",     "9.1",     "9.4",     "9.5",     "9.15",    "EyeballLeft", "EyeballRight"};

// The index of `id` in `ids`; for an id not among them, a throw, which in a constant expression
// (a constexpr variable) stops the build.
template <std::size_t N>
constexpr std::size_t index_in(const std::array<std::string_view, N>& ids, std::string_view id) {
    for (std::size_t i = 0; i < N; ++i) {
        if (ids[i] == id) return i;
    }
    throw std::logic_error("not a point id");
}

// A point id's index in FaceModel::points(), for ids written in the source (see the top).
constexpr std::size_t point_at(std::string_view id) {
    return index_in(kPointIds, id);
}

// The index of a point id in FaceModel::point_ids(), or nullopt: a plain search of the 72, for ids
// read at run time.
std::optional<std::size_t> point_index(std::string_view id);
// The index of a FAPU name in FaceModel::fapu_names(), or nullopt.
std::optional<std::size_t> fapu_index(std::string_view name);

// Moves the point at `index` (FaceModel::points() order), checked as FaceModel::set_point() checks:
// the pipeline moves the points it names by index, not by id. FaceModel befriends it.
struct FacePointEditor {
    // \throws talkface::InvalidArgument naming the point, as FaceModel::set_point().
    static void set_point(FaceModel& face, std::size_t index, Point2 image_xy);
};

// FAPU indices (FaceModel::fapu_names() order), for code that reads them by name at compile time.
enum FapuIndex : std::size_t {
    kFapuD,
    kFapuEyebrowH,
    kFapuEyebrowH2,
    kFapuLeftEyeH,
    kFapuRightEyeH,
    kFapuUpperLipH,
    kFapuLowerLipH,
    kFapuMNS0,
    kFapuMW0,
    kFapuJawH,
    kFapuR1,
    kFapuR2
};

}  // namespace detail
}  // namespace talkface

#endif
