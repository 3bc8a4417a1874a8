// Where a point id stands in a lifted or projected face (LiftedFace::points, ProjectedFace::points):
// the 72 model points in FaceModel::point_ids() order, then the 17 additional points A .. S.
#ifndef TALKFACE_LIFT_LIFTED_POINT_INDEX_HPP
#define TALKFACE_LIFT_LIFTED_POINT_INDEX_HPP

#include <cstddef>
#include <optional>
#include <string_view>

namespace talkface::detail {

// The index of `id` in a lifted face's points, or nullopt for an id that is not one of them.
// As cheap as face/point_ids.hpp's point_index(), for drawing every point of every frame.
std::optional<std::size_t> lifted_point_index(std::string_view id);

}  // namespace talkface::detail

#endif
