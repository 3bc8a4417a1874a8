// expression_simulator.hpp's opening example, extracted from the header by extract_fragment.cmake,
// run on an aligned timeline, with the style file it loads written first (the normal style's).
#include <fstream>

#include "aligned_hello.hpp"
#include "talkface/expression_simulator.hpp"

int main() {
    const talkface::Timeline timeline = aligned_hello();
    std::ofstream("calm.json") << talkface::ExpressionStyle::normal().to_json();
#include "expression_simulator_hpp_example.inc"
    static_cast<void>(pose);
    static_cast<void>(expression);
    return calm_simulator.style().is_nod_simulated ? 1 : 0;
}
