// What `talkface animate` and `talkface demo` say when they are done: the file written, what it
// holds, how long and how large ("talkface: wrote talk.html: web page, 7.42 s, 412.3 kB"). On stderr,
// as Rhubarb and the rest of this command write everything that is not a result (stdout carries
// results only, `-o -`); --quiet keeps it silent.
#ifndef TALKFACE_CLI_WRITTEN_REPORT_HPP
#define TALKFACE_CLI_WRITTEN_REPORT_HPP

#include <optional>
#include <ostream>
#include <string>

namespace talkface_cli {

// "412.3 kB": a file size in bytes with decimal units (B, kB, MB, GB), one decimal above bytes.
std::string format_file_size(unsigned long long bytes);

// Writes "talkface: wrote PATH: WHAT[, DURATION s], SIZE\n" to `out` for the file now at `path`.
void report_written(std::ostream& out, const std::string& path, const std::string& what,
                    std::optional<double> duration_s);

}  // namespace talkface_cli

#endif
