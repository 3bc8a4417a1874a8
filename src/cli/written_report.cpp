#include "written_report.hpp"

#include <array>
#include <cstdio>
#include <filesystem>

namespace talkface_cli {

std::string format_file_size(unsigned long long bytes) {
    if (bytes < 1000) return std::to_string(bytes) + " B";
    static const std::array<const char*, 3> kUnits = {"kB", "MB", "GB"};
    double value = static_cast<double>(bytes) / 1000.0;
    std::size_t unit = 0;
    while (value >= 999.95 && unit + 1 < kUnits.size()) {
        value /= 1000.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
    return text;
}

void report_written(std::ostream& out, const std::string& path, const std::string& what,
                    std::optional<double> duration_s) {
    out << "talkface: wrote " << path << ": " << what;
    if (duration_s) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%.2f s", *duration_s);
        out << ", " << seconds;
    }
    out << ", " << format_file_size(std::filesystem::file_size(path)) << '\n';
}

}  // namespace talkface_cli
