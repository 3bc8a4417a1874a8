// Progress of a long rendering, reported through the caller's callback.
#ifndef TALKFACE_RENDER_PROGRESS_REPORT_HPP
#define TALKFACE_RENDER_PROGRESS_REPORT_HPP

#include <cstddef>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/svg_animator.hpp"

namespace talkface::detail {

// Reports `fraction` done at `stage`. \throws talkface::Cancelled, naming `frame`, if the callback
// returned false.
inline void report_progress(const ProgressCallback& progress, double fraction, const char* stage,
                            std::size_t frame) {
    if (progress && !progress(fraction, stage)) {
        throw Cancelled("rendering the animation was cancelled at frame " + std::to_string(frame));
    }
}

}  // namespace talkface::detail

#endif
