#include "talkface/face_look.hpp"

#include <string>

#include "render/layers.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

const char* face_look_name(FaceLook look) {
    switch (look) {
        case FaceLook::outlined: return "outlined";
        case FaceLook::flat: return "flat";
    }
    return "unknown";
}

FaceLook face_look_from_name(std::string_view name) {
    if (name == "outlined") return FaceLook::outlined;
    if (name == "flat") return FaceLook::flat;
    throw InvalidArgument("look", "expected outlined or flat, found \"" + std::string(name) + "\"");
}

}  // namespace v0

void detail::check_face_look(FaceLook look) {
    if (look != FaceLook::outlined && look != FaceLook::flat) {
        throw InvalidArgument("look", "expected FaceLook::outlined or FaceLook::flat, found " +
                                          std::to_string(static_cast<int>(look)));
    }
}

}  // namespace talkface
