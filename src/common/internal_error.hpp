// The error for a broken invariant of talkface itself, not of the caller's input: every stage words it
// the same way, so that a user knows to report it.
#pragma once

#include <string>

#include "talkface/errors.hpp"

namespace talkface::detail {

inline Error internal_error(const std::string& what) {
    return Error(ErrorCode::internal, "internal error (a bug in talkface): " + what);
}

}  // namespace talkface::detail
