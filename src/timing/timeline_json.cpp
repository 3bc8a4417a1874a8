// The timeline JSON (include/talkface/timeline_json.hpp): every field of Sentence and Syllable
// written and read from one table per item, so that a field added to timeline.hpp is one row here.
#include "talkface/timeline_json.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/json.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using detail::json_found;
using detail::json_number;
using detail::json_quoted;
using detail::JsonReader;
using detail::JsonValue;

// Reads the values of one item ("syllables[3]"), naming the item and the value's line in messages.
class ItemReader {
public:
    ItemReader(const JsonReader& json, std::string item, std::size_t sentence_count)
        : json_(json), item_(std::move(item)), sentence_count_(sentence_count) {}

    [[noreturn]] void fail(const JsonValue& value, const char* key, const std::string& problem) const {
        json_.fail(value.offset, item_ + "." + key, problem);
    }

    std::string text(const JsonValue& value, const char* key) const {
        if (value.type != JsonValue::Type::string) fail(value, key, "expected a string, found " + json_found(value));
        return value.text;
    }

    double seconds(const JsonValue& value, const char* key) const {
        if (value.type != JsonValue::Type::number) {
            fail(value, key, "expected a number of seconds, found " + json_found(value));
        }
        if (value.number < 0.0) fail(value, key, "expected seconds >= 0, found " + json_found(value));
        return value.number;
    }

    double fraction(const JsonValue& value, const char* key) const {
        if (value.type != JsonValue::Type::number || value.number < 0.0 || value.number > 1.0) {
            fail(value, key, "expected a number 0..1, found " + json_found(value));
        }
        return value.number;
    }

    std::vector<double> fractions(const JsonValue& value, const char* key) const {
        if (value.type != JsonValue::Type::array) fail(value, key, "expected a list of numbers 0..1, found " + json_found(value));
        std::vector<double> numbers;
        for (const JsonValue& item : value.items) numbers.push_back(fraction(item, key));
        return numbers;
    }

    bool flag(const JsonValue& value, const char* key) const {
        if (value.type != JsonValue::Type::boolean) fail(value, key, "expected true or false, found " + json_found(value));
        return value.boolean;
    }

    std::size_t count(const JsonValue& value, const char* key, std::size_t lowest) const {
        if (value.type != JsonValue::Type::number || value.number < static_cast<double>(lowest) ||
            value.number != std::floor(value.number) || value.number > 1e15) {
            fail(value, key, "expected a whole number >= " + std::to_string(lowest) + ", found " + json_found(value));
        }
        return static_cast<std::size_t>(value.number);
    }

    std::size_t sentence_index(const JsonValue& value, const char* key) const {
        if (value.type != JsonValue::Type::number || value.number < 0.0 || value.number != std::floor(value.number) ||
            value.number >= static_cast<double>(sentence_count_)) {
            fail(value, key,
                 "expected a sentence index 0.." + std::to_string(static_cast<long>(sentence_count_) - 1) +
                     ", found " + json_found(value));
        }
        return static_cast<std::size_t>(value.number);
    }

private:
    const JsonReader& json_;
    std::string item_;
    std::size_t sentence_count_;
};

// One key of an item. write gives the value's JSON text, or nothing to leave the key out (a final
// start not measured); read sets the field from the value. Rows are in the order keys are written:
// the SPEC "Contracts" keys first, in the contract's order.
template <typename Item>
struct Field {
    const char* key;
    bool is_required;  // a document without it is refused; otherwise the field keeps its default
    bool is_measured;  // a time or an aligner's figure: left out by TimelineJsonOptions::with_times = false
    std::optional<std::string> (*write)(const Item&);
    void (*read)(const ItemReader&, const JsonValue&, Item&);
};

const std::vector<Field<Sentence>>& sentence_fields() {
    static const std::vector<Field<Sentence>> fields = {
        {"text", true, false, [](const Sentence& s) -> std::optional<std::string> { return json_quoted(s.text); },
         [](const ItemReader& r, const JsonValue& v, Sentence& s) { s.text = r.text(v, "text"); }},
        {"start", false, true,
         [](const Sentence& s) -> std::optional<std::string> { return json_number(s.start_s); },
         [](const ItemReader& r, const JsonValue& v, Sentence& s) { s.start_s = r.seconds(v, "start"); }},
        {"end", false, true, [](const Sentence& s) -> std::optional<std::string> { return json_number(s.end_s); },
         [](const ItemReader& r, const JsonValue& v, Sentence& s) { s.end_s = r.seconds(v, "end"); }},
        // Written only where a paragraph begins (issue 17), so documents without paragraphs keep
        // their bytes.
        {"paragraph", false, false,
         [](const Sentence& s) -> std::optional<std::string> {
             return s.starts_paragraph ? std::optional<std::string>("true") : std::nullopt;
         },
         [](const ItemReader& r, const JsonValue& v, Sentence& s) { s.starts_paragraph = r.flag(v, "paragraph"); }},
    };
    return fields;
}

