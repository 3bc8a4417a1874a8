// FaceModel's tables and accessors. The file format is in face_file.cpp, the built-in face in
// default_face.cpp.
#include "talkface/face_model.hpp"

#include <algorithm>
#include <cmath>

#include "face/fapu_measure.hpp"
#include "common/internal_error.hpp"
#include "common/number_format.hpp"
#include "face/point_ids.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

std::vector<std::string> make_point_ids() {
    return {detail::kPointIds.begin(), detail::kPointIds.end()};
}

std::optional<std::size_t> find_index(const std::vector<std::string>& names, std::string_view name) {
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) return std::nullopt;
    return static_cast<std::size_t>(found - names.begin());
}

std::size_t require_point(std::string_view id) {
    if (auto index = detail::point_index(id)) return *index;
    throw InvalidArgument("point \"" + std::string(id) + "\"",
                          "no such point in the 72-point face model (see FaceModel::point_ids())");
}

std::size_t require_fapu(std::string_view name) {
    if (auto index = detail::fapu_index(name)) return *index;
    throw InvalidArgument("FAPU \"" + std::string(name) + "\"",
                          "no such FAPU; expected one of d, EyebrowH, EyebrowH2, LeftEyeH, RightEyeH, "
                          "UpperLipH, LowerLipH, MNS0, MW0, JawH, r1, r2");
}

}  // namespace

bool operator==(const FaceColors& a, const FaceColors& b) {
    return a.skin == b.skin && a.hair == b.hair && a.brows == b.brows && a.eye_white == b.eye_white &&
           a.iris == b.iris && a.lips == b.lips && a.mouth_inside == b.mouth_inside &&
           a.outline == b.outline;
}

FaceModel::FaceModel() : FaceModel(default_face()) {}

const std::vector<std::string>& FaceModel::point_ids() {
    static const std::vector<std::string> ids = make_point_ids();
    return ids;
}

const std::vector<std::string>& FaceModel::fapu_names() {
    static const std::vector<std::string> names = {"d",         "EyebrowH",  "EyebrowH2", "LeftEyeH",
                                                   "RightEyeH", "UpperLipH", "LowerLipH", "MNS0",
                                                   "MW0",       "JawH",      "r1",        "r2"};
    return names;
}

bool FaceModel::is_point_id(std::string_view id) { return detail::point_index(id).has_value(); }

Point2 FaceModel::point(std::string_view id) const { return points_[require_point(id)]; }

void FaceModel::check_coordinates(std::string_view id, Point2 image_xy) {
    const auto within = [](double value) { return std::isfinite(value) && std::abs(value) <= kMaxCoordinatePx; };
    if (!within(image_xy.x) || !within(image_xy.y)) {
        throw InvalidArgument("point \"" + std::string(id) + "\"",
                              "coordinates must be finite and within +-1e6 px, got (" + detail::format_shortest(image_xy.x) +
                                  ", " + detail::format_shortest(image_xy.y) + ")");
    }
}

void FaceModel::set_point(std::string_view id, Point2 image_xy) {
    const std::size_t index = require_point(id);
    check_coordinates(id, image_xy);
    points_[index] = image_xy;
}

double FaceModel::fapu(std::string_view name) const { return fapus_[require_fapu(name)]; }

void FaceModel::set_fapu(std::string_view name, double value_px) {
    const std::size_t index = require_fapu(name);
    if (!std::isfinite(value_px) || value_px <= 0.0 || value_px > kMaxFapuPx) {
        throw InvalidArgument("FAPU \"" + std::string(name) + "\"",
                              "must be finite, positive and at most 1e7 px, got " + detail::format_shortest(value_px));
    }
    fapus_[index] = value_px;
}

bool operator==(const FaceModel& a, const FaceModel& b) {
    return a.points_ == b.points_ && a.fapus_ == b.fapus_ && a.colors_ == b.colors_ && a.name_ == b.name_;
}

}  // namespace v0

// Declared in face/point_ids.hpp and face/fapu_measure.hpp, outside the inline namespace.
namespace detail {

std::optional<std::size_t> point_index(std::string_view id) {
    const auto found = std::find(kPointIds.begin(), kPointIds.end(), id);
    if (found == kPointIds.end()) return std::nullopt;
    return static_cast<std::size_t>(found - kPointIds.begin());
}

void FacePointEditor::set_point(FaceModel& face, std::size_t index, Point2 image_xy) {
    FaceModel::check_coordinates(kPointIds.at(index), image_xy);
    face.points_[index] = image_xy;
}

std::optional<std::size_t> fapu_index(std::string_view name) {
    return find_index(FaceModel::fapu_names(), name);
}

double measured_fapu(const FaceModel& face, std::string_view name) {
    auto p = [&](const char* id) { return face.point(id); };
    const double d = std::hypot(p("EyeballLeft").x - p("EyeballRight").x,
                                p("EyeballLeft").y - p("EyeballRight").y);
    if (name == "d") return d;
    if (name == "EyebrowH") return 0.12 * d;
    if (name == "EyebrowH2") return 0.09 * d;
    if (name == "LeftEyeH") return p("3.4").y - p("3.2").y;
    if (name == "RightEyeH") return p("3.3").y - p("3.1").y;
    if (name == "UpperLipH") return p("2.2").y - p("8.1").y;
    if (name == "LowerLipH") return p("8.2").y - p("2.3").y;
    if (name == "MNS0") return p("2.2").y - p("9.15").y;
    if (name == "MW0") return p("8.3").x - p("8.4").x;
    if (name == "JawH") return p("2.1").y - p("8.2").y;
    if (name == "r1") return 0.5 * (p("3.4").y - p("3.2").y);
    if (name == "r2") return 0.5 * (p("3.3").y - p("3.1").y);
    require_fapu(name);
    return 0.0;
}

}  // namespace detail

}  // namespace talkface
