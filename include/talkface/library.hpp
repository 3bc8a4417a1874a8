// talkface: facts about the loaded library.
#ifndef TALKFACE_LIBRARY_HPP
#define TALKFACE_LIBRARY_HPP

#include "talkface/export.h"
#include "talkface/version.h"

namespace talkface {
inline namespace v0 {

/// The version of the library that is loaded, "MAJOR.MINOR.PATCH"; compare with
/// TALKFACE_VERSION_STRING, the version of the headers a program was built with.
TALKFACE_API const char* version() noexcept;

}  // namespace v0
}  // namespace talkface

#endif
