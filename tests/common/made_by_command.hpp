// Test files made by an outside program (ffmpeg, sox) into the test output folder.
#ifndef TALKFACE_TESTS_MADE_BY_COMMAND_HPP
#define TALKFACE_TESTS_MADE_BY_COMMAND_HPP

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

#include "common/test_paths.hpp"

namespace talkface::test {

// Runs `command_before_output` with a file name appended (quoted) as its output, and returns
// output_path(name). ctest runs one file's cases as parallel processes that may each make the same
// file: the command writes a name of this process's own and the finished file is renamed into
// place, so that no case reads a file another is still writing. The test fails with the command
// (shown) if it does not succeed.
inline std::string made_by_command(const std::string& name, const std::string& command_before_output) {
    const std::string path = output_path(name);
    const std::string partial = output_path(std::to_string(::getpid()) + "_partial_" + name);
    const std::string command = command_before_output + " '" + partial + "' 2>&1";
    INFO(command);
    REQUIRE(std::system(command.c_str()) == 0);
    REQUIRE(std::rename(partial.c_str(), path.c_str()) == 0);
    return path;
}

}  // namespace talkface::test

#endif
