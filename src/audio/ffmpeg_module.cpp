// libtalkface's side of the FFmpeg module (ffmpeg_module.hpp): finding and opening it, and
// open_ffmpeg_file forwarding to it.
#include "audio/ffmpeg_module.hpp"

#include <dlfcn.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/version.h"

namespace talkface::detail {

namespace {

// The file holding this code: libtalkface, or the program or Python module it is linked into
// statically.
std::filesystem::path this_library() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&this_library), &info) != 0 && info.dli_fname != nullptr &&
        std::strchr(info.dli_fname, '/') != nullptr) {
        return std::filesystem::absolute(info.dli_fname);
    }
    // The main program, which the loader names by argv[0].
    return std::filesystem::canonical("/proc/self/exe");
}

// The module's path: talkface/ beside the library (src/CMakeLists.txt puts it there in the build
// tree, in an install and in the Python package). A program linked with a static libtalkface is
// the file holding this code: talkface/ beside the program, else where the build that made the
// archive installs the module (its CMAKE_INSTALL_PREFIX, compiled in; `cmake --install --prefix`
// elsewhere cannot move a path compiled into the program).
std::string module_path() {
    const std::filesystem::path beside = (this_library().parent_path() / TALKFACE_FFMPEG_MODULE).lexically_normal();
#ifdef TALKFACE_STATIC_DEFINE
    if (!std::filesystem::exists(beside) && std::filesystem::exists(TALKFACE_INSTALLED_FFMPEG_MODULE))
        return TALKFACE_INSTALLED_FFMPEG_MODULE;
#endif
    return beside.string();
}

const FfmpegModuleCalls* open_module() {
    const std::string path = module_path();
    if (!std::filesystem::exists(path)) {
#ifdef TALKFACE_STATIC_DEFINE
        throw FileError(path, std::string("FFmpeg's module is missing (it reads MP3, M4A, Opus and a video's sound, "
                                          "and writes the pages' audio and videos); a program linked with the static "
                                          "libtalkface looks for it in talkface/ beside itself and at ") +
                                  TALKFACE_INSTALLED_FFMPEG_MODULE +
                                  ", where the build that made the library installs it; installed elsewhere "
                                  "(cmake --install --prefix), copy LIBDIR/talkface/ beside the program");
#else
        throw FileError(path, "FFmpeg's module is missing (it reads MP3, M4A, Opus and a video's sound, and writes "
                              "the pages' audio and videos); install talkface whole (cmake --install puts it in "
                              "LIBDIR/talkface/, beside the library)");
#endif
    }
    // Lazily bound, as libtalkface bound FFmpeg when it linked it: binding every call of FFmpeg's
    // 130-odd libraries now cost a page 14 M instructions more (FFmpeg's sonames carry its ABI).
    void* module = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    void* entry = module != nullptr ? dlsym(module, "talkface_ffmpeg_module_calls") : nullptr;
    if (entry == nullptr) {
        const char* reason = dlerror();
        throw FileError(path, "FFmpeg's module could not be loaded (" +
                                  std::string(reason != nullptr ? reason : "no entry point") +
                                  "); install FFmpeg's libraries (Debian 12: libavformat59, libavcodec59, "
                                  "libavutil57, libswscale6, libswresample4)");
    }
    const FfmpegModuleCalls* calls = reinterpret_cast<decltype(&talkface_ffmpeg_module_calls)>(entry)();
    if (std::strcmp(calls->version, TALKFACE_VERSION_STRING) != 0) {
        throw FileError(path, "is FFmpeg's module of talkface " + std::string(calls->version) + ", not of " +
                                  TALKFACE_VERSION_STRING + "; install talkface whole");
    }
    return calls;
}

}  // namespace

const FfmpegModuleCalls& ffmpeg_module_calls() {
    // Thread-safe, once; a failure throws and the next call tries again.
    static const FfmpegModuleCalls* const calls = open_module();
    return *calls;
}

std::unique_ptr<AudioSource> open_ffmpeg_file(const std::string& path, const FfmpegReading& reading) {
    return ffmpeg_module_calls().open_ffmpeg_file(path, reading);
}

bool ffmpeg_is_loadable() {
    try {
        ffmpeg_module_calls();
        return true;
    } catch (const FileError&) {
        return false;
    }
}

}  // namespace talkface::detail
