// Where tests find the source tree's files (samples/, tests/data/) and write their outputs.
#ifndef TALKFACE_TESTS_TEST_PATHS_HPP
#define TALKFACE_TESTS_TEST_PATHS_HPP

#include <string>

namespace talkface::test {

inline std::string source_path(const std::string& relative) {
    return std::string(TALKFACE_SOURCE_DIR) + "/" + relative;
}

inline std::string output_path(const std::string& name) {
    return std::string(TALKFACE_TEST_OUTPUT_DIR) + "/" + name;
}

}  // namespace talkface::test

#endif
