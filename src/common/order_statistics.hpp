// Order statistics of a sample: the levels, rates and fits the stages hold up against what is
// typical. Each takes its values by value, as it reorders them (std::nth_element: linear time,
// where a sort is not), and needs at least one value. Three medians, because an even count has
// two middle values and the stages were tuned each on its own choice of them; which one a caller
// takes is part of its results.
#ifndef TALKFACE_COMMON_ORDER_STATISTICS_HPP
#define TALKFACE_COMMON_ORDER_STATISTICS_HPP

#include <algorithm>
#include <cstddef>
#include <vector>

namespace talkface::detail {

// The sorted values' element at floor(fraction * (n - 1)), without interpolation.
template <typename T>
T percentile_of(std::vector<T> values, double fraction) {
    const auto index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
    return values[index];
}

// The middle value of an odd count, the upper of an even count's middle two.
template <typename T>
T upper_median(std::vector<T> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The middle value of an odd count, the lower of an even count's middle two.
template <typename T>
T lower_median(std::vector<T> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>((values.size() - 1) / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The middle value of an odd count, the mean of an even count's middle two.
inline double mean_median(std::vector<double> values) {
    const std::size_t n = values.size();
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(n / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (n % 2 == 1) return *middle;
    return 0.5 * (*std::max_element(values.begin(), middle) + *middle);
}

}  // namespace talkface::detail

#endif
