// talkface: errors thrown by the C++ API.
//
// Every message names what was wrong and where: a file with line and column, a point id, a FAPU,
// a parameter, a time. Each class maps to one tf_status of the C ABI and one Python exception.
#ifndef TALKFACE_ERRORS_HPP
#define TALKFACE_ERRORS_HPP

#include <stdexcept>
#include <string>

#include "talkface/export.h"

namespace talkface {
inline namespace v0 {

/// What kind of failure an Error is. The values equal the C ABI's tf_status and are never
/// renumbered within a major version.
enum class ErrorCode : int {
    invalid_argument = 1,  ///< a value or option the caller passed is out of range or malformed
    file = 2,              ///< a file could not be opened, read, written or renamed
    parse = 3,             ///< a file or string was read but its content is wrong
    alignment = 4,         ///< audio and transcript cannot be matched
    cancelled = 5,         ///< a progress callback asked to stop
    out_of_memory = 6,     ///< an allocation failed
    internal = 7,          ///< a bug in talkface: an invariant did not hold
};

/// Base of every exception talkface throws. what() is the full message.
/// Silence warning C4275 under Visual Studio: std::runtime_error is not exported, which is fine.
class TALKFACE_API Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::string& message);
    /// The kind of failure (maps to tf_status).
    ErrorCode code() const noexcept { return code_; }

private:
    ErrorCode code_;
};

/// A file could not be opened, read, written or renamed. what() names the path and the OS reason.
class TALKFACE_API FileError : public Error {
public:
    FileError(const std::string& path, const std::string& reason);
    /// The file that failed.
    const std::string& path() const noexcept { return path_; }

private:
    std::string path_;
};

/// A file or string was read but its content is wrong: "face.xml:12:5: point "8.3": ...".
/// line and column are 1-based; 0 where unknown (an empty file, say).
class TALKFACE_API ParseError : public Error {
public:
    ParseError(const std::string& path, int line, int column, const std::string& item,
               const std::string& problem);
    const std::string& path() const noexcept { return path_; }  ///< file, or "<string>"
    int line() const noexcept { return line_; }                  ///< 1-based, 0 if unknown
    int column() const noexcept { return column_; }              ///< 1-based, 0 if unknown
    const std::string& item() const noexcept { return item_; }  ///< e.g. point "8.3"; may be empty

private:
    std::string path_;
    int line_;
    int column_;
    std::string item_;
};

/// A value the caller passed is out of range or malformed. what() names the parameter.
class TALKFACE_API InvalidArgument : public Error {
public:
    InvalidArgument(const std::string& parameter, const std::string& problem);
    /// The parameter, option or item that was wrong (e.g. "beta_deg", "--pose", "MW0").
    const std::string& parameter() const noexcept { return parameter_; }

private:
    std::string parameter_;
};

/// Audio and transcript cannot be matched (a missing sentence, the wrong text, a text that lacks
/// its last words).
class TALKFACE_API AlignmentError : public Error {
public:
    explicit AlignmentError(const std::string& message);
};

/// A progress callback returned "stop"; nothing was written.
class TALKFACE_API Cancelled : public Error {
public:
    explicit Cancelled(const std::string& message);
};

/// what() of `error` and of every exception nested in it (std::throw_with_nested), outermost first,
/// one per line: the text the C ABI and Python report.
TALKFACE_API std::string full_message(const std::exception& error);

}  // namespace v0
}  // namespace talkface

#endif
