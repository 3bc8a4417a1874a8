// Where a point id stands in a lifted or projected face (LiftedFace::points, ProjectedFace::points):
// the 72 model points in FaceModel::point_ids() order, then the 17 additional points A .. S.
//
// As face/point_ids.hpp's point_at(), lifted_at() resolves the ids a source file names when it is
// compiled: posing and drawing read every frame's points by index, never by name.
#ifndef TALKFACE_LIFT_LIFTED_POINT_INDEX_HPP
#define TALKFACE_LIFT_LIFTED_POINT_INDEX_HPP

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "face/point_ids.hpp"

namespace talkface::detail {

// Algorithm 2.1's additional points (additional_point_ids() is made from this): A .. S without O,
// the rotation origin, and P, its name for any point.
inline constexpr std::array<std::string_view, 17> kAdditionalPointIds{
    "A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M", "N", "Q", "R", "S"};

inline constexpr std::size_t kLiftedPointCount = kPointIds.size() + kAdditionalPointIds.size();

// The lifted order's ids.
inline constexpr std::array<std::string_view, kLiftedPointCount> kLiftedPointIds = [] {
    std::array<std::string_view, kLiftedPointCount> ids{};
    for (std::size_t i = 0; i < kPointIds.size(); ++i) ids[i] = kPointIds[i];
    for (std::size_t i = 0; i < kAdditionalPointIds.size(); ++i)
        ids[kPointIds.size() + i] = kAdditionalPointIds[i];
    return ids;
}();

// A point's index in the lifted order, for ids written in the source (in a constexpr variable: an
// unknown id stops the build).
constexpr std::size_t lifted_at(std::string_view id) {
    return index_in(kLiftedPointIds, id);
}

// The indices of a list of ids, in its order.
template <std::size_t N>
constexpr std::array<std::size_t, N> lifted_at(const std::string_view (&ids)[N]) {
    std::array<std::size_t, N> indices{};
    for (std::size_t i = 0; i < N; ++i) indices[i] = lifted_at(ids[i]);
    return indices;
}

// The index of `id` in the lifted order, or nullopt: a plain search, for ids that arrive at run time.
std::optional<std::size_t> lifted_point_index(std::string_view id);

}  // namespace talkface::detail

#endif
