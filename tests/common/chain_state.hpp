// One state of a phone chain as the HSMM tests build their chains by hand (hsmm_test,
// alignment_confidence_test): a log-normal duration prior of spread 0.4 around `median_frames`.
#ifndef TALKFACE_TESTS_CHAIN_STATE_HPP
#define TALKFACE_TESTS_CHAIN_STATE_HPP

#include <cstddef>

#include "speech/phone_chain.hpp"

namespace talkface::test {

inline detail::PhoneState chain_state(detail::PhoneClass phone_class, detail::StateRole role, std::size_t syllable,
                                      double median_frames, std::size_t max_frames, bool is_optional) {
    detail::PhoneState state;
    state.phone_class = phone_class;
    state.role = role;
    state.syllable = syllable;
    state.median_frames = median_frames;
    state.log_sigma = 0.4;
    state.max_frames = max_frames;
    state.is_optional = is_optional;
    return state;
}

}  // namespace talkface::test

#endif
