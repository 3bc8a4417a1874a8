// talkface: FaceModel, the 72 feature points and FAPUs of a cartoon face (SPEC "Face model").
#ifndef TALKFACE_FACE_MODEL_HPP
#define TALKFACE_FACE_MODEL_HPP

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "talkface/export.h"
#include "talkface/types.hpp"

namespace talkface {
namespace detail {
struct FacePointEditor;  // the library's own access to a point by index (not API)
}  // namespace detail
inline namespace v0 {

/// The colours a face is drawn with; part of the face file.
struct FaceColors {
    Rgb skin{0xf4, 0xcf, 0xa8};
    Rgb hair{0x3a, 0x2a, 0x22};
    Rgb brows{0x2e, 0x20, 0x18};
    Rgb eye_white{0xff, 0xff, 0xff};
    Rgb iris{0x4a, 0x32, 0x22};
    Rgb lips{0xc8, 0x5a, 0x5a};
    Rgb mouth_inside{0x6a, 0x1e, 0x22};
    Rgb outline{0x5a, 0x3c, 0x2e};
    friend TALKFACE_API bool operator==(const FaceColors& a, const FaceColors& b);
    friend bool operator!=(const FaceColors& a, const FaceColors& b) { return !(a == b); }
};

/// A neutral cartoon face: 72 named feature points in image pixels (y down) and 12 FAPUs.
///
/// Point ids are the thesis's (MPEG-4 numbers, "left" = image left): "hair.1" .. "hair.23" (the hair
/// polygon, in order), "11.1", "11.2a", "11.3a", "11.2", "11.3", "10.2", "10.8", "10.1", "10.7",
/// "10.10", "10.9", "2.1", "2.14", "2.13", "2.2", "2.3", "3.2", "3.4", "3.8", "3.12", "3.1", "3.3",
/// "3.7", "3.11", "4.2", "4.4", "4.4a", "4.6", "4.1", "4.3", "4.3a", "4.5", "8.1", "8.9", "8.10", "8.2",
/// "8.4", "8.3", "9.6", "9.7", "9.14", "9.13", "9.2", "9.1", "9.4", "9.5", "9.15", "EyeballLeft",
/// "EyeballRight". docs/face-format.md draws where each one is.
///
/// FAPUs (pixels): "d" (eyeball distance), "EyebrowH", "EyebrowH2", "LeftEyeH", "RightEyeH",
/// "UpperLipH", "LowerLipH", "MNS0" (mouth-nose separation), "MW0" (mouth width), "JawH", "r1", "r2"
/// (eyeball radii).
///
/// A value type: copyable, comparable, cheap to pass. Thread safety: const members may be called
/// from several threads at once.
class TALKFACE_API FaceModel {
public:
    static constexpr std::size_t kPointCount = 72;
    static constexpr std::size_t kFapuCount = 12;
    /// Every coordinate lies within +-kMaxCoordinatePx: a million pixels is far beyond any image,
    /// and the bound keeps every later computation (projection, canvas size) finite.
    static constexpr double kMaxCoordinatePx = 1e6;
    /// Every FAPU is at most this (a measured FAPU of points within +-kMaxCoordinatePx is less).
    static constexpr double kMaxFapuPx = 1e7;
    /// The newest face file format version this library reads and the one it writes.
    static constexpr int kFileFormatVersion = 1;

    /// The built-in default face (same as default_face()).
    FaceModel();

    /// The built-in default face, compiled into the library.
    static FaceModel default_face();

    /// Reads a face file (docs/face-format.md). FAPUs the file leaves out are measured from the
    /// points (d, eye, lip, mouth, jaw sizes, r1, r2) or set from d (EyebrowH, EyebrowH2).
    /// \throws talkface::FileError if the file cannot be read.
    /// \throws talkface::ParseError naming file:line:column and the point or attribute: not XML, empty,
    ///         unknown version, a missing, duplicate or unknown point, a non-numeric or non-finite value,
    ///         or one beyond kMaxCoordinatePx / kMaxFapuPx.
    static FaceModel load(const std::string& path);

    /// Parses the text of a face file; `source_name` stands for the path in error messages.
    /// \throws talkface::ParseError as load() does.
    static FaceModel from_xml(std::string_view xml, const std::string& source_name = "<string>");

    /// Writes the face file atomically (a temporary file renamed over `path`): on failure `path` is
    /// untouched. load(path) gives back a face equal to this one, bit for bit.
    /// \throws talkface::FileError if the file cannot be written.
    void save(const std::string& path) const;

    /// The face file's text (what save() writes).
    std::string to_xml() const;

    /// The 72 point ids in file order.
    static const std::vector<std::string>& point_ids();
    /// The 12 FAPU names in file order.
    static const std::vector<std::string>& fapu_names();
    /// Whether `id` names one of the 72 points.
    static bool is_point_id(std::string_view id);

    /// A point's image position. \throws talkface::InvalidArgument for an unknown id.
    Point2 point(std::string_view id) const;
    /// Moves a point. \throws talkface::InvalidArgument for an unknown id or a coordinate that is not
    /// finite or lies beyond +-kMaxCoordinatePx.
    void set_point(std::string_view id, Point2 image_xy);
    /// All 72 points, in point_ids() order.
    const std::array<Point2, kPointCount>& points() const { return points_; }

    /// A FAPU in pixels. \throws talkface::InvalidArgument for an unknown name.
    double fapu(std::string_view name) const;
    /// Sets a FAPU. \throws talkface::InvalidArgument for an unknown name or a value that is not
    /// finite and positive, or exceeds kMaxFapuPx.
    void set_fapu(std::string_view name, double value_px);
    /// All 12 FAPUs, in fapu_names() order.
    const std::array<double, kFapuCount>& fapus() const { return fapus_; }

    const FaceColors& colors() const { return colors_; }     ///< colours the face is drawn with
    void set_colors(const FaceColors& colors) { colors_ = colors; }
    const std::string& name() const { return name_; }         ///< a label, e.g. "default"
    void set_name(std::string name) { name_ = std::move(name); }

    friend TALKFACE_API bool operator==(const FaceModel& a, const FaceModel& b);
    friend bool operator!=(const FaceModel& a, const FaceModel& b) { return !(a == b); }

private:
    friend struct detail::FacePointEditor;

    // Throws InvalidArgument naming point `id` unless `image_xy` is finite and within kMaxCoordinatePx.
    static void check_coordinates(std::string_view id, Point2 image_xy);

    // An all-zero face for default_face() and the file reader to fill in: the public default
    // constructor delegates to default_face(), so that cannot use it.
    struct Blank {};
    explicit FaceModel(Blank) {}

    std::array<Point2, kPointCount> points_{};
    std::array<double, kFapuCount> fapus_{};
    FaceColors colors_{};
    std::string name_;
};

}  // namespace v0
}  // namespace talkface

#endif