const std::vector<Field<Syllable>>& syllable_fields() {
    static const std::vector<Field<Syllable>> fields = {
        {"text", true, false, [](const Syllable& s) -> std::optional<std::string> { return json_quoted(s.text); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.text = r.text(v, "text"); }},
        {"pinyin", true, false,
         [](const Syllable& s) -> std::optional<std::string> { return json_quoted(s.pinyin); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.pinyin = r.text(v, "pinyin"); }},
        {"start", false, true,
         [](const Syllable& s) -> std::optional<std::string> { return json_number(s.start_s); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.start_s = r.seconds(v, "start"); }},
        {"end", false, true, [](const Syllable& s) -> std::optional<std::string> { return json_number(s.end_s); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.end_s = r.seconds(v, "end"); }},
        {"sentence", true, false,
         [](const Syllable& s) -> std::optional<std::string> { return std::to_string(s.sentence); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.sentence = r.sentence_index(v, "sentence"); }},
        {"final_start", false, true,
         [](const Syllable& s) -> std::optional<std::string> {
             if (!s.final_start_s) return std::nullopt;
             return json_number(*s.final_start_s);
         },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) {
             // null is what a reader of an older document may have written for "not measured"
             if (v.type == JsonValue::Type::null) s.final_start_s.reset();
             else s.final_start_s = r.seconds(v, "final_start");
         }},
        {"confidence", false, true,
         [](const Syllable& s) -> std::optional<std::string> { return json_number(s.confidence); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.confidence = r.fraction(v, "confidence"); }},
        {"pause_after", false, false,
         [](const Syllable& s) -> std::optional<std::string> { return std::string(s.pause_after ? "true" : "false"); },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.pause_after = r.flag(v, "pause_after"); }},
        // Written only for a syllable of a word no table reads (issue 13), so other documents keep
        // their bytes.
        {"generic_speech", false, false,
         [](const Syllable& s) -> std::optional<std::string> {
             return s.generic_speech ? std::optional<std::string>("true") : std::nullopt;
         },
         [](const ItemReader& r, const JsonValue& v, Syllable& s) { s.generic_speech = r.flag(v, "generic_speech"); }},
    };
    return fields;
}

// A written form read by rule (a number, letters, an English word) and its syllables (issue 13).
const std::vector<Field<WrittenForm>>& written_form_fields() {
    static const std::vector<Field<WrittenForm>> fields = {
        {"text", true, false, [](const WrittenForm& f) -> std::optional<std::string> { return json_quoted(f.text); },
         [](const ItemReader& r, const JsonValue& v, WrittenForm& f) { f.text = r.text(v, "text"); }},
        {"first_syllable", true, false,
         [](const WrittenForm& f) -> std::optional<std::string> { return std::to_string(f.first_syllable); },
         [](const ItemReader& r, const JsonValue& v, WrittenForm& f) {
             f.first_syllable = r.count(v, "first_syllable", 0);
         }},
        {"syllable_count", true, false,
         [](const WrittenForm& f) -> std::optional<std::string> { return std::to_string(f.syllable_count); },
         [](const ItemReader& r, const JsonValue& v, WrittenForm& f) {
             f.syllable_count = r.count(v, "syllable_count", 1);
         }},
    };
    return fields;
}

// A stretch where the speech does not say the text, from lenient alignment (issue 13).
const std::vector<Field<TextMismatch>>& mismatch_fields() {
    static const std::vector<Field<TextMismatch>> fields = {
        {"start", true, true, [](const TextMismatch& m) -> std::optional<std::string> { return json_number(m.start_s); },
         [](const ItemReader& r, const JsonValue& v, TextMismatch& m) { m.start_s = r.seconds(v, "start"); }},
        {"end", true, true, [](const TextMismatch& m) -> std::optional<std::string> { return json_number(m.end_s); },
         [](const ItemReader& r, const JsonValue& v, TextMismatch& m) { m.end_s = r.seconds(v, "end"); }},
        {"first_syllable", true, false,
         [](const TextMismatch& m) -> std::optional<std::string> { return std::to_string(m.first_syllable); },
         [](const ItemReader& r, const JsonValue& v, TextMismatch& m) {
             m.first_syllable = r.count(v, "first_syllable", 0);
         }},
        {"syllable_count", true, false,
         [](const TextMismatch& m) -> std::optional<std::string> { return std::to_string(m.syllable_count); },
         [](const ItemReader& r, const JsonValue& v, TextMismatch& m) {
             m.syllable_count = r.count(v, "syllable_count", 0);
         }},
        {"expected", true, false,
         [](const TextMismatch& m) -> std::optional<std::string> { return json_quoted(m.expected_text); },
         [](const ItemReader& r, const JsonValue& v, TextMismatch& m) { m.expected_text = r.text(v, "expected"); }},
        // Written only where measured, so that documents of other sources keep their bytes.
        {"loudness", false, true,
         [](const TextMismatch& m) -> std::optional<std::string> {
             if (m.loudness.empty()) return std::nullopt;
             std::string json = "[";
             for (const double value : m.loudness) json += (json.size() > 1 ? "," : "") + json_number(value);
             return json + "]";
         },
         [](const ItemReader& r, const JsonValue& v, TextMismatch& m) { m.loudness = r.fractions(v, "loudness"); }},
    };
    return fields;
}

