// The frames encoding of one layer (thesis 6.3.2): every frame's layer as a group of its own,
// hidden except while its <set> shows it; a run of identical frames is one group.
#ifndef TALKFACE_RENDER_FRAMES_ENCODER_HPP
#define TALKFACE_RENDER_FRAMES_ENCODER_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "render/drawing.hpp"

namespace talkface::detail {

class FramesEncoder {
public:
    // `group_counter` numbers the groups of every layer of the document: each group's clip paths and
    // gradients get ids of their own ("f12-tf-..."), since ids are unique per document.
    FramesEncoder(const char* layer_id, double fps, int decimals, std::size_t& group_counter);

    // The next frame's layer, written as the frames come.
    void add(const Layer& layer);

    // The layer's group with every frame's.
    std::string finish();

private:
    void flush(bool is_last);

    double fps_;
    int decimals_;
    std::size_t& groups_;
    std::string svg_;
    Layer run_;                   // the frame a run of equal frames shows
    std::vector<double> run_numbers_;  // and its numbers, as written
    std::vector<NumericAttribute> attributes_;  // reused for each frame
    std::vector<double> numbers_;
    std::size_t run_start_ = 0;
    std::size_t frames_ = 0;
};

}  // namespace talkface::detail

#endif
