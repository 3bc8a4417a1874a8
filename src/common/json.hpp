// A small strict JSON (RFC 8259) reader that remembers where every value and key starts, so that a
// codec can name the line and column of a wrong item, not only of a syntax error; and the two
// pieces every JSON writer here needs (a quoted string, a number). The library's JSON formats (the
// style file, the timeline, the timing imports and exports) all read and write through this.
#ifndef TALKFACE_COMMON_JSON_HPP
#define TALKFACE_COMMON_JSON_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace talkface::detail {

struct JsonValue {
    enum class Type { null, boolean, number, string, array, object };
    Type type = Type::null;
    std::size_t offset = 0;  // where the value starts in the text, for line:column
    bool boolean = false;
    double number = 0.0;
    std::string text;
    std::vector<JsonValue> items;
    std::vector<std::pair<std::string, JsonValue>> members;  // in the order of the text
    std::vector<std::size_t> key_offsets;                    // one per member

    // The member named `key` of an object, or nullptr (also when this is not an object).
    const JsonValue* find(std::string_view key) const;
};

// Reads one document; fail() turns an offset of it into "source:line:column: item: problem".
// Keeps a view of `text`: the text must outlive the reader.
class JsonReader {
public:
    JsonReader(std::string_view text, std::string source);

    // The whole text as one value. Throws ParseError naming line:column at the first fault.
    JsonValue read_document();

    // Throws ParseError at `offset` of the text, naming the item (may be empty) and the problem.
    [[noreturn]] void fail(std::size_t offset, const std::string& item, const std::string& problem) const;

    const std::string& source() const { return source_; }

private:
    void skip_space();
    bool consume(std::string_view word);
    void expect(char c, const char* context);
    JsonValue read_value(int depth);
    void read_object(JsonValue& value, int depth);
    void read_array(JsonValue& value, int depth);
    double read_number();
    unsigned read_hex4();
    std::string read_string();

    std::string_view text_;
    std::string source_;
    std::size_t position_ = 0;
};

// What a message says was found: the value itself where it is short, else its type.
std::string json_found(const JsonValue& value);

// `text` as a JSON string: quotes and backslashes escaped, control characters as \u00XX, other
// UTF-8 passed through so that readers see the characters, not \u escapes.
std::string json_quoted(std::string_view text);

// A finite number in its shortest round-trip form ("0.5", "12", "1e-07"), whatever the C locale.
std::string json_number(double value);

}  // namespace talkface::detail

#endif