template <typename Item>
std::string item_json(const Item& item, const std::vector<Field<Item>>& fields, const TimelineJsonOptions& options) {
    std::string json = "{";
    for (const Field<Item>& field : fields) {
        if (field.is_measured && !options.with_times) continue;
        const std::optional<std::string> value = field.write(item);
        if (!value) continue;
        if (json.size() > 1) json += ',';
        json += json_quoted(field.key) + ":" + *value;
    }
    return json + "}";
}

// "[\n{...},\n{...}\n]": one item per line, so that a diff of two documents reads item by item.
std::string list_json(const std::vector<std::string>& items) {
    if (items.empty()) return "[]";
    std::string json = "[";
    for (std::size_t k = 0; k < items.size(); ++k) json += (k == 0 ? "\n" : ",\n") + items[k];
    return json + "\n]";
}

const JsonValue& member(const JsonReader& json, const JsonValue& object, const char* key, const std::string& item) {
    const JsonValue* value = object.find(key);
    if (value == nullptr) json.fail(object.offset, item, "\"" + std::string(key) + "\" is missing");
    return *value;
}

const JsonValue& list(const JsonReader& json, const JsonValue& value, const std::string& item) {
    if (value.type != JsonValue::Type::array) json.fail(value.offset, item, "expected a list, found " + json_found(value));
    return value;
}

template <typename Item>
Item read_item(const JsonReader& json, const JsonValue& value, const std::string& item,
               const std::vector<Field<Item>>& fields, std::size_t sentence_count) {
    if (value.type != JsonValue::Type::object) {
        json.fail(value.offset, item, "expected an object, found " + json_found(value));
    }
    const ItemReader reader(json, item, sentence_count);
    Item result;
    for (const Field<Item>& field : fields) {
        const JsonValue* found = value.find(field.key);
        if (found != nullptr) field.read(reader, *found, result);
        else if (field.is_required) json.fail(value.offset, item, "\"" + std::string(field.key) + "\" is missing");
    }
    if constexpr (!std::is_same_v<Item, WrittenForm>) {
        if (result.end_s < result.start_s) {
            json.fail(value.offset, item,
                      "ends at " + json_number(result.end_s) + " s, before it starts (" +
                          json_number(result.start_s) + " s)");
        }
    }
    return result;
}

int read_version(const JsonReader& json, const JsonValue& document) {
    const JsonValue* version = document.find("version");
    if (version == nullptr) return 1;
    if (version->type != JsonValue::Type::number || version->number != std::floor(version->number) ||
        version->number < 1) {
        json.fail(version->offset, "version", "expected a whole number >= 1, found " + json_found(*version));
    }
    if (version->number > kTimelineJsonVersion) {
        json.fail(version->offset, "version",
                  "timeline JSON version " + json_found(*version) + " is newer than this talkface reads (version " +
                      std::to_string(kTimelineJsonVersion) + "); update talkface to read it");
    }
    return static_cast<int>(version->number);
}

}  // namespace

std::string timeline_to_json(const Timeline& timeline, const TimelineJsonOptions& options) {
    std::vector<std::string> sentences;
    for (const Sentence& sentence : timeline.sentences) sentences.push_back(item_json(sentence, sentence_fields(), options));
    std::vector<std::string> syllables;
    for (const Syllable& syllable : timeline.syllables) syllables.push_back(item_json(syllable, syllable_fields(), options));
    std::vector<std::string> written_forms;
    for (const WrittenForm& form : timeline.written_forms) {
        written_forms.push_back(item_json(form, written_form_fields(), options));
    }
    // Found by the aligner: a document without times has none.
    std::vector<std::string> mismatches;
    if (options.with_times)
        for (const TextMismatch& mismatch : timeline.mismatches) mismatches.push_back(item_json(mismatch, mismatch_fields(), options));
    std::vector<std::string> warnings;
    for (const std::string& warning : timeline.warnings) warnings.push_back(json_quoted(warning));
    std::string json = "{\"version\":" + std::to_string(kTimelineJsonVersion) + ",\n";
    json += "\"sentences\":" + list_json(sentences) + ",\n";
    json += "\"syllables\":" + list_json(syllables) + ",\n";
    if (!written_forms.empty()) json += "\"written_forms\":" + list_json(written_forms) + ",\n";
    if (!mismatches.empty()) json += "\"mismatches\":" + list_json(mismatches) + ",\n";
    if (options.with_times) json += "\"duration\":" + json_number(timeline.duration_s) + ",\n";
    json += "\"warnings\":" + list_json(warnings) + "}\n";
    return json;
}

