// FaceModel's tables and accessors. The file format is in face_file.cpp, the built-in face in
// default_face.cpp.
#include "talkface/face_model.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <cstring>

#include "face/fapu_measure.hpp"
#include "common/internal_error.hpp"
#include "common/number_format.hpp"
#include "face/point_ids.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

std::vector<std::string> make_point_ids() {
    std::vector<std::string> ids;
    for (std::size_t i = 1; i <= detail::kHairPointCount; ++i) ids.push_back("hair." + std::to_string(i));
    for (const char* id :
         {"11.1", "11.2a", "11.3a", "11.2", "11.3", "10.2", "10.8", "10.1", "10.7", "10.10", "10.9",
          "2.1", "2.14", "2.13", "2.2", "2.3", "3.2", "3.4", "3.8", "3.12", "3.1", "3.3", "3.7", "3.11",
          "4.2", "4.4", "4.4a", "4.6", "4.1", "4.3", "4.3a", "4.5", "8.1", "8.9", "8.10", "8.2", "8.4",
          "8.3", "9.6", "9.7", "9.14", "9.13", "9.2", "9.1", "9.4", "9.5", "9.15", "EyeballLeft",
          "EyeballRight"}) {
        ids.emplace_back(id);
    }
    return ids;
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

void FaceModel::set_point(std::string_view id, Point2 image_xy) {
    const std::size_t index = require_point(id);
    const auto within = [](double value) { return std::isfinite(value) && std::abs(value) <= kMaxCoordinatePx; };
    if (!within(image_xy.x) || !within(image_xy.y)) {
        throw InvalidArgument("point \"" + std::string(id) + "\"",
                              "coordinates must be finite and within +-1e6 px, got (" + detail::format_shortest(image_xy.x) +
                                  ", " + detail::format_shortest(image_xy.y) + ")");
    }
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

namespace {

// An id's first 8 bytes as one integer (zeros past its end), read with fixed-size copies.
std::uint64_t packed_id(std::string_view id) {
    std::uint64_t key = 0;
    switch (std::min<std::size_t>(id.size(), 8)) {
        case 8: std::memcpy(&key, id.data(), 8); break;
        case 7: std::memcpy(&key, id.data(), 7); break;
        case 6: std::memcpy(&key, id.data(), 6); break;
        case 5: std::memcpy(&key, id.data(), 5); break;
        case 4: std::memcpy(&key, id.data(), 4); break;
        case 3: std::memcpy(&key, id.data(), 3); break;
        case 2: std::memcpy(&key, id.data(), 2); break;
        case 1: std::memcpy(&key, id.data(), 1); break;
        default: break;
    }
    return key;
}

// The 72 ids by their packed first 8 bytes (unique among them) in an open-addressed table of 256
// slots, a quarter full: the slot is the key's Fibonacci hash, a collision takes the next slot.
class PointIdTable {
public:
    PointIdTable() {
        const auto& ids = ids_;
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const std::uint64_t key = packed_id(ids[i]);
            std::size_t slot = slot_of(key);
            while (slots_[slot].index != kEmpty) {
                if (slots_[slot].key == key) throw internal_error("two point ids share their first 8 bytes");
                slot = (slot + 1) % kSlots;
            }
            slots_[slot] = {key, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(ids[i].size())};
        }
    }

    std::optional<std::size_t> find(std::string_view id) const {
        const std::uint64_t key = packed_id(id);
        for (std::size_t slot = slot_of(key);; slot = (slot + 1) % kSlots) {
            const Slot& entry = slots_[slot];
            if (entry.index == kEmpty) return std::nullopt;
            if (entry.key == key) {
                // The key holds the first 8 bytes: a longer id is compared whole.
                const bool same = entry.length == id.size() && (id.size() <= 8 || ids_[entry.index] == id);
                if (!same) return std::nullopt;
                return entry.index;
            }
        }
    }

private:
    static constexpr std::size_t kSlots = 256;
    static constexpr std::uint32_t kEmpty = 0xffffffffu;
    struct Slot {
        std::uint64_t key = 0;
        std::uint32_t index = kEmpty;
        std::uint32_t length = 0;
    };
    // 2^64 / the golden ratio: the top 8 bits of the product spread ids that differ in any byte.
    static std::size_t slot_of(std::uint64_t key) { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 56); }

    const std::vector<std::string>& ids_ = FaceModel::point_ids();
    std::array<Slot, kSlots> slots_{};
};

}  // namespace

std::optional<std::size_t> point_index(std::string_view id) {
    // Posing and drawing a face name its points by id, about 900 000 times in a 3-minute animation:
    // a table of the ids' packed bytes instead of std::unordered_map<std::string_view>, whose
    // general-purpose hash took 160 instructions a look-up, 4% of the 3 minutes with the drawing's
    // own std::string map (bench/README.md, session 13).
    static const PointIdTable table;
    return table.find(id);
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
