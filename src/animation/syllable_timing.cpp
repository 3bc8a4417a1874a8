// Onsets of the mouth shapes inside a syllable (thesis 5.3, as SPEC "Mouth shapes" reads it).
#include <cmath>
#include <string>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"

namespace talkface {
inline namespace v0 {

namespace {

template <std::size_t N>
void check_row(const char* name, const std::array<double, N>& row) {
    double previous = 0.0;
    for (const double fraction : row) {
        if (!std::isfinite(fraction) || fraction <= previous || fraction >= 1.0) {
            std::string values;
            for (const double value : row)
                values += (values.empty() ? "" : ", ") + detail::format_shortest(value);
            throw InvalidArgument(std::string("ShapeOnsetTable::") + name,
                                  "onsets must rise strictly inside (0, 1), got {" + values + "}");
        }
        previous = fraction;
    }
}

}  // namespace

std::vector<double> shape_onsets_s(const Syllable& syllable, const SyllableShapes& shapes,
                                   const ShapeOnsetTable& table) {
    check_row("two_shapes", table.two_shapes);
    check_row("three_shapes", table.three_shapes);
    check_row("four_shapes", table.four_shapes);
    const std::string where = "syllable \"" + syllable.pinyin + "\"";
    const std::size_t count = shapes.shapes.size();
    if (count == 0 || count > 4) {
        throw InvalidArgument(where, "expected 1 to 4 mouth shapes, got " + std::to_string(count));
    }
    if (!std::isfinite(syllable.start_s) || !std::isfinite(syllable.end_s) ||
        syllable.end_s < syllable.start_s) {
        throw InvalidArgument(where, "times must be finite and end at or after the start, got " +
                                         detail::format_shortest(syllable.start_s) + "-" +
                                         detail::format_shortest(syllable.end_s) + " s");
    }

    std::vector<double> fractions{0.0};
    if (count == 2) fractions.insert(fractions.end(), table.two_shapes.begin(), table.two_shapes.end());
    if (count == 3) fractions.insert(fractions.end(), table.three_shapes.begin(), table.three_shapes.end());
    if (count == 4) fractions.insert(fractions.end(), table.four_shapes.begin(), table.four_shapes.end());

    const double duration_s = syllable.end_s - syllable.start_s;
    std::vector<double> onsets;
    for (const double fraction : fractions) onsets.push_back(syllable.start_s + fraction * duration_s);

    // SPEC: where the aligner measured the initial / final boundary, the vowel starts there. A
    // syllable whose first shape is already the vowel's (no initial, or h' / h dropped) keeps it
    // from the start: that is the pre-posture the thesis drops h' for.
    const bool has_measured_final = syllable.final_start_s.has_value() &&
                                    *syllable.final_start_s > syllable.start_s &&
                                    *syllable.final_start_s < syllable.end_s;
    if (has_measured_final && shapes.has_initial_shape && count >= 2) {
        const double final_start_s = *syllable.final_start_s;
        onsets[1] = final_start_s;
        for (std::size_t k = 2; k < count; ++k) {
            const double share = (fractions[k] - fractions[1]) / (1.0 - fractions[1]);
            onsets[k] = final_start_s + share * (syllable.end_s - final_start_s);
        }
    }
    return onsets;
}

}  // namespace v0
}  // namespace talkface
