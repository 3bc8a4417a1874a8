#include "error_report.hpp"

#include <iostream>
#include <string>

#include <talkface/errors.hpp>

namespace talkface_cli {

namespace {

int exit_code_for(const std::exception& error) {
    const auto* talkface_error = dynamic_cast<const talkface::Error*>(&error);
    if (talkface_error == nullptr) return kExitInternal;
    return talkface_error->code() == talkface::ErrorCode::internal ? kExitInternal : kExitFailed;
}

// Each layer of a std::throw_with_nested chain on its own line, outermost first (as Rhubarb does).
void print_nested(const std::exception& error, int depth) {
    if (depth == 0) {
        std::cerr << "talkface: error: " << error.what() << '\n';
    } else {
        std::cerr << std::string(static_cast<std::size_t>(2 * depth), ' ') << error.what() << '\n';
    }
    try {
        std::rethrow_if_nested(error);
    } catch (const std::exception& inner) {
        print_nested(inner, depth + 1);
    } catch (...) {
        std::cerr << std::string(static_cast<std::size_t>(2 * depth + 2), ' ') << "unknown error\n";
    }
}

}  // namespace

const char* exit_code_help() {
    return "Exit codes:\n"
           "  0    success\n"
           "  1    the work failed (a file, a face file, a value out of range)\n"
           "  2    usage error (unknown option, malformed or missing argument)\n"
           "  3    internal error (a bug in talkface)\n"
           "  130  interrupted";
}

int report_error(const std::exception& error) {
    print_nested(error, 0);
    return exit_code_for(error);
}

void report_warnings(const talkface::Timeline& timeline) {
    for (const std::string& warning : timeline.warnings) std::cerr << "talkface: warning: " << warning << '\n';
}

}  // namespace talkface_cli