Timeline timeline_from_json(std::string_view utf8_text, const std::string& source_name) {
    JsonReader json(utf8_text, source_name);
    const JsonValue document = json.read_document();
    if (document.type != JsonValue::Type::object) {
        json.fail(document.offset, "document", "expected a timeline object {\"sentences\": ..., ...}, found " +
                                                   json_found(document));
    }
    read_version(json, document);
    Timeline timeline;
    const JsonValue& sentences = list(json, member(json, document, "sentences", "document"), "sentences");
    const JsonValue& syllables = list(json, member(json, document, "syllables", "document"), "syllables");
    for (std::size_t k = 0; k < sentences.items.size(); ++k) {
        timeline.sentences.push_back(
            read_item(json, sentences.items[k], "sentences[" + std::to_string(k) + "]", sentence_fields(), 0));
    }
    for (std::size_t k = 0; k < syllables.items.size(); ++k) {
        timeline.syllables.push_back(read_item(json, syllables.items[k], "syllables[" + std::to_string(k) + "]",
                                               syllable_fields(), timeline.sentences.size()));
    }
    if (const JsonValue* forms = document.find("written_forms")) {
        std::size_t covered = 0;  // forms come in order, apart, inside the syllables
        for (std::size_t k = 0; k < list(json, *forms, "written_forms").items.size(); ++k) {
            const std::string item = "written_forms[" + std::to_string(k) + "]";
            const JsonValue& value = forms->items[k];
            auto form = read_item(json, value, item, written_form_fields(), 0);
            if (form.first_syllable < covered ||
                form.syllable_count > timeline.syllables.size() - std::min(form.first_syllable, timeline.syllables.size()) ||
                form.first_syllable >= timeline.syllables.size()) {
                json.fail(value.offset, item,
                          "covers syllables " + std::to_string(form.first_syllable) + ".." +
                              std::to_string(form.first_syllable + form.syllable_count - 1) +
                              ", expected a stretch of the " + std::to_string(timeline.syllables.size()) +
                              " syllables from " + std::to_string(covered) + " on (forms come in order, apart)");
            }
            covered = form.first_syllable + form.syllable_count;
            timeline.written_forms.push_back(std::move(form));
        }
    }
    if (const JsonValue* mismatches = document.find("mismatches")) {
        for (std::size_t k = 0; k < list(json, *mismatches, "mismatches").items.size(); ++k) {
            const std::string item = "mismatches[" + std::to_string(k) + "]";
            const JsonValue& value = mismatches->items[k];
            auto mismatch = read_item(json, value, item, mismatch_fields(), 0);
            if (mismatch.first_syllable > timeline.syllables.size() ||
                mismatch.syllable_count > timeline.syllables.size() - mismatch.first_syllable) {
                json.fail(value.offset, item,
                          "stands for syllables from " + std::to_string(mismatch.first_syllable) + " (" +
                              std::to_string(mismatch.syllable_count) + " of them), past the " +
                              std::to_string(timeline.syllables.size()) + " syllables");
            }
            timeline.mismatches.push_back(std::move(mismatch));
        }
    }
    if (const JsonValue* duration = document.find("duration")) {
        timeline.duration_s = ItemReader(json, "document", 0).seconds(*duration, "duration");
    }
    if (const JsonValue* warnings = document.find("warnings")) {
        for (std::size_t k = 0; k < list(json, *warnings, "warnings").items.size(); ++k) {
            const JsonValue& warning = warnings->items[k];
            if (warning.type != JsonValue::Type::string) {
                json.fail(warning.offset, "warnings[" + std::to_string(k) + "]",
                          "expected a string, found " + json_found(warning));
            }
            timeline.warnings.push_back(warning.text);
        }
    }
    return timeline;
}

Timeline load_timeline_json(const std::string& path) { return timeline_from_json(detail::read_file(path), path); }

void save_timeline_json(const std::string& path, const Timeline& timeline, const TimelineJsonOptions& options) {
    detail::write_file_atomically(path, timeline_to_json(timeline, options));
}

}  // namespace v0
}  // namespace talkface
