#include "talkface/library.hpp"

namespace talkface {
inline namespace v0 {

const char* version() noexcept { return TALKFACE_VERSION_STRING; }

}  // namespace v0
}  // namespace talkface
