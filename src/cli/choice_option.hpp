// Options whose value is one of a few names, kept as the enum the library names them by: CLI11
// checks the name and converts it once, while parsing, so a bad value is a usage error (exit 2)
// that lists the choices, and no command parses the name again.
#ifndef TALKFACE_CLI_CHOICE_OPTION_HPP
#define TALKFACE_CLI_CHOICE_OPTION_HPP

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace talkface_cli {

// A transformer for an option bound to an Enum: each of `values` is accepted by its name
// (name_of, the library's own, e.g. talkface::face_look_name) and handed on as the enum's number,
// which CLI11 reads into the Enum. Its description, shown in --help, lists the names.
template <class Enum>
CLI::Validator choice_of(std::vector<Enum> values, const char* (*name_of)(Enum)) {
    std::vector<std::pair<std::string, Enum>> choices;
    std::string listed;
    for (std::size_t k = 0; k < values.size(); ++k) {
        choices.emplace_back(name_of(values[k]), values[k]);
        listed += (k == 0 ? "" : k + 1 == values.size() ? " or " : ", ") + choices.back().first;
    }
    std::string described = "{";
    for (const auto& choice : choices) described += (described.size() > 1 ? "," : "") + choice.first;
    return CLI::Validator(
        [choices, listed](std::string& input) -> std::string {
            for (const auto& [name, value] : choices) {
                if (input == name) {
                    input = std::to_string(static_cast<int>(value));
                    return {};
                }
            }
            return "expected " + listed + ", found \"" + input + "\"";
        },
        described + "}");
}

}  // namespace talkface_cli

#endif
