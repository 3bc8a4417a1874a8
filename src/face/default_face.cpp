// The built-in default face (SPEC pipeline step 1): a symmetric cartoon face with short hair.
//
// Every coordinate is a multiple of 0.25 px and the face mirrors exactly about x = 200 (point pairs
// as in Table 2.1: 3.2 <-> 3.1, 4.4a <-> 4.3a, 8.9 <-> 8.10, ...; hair.k <-> hair.(24 - k), hair.12
// on the axis), so mirrored values are exact and a turn by beta mirrors a turn by -beta bit for bit.
// d = 65 px makes the rotation origin O = (200, 200 + 1.3 d) = (200, 284.5) land on that grid too,
// which keeps global -> local -> global exact. The face fits a 400 x 400 px canvas.
#include <iterator>
#include <utility>

#include "talkface/face_model.hpp"

namespace talkface {
inline namespace v0 {

namespace {

struct NamedPoint {
    const char* id;
    Point2 image_xy;
};

// Hair: the polygon runs from the image-left side at ear level (hair.1) over the crown (hair.12) down
// to the right side (hair.23). At the sides it keeps at least 0.2 d outside the face contour: hair
// sits behind the face (depth -0.58 d), so a 15-degree turn slides the face towards it.
// clang-format off
const NamedPoint kDefaultPoints[] = {
    // hair: image left, crown, image right
    {"hair.1", {112.0, 226.0}}, {"hair.2", {108.0, 204.0}}, {"hair.3", {104.0, 180.0}},
    {"hair.4", {103.0, 154.0}}, {"hair.5", {108.0, 128.0}}, {"hair.6", {118.0, 105.0}},
    {"hair.7", {132.0, 86.0}}, {"hair.8", {148.0, 72.0}}, {"hair.9", {164.0, 63.0}},
    {"hair.10", {176.0, 58.5}}, {"hair.11", {188.0, 56.0}}, {"hair.12", {200.0, 55.0}},
    {"hair.13", {212.0, 56.0}}, {"hair.14", {224.0, 58.5}}, {"hair.15", {236.0, 63.0}},
    {"hair.16", {252.0, 72.0}}, {"hair.17", {268.0, 86.0}}, {"hair.18", {282.0, 105.0}},
    {"hair.19", {292.0, 128.0}}, {"hair.20", {297.0, 154.0}}, {"hair.21", {296.0, 180.0}},
    {"hair.22", {292.0, 204.0}}, {"hair.23", {288.0, 226.0}},
    // forehead / hairline
    {"11.1", {200.0, 118.0}},
    {"11.2a", {156.0, 127.0}}, {"11.3a", {244.0, 127.0}},
    {"11.2", {133.0, 166.0}}, {"11.3", {267.0, 166.0}},
    // ears (image left, then right), cheeks
    {"10.2", {109.0, 198.0}}, {"10.8", {131.0, 246.0}},
    {"10.1", {291.0, 198.0}}, {"10.7", {269.0, 246.0}},
    {"10.10", {133.0, 229.0}}, {"10.9", {267.0, 229.0}},
    // chin, jaw, inner lips (closed: 2.2.y == 2.3.y)
    {"2.1", {200.0, 315.0}},
    {"2.14", {153.0, 289.0}}, {"2.13", {247.0, 289.0}},
    {"2.2", {200.0, 268.0}}, {"2.3", {200.0, 268.0}},
    // eyes: image left (top, bottom, inner, outer corner), then right
    {"3.2", {167.5, 189.0}}, {"3.4", {167.5, 211.0}}, {"3.8", {186.0, 201.0}}, {"3.12", {149.0, 199.5}},
    {"3.1", {232.5, 189.0}}, {"3.3", {232.5, 211.0}}, {"3.7", {251.0, 199.5}}, {"3.11", {214.0, 201.0}},
    // eyebrows, upper edge: image left (inner to outer end), then right
    {"4.2", {186.0, 170.0}}, {"4.4", {167.0, 166.0}}, {"4.4a", {153.0, 169.5}}, {"4.6", {143.0, 177.0}},
    {"4.1", {214.0, 170.0}}, {"4.3", {233.0, 166.0}}, {"4.3a", {247.0, 169.5}}, {"4.5", {257.0, 177.0}},
    // mouth
    {"8.1", {200.0, 263.0}}, {"8.9", {193.0, 261.0}}, {"8.10", {207.0, 261.0}}, {"8.2", {200.0, 277.0}},
    {"8.4", {177.0, 268.0}}, {"8.3", {223.0, 268.0}},
    // nose
    {"9.6", {195.0, 206.0}}, {"9.7", {205.0, 206.0}}, {"9.14", {193.0, 234.0}}, {"9.13", {207.0, 234.0}},
    {"9.2", {186.5, 243.0}}, {"9.1", {213.5, 243.0}}, {"9.4", {192.5, 249.0}}, {"9.5", {207.5, 249.0}},
    {"9.15", {200.0, 251.0}},
    // eyeball centres
    {"EyeballLeft", {167.5, 200.0}}, {"EyeballRight", {232.5, 200.0}},
};
// clang-format on
static_assert(std::size(kDefaultPoints) == FaceModel::kPointCount);

}  // namespace

FaceModel FaceModel::default_face() {
    // Built once and copied: FaceModel() starts from it, and project_face() default-constructs a
    // ProjectedFace (and so a FaceModel) every frame.
    static const FaceModel built = [] {
        FaceModel face{Blank{}};
        for (const NamedPoint& named : kDefaultPoints) face.set_point(named.id, named.image_xy);
        // All twelve FAPUs are set, so a caller never sees a value it did not expect. The measurable
        // ones equal detail::measured_fapu(); EyebrowH and EyebrowH2 are its 0.12 d and 0.09 d.
        const std::pair<const char*, double> fapus_px[] = {
            {"d", 65.0},         {"EyebrowH", 7.8},  {"EyebrowH2", 5.85}, {"LeftEyeH", 22.0},
            {"RightEyeH", 22.0}, {"UpperLipH", 5.0}, {"LowerLipH", 9.0},  {"MNS0", 17.0},
            {"MW0", 46.0},       {"JawH", 38.0},     {"r1", 11.0},        {"r2", 11.0}};
        for (const auto& [name, value_px] : fapus_px) face.set_fapu(name, value_px);
        face.set_name("default");
        return face;
    }();
    return built;
}

}  // namespace v0
}  // namespace talkface
