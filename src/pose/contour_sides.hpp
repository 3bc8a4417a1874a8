// The face contour's side points (forehead, cheek, jaw) of Algorithm 2.3 steps 5-6: frontal, and on
// the side the head turns away from past 10 degrees. project_face() names them in ProjectedFace's
// left_contour / right_contour; the drawing reads them at their indices.
#ifndef TALKFACE_POSE_CONTOUR_SIDES_HPP
#define TALKFACE_POSE_CONTOUR_SIDES_HPP

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "lift/lifted_point_index.hpp"

namespace talkface::detail {

// One side's three contour points, by id and by index in the lifted order.
struct ContourSide {
    std::array<std::string_view, 3> ids;
    std::array<std::size_t, 3> indices;

    std::array<std::string, 3> id_strings() const {
        return {std::string(ids[0]), std::string(ids[1]), std::string(ids[2])};
    }
};

constexpr ContourSide contour_side(std::string_view forehead, std::string_view cheek, std::string_view jaw) {
    return {{forehead, cheek, jaw}, {lifted_at(forehead), lifted_at(cheek), lifted_at(jaw)}};
}

// Image left and right, frontal and substituted (SPEC's un-mirrored frame: see project_face()).
inline constexpr ContourSide kLeftContour = contour_side("11.2", "10.10", "2.14");
inline constexpr ContourSide kLeftContourTurned = contour_side("N", "L", "J");
inline constexpr ContourSide kRightContour = contour_side("11.3", "10.9", "2.13");
inline constexpr ContourSide kRightContourTurned = contour_side("Q", "M", "K");

// The indices of a side's three ids: one of the four sides above, compared by id (a few
// instructions a frame); any other ids are searched for. \throws talkface::InvalidArgument naming an
// id that is not a point of a projected face.
std::array<std::size_t, 3> contour_indices(const std::array<std::string, 3>& side);

}  // namespace talkface::detail

#endif
