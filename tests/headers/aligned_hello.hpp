// What the headers' opening examples take as given: 你好。 with its syllables' times set as an
// aligner sets them (from 0.5 s, a quarter second each, in 1.5 s of sound), and the built-in face
// animated on it.
#ifndef TALKFACE_TESTS_HEADERS_ALIGNED_HELLO_HPP
#define TALKFACE_TESTS_HEADERS_ALIGNED_HELLO_HPP

#include <cstddef>

#include "talkface/animation.hpp"
#include "talkface/transcript.hpp"

inline talkface::Timeline aligned_hello() {
    talkface::Timeline timeline = talkface::read_transcript("你好。");
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        timeline.syllables[k].start_s = 0.5 + 0.25 * static_cast<double>(k);
        timeline.syllables[k].end_s = timeline.syllables[k].start_s + 0.25;
    }
    timeline.sentences.front().start_s = 0.5;
    timeline.sentences.front().end_s = timeline.syllables.back().end_s;
    timeline.duration_s = 1.5;
    return timeline;
}

struct AnimatedHello {
    talkface::FaceModel face;
    talkface::Timeline timeline;
    talkface::Animation animation;
};

inline AnimatedHello animated_hello() {
    AnimatedHello hello{talkface::FaceModel::default_face(), aligned_hello(), {}};
    hello.animation =
        talkface::animate(hello.face, hello.timeline, talkface::ExpressionSimulator(hello.timeline, 7));
    return hello;
}

#endif
