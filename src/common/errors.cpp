#include "talkface/errors.hpp"

#include <exception>
#include <sstream>

namespace talkface {
inline namespace v0 {

namespace {

std::string parse_message(const std::string& path, int line, int column, const std::string& item,
                          const std::string& problem) {
    std::ostringstream out;
    out << path;
    if (line > 0) {
        out << ':' << line;
        if (column > 0) out << ':' << column;
    }
    out << ": ";
    if (!item.empty()) out << item << ": ";
    out << problem;
    return out.str();
}

}  // namespace

std::string full_message(const std::exception& error) {
    std::string message = error.what();
    try {
        std::rethrow_if_nested(error);
    } catch (const std::exception& nested) {
        message += '\n' + full_message(nested);
    } catch (...) {
        message += "\n(an exception that is not a std::exception)";
    }
    return message;
}

Error::Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}

FileError::FileError(const std::string& path, const std::string& reason)
    : Error(ErrorCode::file, path + ": " + reason), path_(path) {}

ParseError::ParseError(const std::string& path, int line, int column, const std::string& item,
                       const std::string& problem)
    : Error(ErrorCode::parse, parse_message(path, line, column, item, problem)),
      path_(path),
      line_(line),
      column_(column),
      item_(item) {}

InvalidArgument::InvalidArgument(const std::string& parameter, const std::string& problem)
    : Error(ErrorCode::invalid_argument, parameter + ": " + problem), parameter_(parameter) {}

AlignmentError::AlignmentError(const std::string& message) : Error(ErrorCode::alignment, message) {}

Cancelled::Cancelled(const std::string& message) : Error(ErrorCode::cancelled, message) {}

}  // namespace v0
}  // namespace talkface
