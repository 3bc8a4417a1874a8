// Status names, the thread-local last error, version and tf_free.
#include <cstdlib>
#include <exception>
#include <iterator>

#include "c_api_guard.hpp"
#include "talkface/library.hpp"

namespace talkface::capi {

std::string& last_error() {
    thread_local std::string message;
    return message;
}


void give_document(std::string_view text, char** out, size_t* out_len) {
    auto* copy = static_cast<char*>(std::malloc(text.size() + 1));
    if (copy == nullptr) throw std::bad_alloc();
    std::memcpy(copy, text.data(), text.size());
    copy[text.size()] = '\0';
    *out = copy;
    if (out_len != nullptr) *out_len = text.size();
}

}  // namespace talkface::capi

extern "C" {

const char* tf_status_name(tf_status status) {
    static const char* const kNames[] = {"TF_OK",
                                         "TF_ERR_INVALID_ARGUMENT",
                                         "TF_ERR_FILE",
                                         "TF_ERR_PARSE",
                                         "TF_ERR_ALIGNMENT",
                                         "TF_ERR_CANCELLED",
                                         "TF_ERR_OUT_OF_MEMORY",
                                         "TF_ERR_INTERNAL"};
    const int value = talkface::capi::enum_value(status);
    if (value < 0 || value >= static_cast<int>(std::size(kNames))) return "TF_ERR_UNKNOWN";
    return kNames[value];
}

const char* tf_last_error_message(void) {
    return talkface::capi::last_error().c_str();
}

const char* tf_version(void) {
    return talkface::version();
}

void tf_free(void* document) {
    std::free(document);
}

}  // extern "C"
