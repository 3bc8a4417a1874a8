#include "speech/level_line.hpp"

namespace talkface::detail {

LevelLine fit_level_line(const FeatureTrack& track, int column, std::size_t first, std::size_t end) {
    const double n = static_cast<double>(end - first);
    double sum_x = 0.0, sum_y = 0.0, sum_xx = 0.0, sum_xy = 0.0;
    for (std::size_t t = first; t < end; ++t) {
        const double x = static_cast<double>(t - first);
        const double y = track.at(t, column);
        sum_x += x;
        sum_y += y;
        sum_xx += x * x;
        sum_xy += x * y;
    }
    const double spread = n * sum_xx - sum_x * sum_x;
    const double slope = spread > 0.0 ? (n * sum_xy - sum_x * sum_y) / spread : 0.0;
    return {(sum_y - slope * sum_x) / n, slope};
}

}  // namespace talkface::detail
