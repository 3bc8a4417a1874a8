#include "text/web_addresses.hpp"

#include <algorithm>
#include <string_view>

namespace talkface::detail {

namespace {

bool is_alphanumeric(char32_t c) {
    return is_ascii_letter(c) || is_ascii_digit(c);
}

// The code point at text[i] as written, 0 past the end. Not written_number_scan.hpp's value_at, which
// reads a full-width form as its ASCII one: an address is typed in ASCII and its labels are built from
// these very code points, so a full-width letter or dot ends it.
char32_t written_at(const std::vector<CodePoint>& text, std::size_t i) {
    return i < text.size() ? text[i].value : 0;
}

// Top-level domains common enough that a host ending in one is an address without www or a scheme
// (gov.cn, example.com); a rarer one needs either (www.example.museum).
bool is_common_top_level(const std::string& label) {
    constexpr std::string_view kDomains[] = {"com", "net", "org", "cn", "edu", "gov", "io",  "info", "biz", "mil",
                                             "tw",  "hk",  "mo",  "sg", "uk",  "jp",  "kr",  "us",   "de",  "fr",
                                             "me",  "tv",  "cc",  "co", "top", "xyz", "app", "dev",  "ai"};
    const auto lower = ascii_lower_case(label);
    return std::find(std::begin(kDomains), std::end(kDomains), lower) != std::end(kDomains);
}

// Suffixes that make a dotted name a file's or a software library's name (index.html, Node.js,
// Vue.js, setup.exe): read as an address is, the dot 点, not the end of a sentence.
bool is_file_suffix(const std::string& label) {
    constexpr std::string_view kSuffixes[] = {"js", "ts", "py", "html", "htm", "css", "json", "xml", "txt", "pdf",
                                              "doc", "docx", "xls", "xlsx", "ppt", "pptx", "jpg", "jpeg", "png", "gif",
                                              "wav", "mov", "exe", "zip", "md", "cpp", "java", "php", "yaml", "yml"};
    const auto lower = ascii_lower_case(label);
    return std::find(std::begin(kSuffixes), std::end(kSuffixes), lower) != std::end(kSuffixes);
}

// A host at text[start]: labels of letters, digits and inner hyphens joined by dots. Returns its
// end and its labels; the labels are empty if there is none. A dot not followed by a label is not
// the host's (it ends the sentence).
std::size_t host_end(const std::vector<CodePoint>& text, std::size_t start, std::vector<std::string>& labels) {
    labels.clear();
    auto i = start;
    while (is_alphanumeric(written_at(text, i))) {
        std::string label;
        while (is_alphanumeric(written_at(text, i)) ||
               (written_at(text, i) == '-' && is_alphanumeric(written_at(text, i + 1)) && !label.empty())) {
            label += static_cast<char>(text[i++].value);
        }
        labels.push_back(std::move(label));
        if (written_at(text, i) != '.' || !is_alphanumeric(written_at(text, i + 1))) break;
        ++i;
    }
    return i;
}

bool is_all_letters(const std::string& label) {
    return !label.empty() && std::all_of(label.begin(), label.end(), [](char c) { return is_ascii_letter(c); });
}

// A path after a host (/news/2026.html): slashes and what is between them, up to a character an
// address does not hold or a dot that ends the sentence.
std::size_t path_end(const std::vector<CodePoint>& text, std::size_t i) {
    if (written_at(text, i) != '/') return i;
    auto end = i;
    for (auto k = i; k < text.size(); ++k) {
        const auto c = text[k].value;
        if (is_alphanumeric(c) || c == '/') {
            end = k + 1;
        } else if (!(c == '.' || c == '-' || c == '_')) {
            break;
        }
    }
    return end;
}

}  // namespace

bool is_exchange_suffix(std::string_view letters) {
    for (const std::string_view suffix : {"HK", "SH", "SS", "SZ", "BJ", "TW", "TWO"})
        if (letters == suffix) return true;
    return false;
}

void append_address_parts(std::vector<AddressPart>& parts, const std::vector<CodePoint>& text,
                          std::size_t first, std::size_t end) {
    for (auto i = first; i < end;) {
        const auto c = text[i].value;
        if (is_alphanumeric(c)) {
            const bool letters = is_ascii_letter(c);
            std::string run;
            while (i < end && (letters ? is_ascii_letter(text[i].value) : is_ascii_digit(text[i].value)))
                run += static_cast<char>(text[i++].value);
            parts.push_back(
                {letters ? AddressPart::Kind::letters : AddressPart::Kind::digits, std::move(run)});
            continue;
        }
        const char* words = c == '.'   ? "点"
                            : c == '@' ? "艾特"
                            : c == '-' ? "杠"
                            : c == '_' ? "下划线"
                            : c == '/' ? "斜杠"
                                       : "加";
        parts.push_back({AddressPart::Kind::words, words});
        ++i;
    }
}

std::optional<WebAddress> read_web_address(const std::vector<CodePoint>& text, std::size_t start) {
    if (start >= text.size()) return std::nullopt;
    const auto previous = start == 0 ? 0 : text[start - 1].value;
    if (text[start].value == '@') {
        // A mention names someone right after the @ (@新华社, @Tom): a letter, digit or character.
        const auto next = written_at(text, start + 1);
        if (is_alphanumeric(previous) || !(is_alphanumeric(next) || next >= 0x2E80)) return std::nullopt;
        return WebAddress{start + 1, {{AddressPart::Kind::words, "艾特"}}};
    }
    if (!is_alphanumeric(text[start].value) || is_alphanumeric(previous) || previous == '.' || previous == '@' ||
        previous == '_' || previous == '-') {
        return std::nullopt;
    }
    std::vector<std::string> labels;
    WebAddress address;

    // An e-mail address: a name of letters, digits and . _ - +, then @ and a host.
    auto at = start;
    while (is_alphanumeric(written_at(text, at)) || written_at(text, at) == '_' ||
           written_at(text, at) == '+' ||
           ((written_at(text, at) == '.' || written_at(text, at) == '-') &&
            is_alphanumeric(written_at(text, at + 1)))) {
        ++at;
    }
    if (written_at(text, at) == '@') {
        const auto end = host_end(text, at + 1, labels);
        if (labels.size() >= 2 && is_all_letters(labels.back())) {
            append_address_parts(address.parts, text, start, end);
            address.end = end;
            return address;
        }
    }

    // A scheme, not said: https://, http://, ftp://.
    auto host = start;
    std::string scheme;
    for (auto k = start; is_ascii_letter(written_at(text, k)); ++k)
        scheme += static_cast<char>(text[k].value);
    scheme = ascii_lower_case(scheme);
    const bool has_scheme = (scheme == "http" || scheme == "https" || scheme == "ftp") &&
                            written_at(text, start + scheme.size()) == ':' &&
                            written_at(text, start + scheme.size() + 1) == '/' &&
                            written_at(text, start + scheme.size() + 2) == '/';
    if (has_scheme) host = start + scheme.size() + 3;
    const auto end = host_end(text, host, labels);
    if (labels.size() < 2 || !is_all_letters(labels.back())) return std::nullopt;
    // A stock's code and its exchange (00700.HK, 600519.SH, 2330.TW) is no address: the number reader
    // says the code and leaves the suffix unsaid (session 15: it was read as an address, 零零七零零点 H K).
    const auto is_digits = [](const std::string& label) {
        return std::all_of(label.begin(), label.end(), [](char c) { return is_ascii_digit(c); });
    };
    if (!has_scheme && labels.size() == 2 && is_digits(labels.front()) && is_exchange_suffix(labels.back()))
        return std::nullopt;
    if (!has_scheme && ascii_lower_case(labels.front()) != "www" && !is_common_top_level(labels.back()) &&
        !is_file_suffix(labels.back())) {
        return std::nullopt;
    }
    const auto address_end = path_end(text, end);
    append_address_parts(address.parts, text, host, address_end);
    address.end = address_end;
    return address;
}

}  // namespace talkface::detail
