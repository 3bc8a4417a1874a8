// The one place the C ABI turns C++ outcomes into tf_status: every tf_ body runs inside guard().
#ifndef TALKFACE_CAPI_C_API_GUARD_HPP
#define TALKFACE_CAPI_C_API_GUARD_HPP

#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "talkface/errors.hpp"
#include "talkface/talkface.h"

namespace talkface::capi {

// This thread's last error message (tf_last_error_message). Exported (version TALKFACE_C_PRIVATE,
// not API) for the photo calls, which libtalkface_photo compiles (talkface_c.map).
TF_API std::string& last_error();

// Runs `body` (which returns void); returns TF_OK, or records the message and returns the status of
// the exception it threw. Never lets an exception out.
template <typename Body>
tf_status guard(Body&& body) noexcept {
    try {
        last_error().clear();
        body();
        return TF_OK;
    } catch (const talkface::Error& error) {
        last_error() = talkface::full_message(error);
        return static_cast<tf_status>(error.code());
    } catch (const std::bad_alloc&) {
        last_error() = "out of memory";
        return TF_ERR_OUT_OF_MEMORY;
    } catch (const std::exception& error) {
        last_error() = "internal error (a bug in talkface): " + talkface::full_message(error);
        return TF_ERR_INTERNAL;
    } catch (...) {
        last_error() = "internal error (a bug in talkface): unknown exception";
        return TF_ERR_INTERNAL;
    }
}

// Throws InvalidArgument naming `parameter` if `pointer` is NULL.
template <typename T>
void require_non_null(const T* pointer, const char* parameter) {
    if (pointer == nullptr) throw talkface::InvalidArgument(parameter, "must not be NULL");
}

// The int a C caller passed for a C enum parameter. C allows any int there, but in C++ reading an
// enum object outside its enumerators' range is undefined (UBSan: "load of value 42, which is not a
// valid value for type"), so the bytes are copied, never read as the enum.
template <typename Enum>
int enum_value(const Enum& value) {
    static_assert(sizeof(Enum) == sizeof(int), "C enums are int-sized on the platforms we build for");
    int result = 0;
    std::memcpy(&result, &value, sizeof result);
    return result;
}

// A malloc'd NUL-terminated copy of `text` for a (char **out, size_t *out_len) pair; tf_free frees it.
void give_document(std::string_view text, char** out, size_t* out_len);

}  // namespace talkface::capi

#endif
