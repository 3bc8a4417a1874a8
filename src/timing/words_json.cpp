// Word or syllable times as text-to-speech engines report them: a JSON list of
// {"text": "你好", "start": 0.5, "end": 0.9}, seconds. Written one syllable per item (pinyin is
// not kept: the transcript gives it back). Lossy: drops sentences, final starts and confidences.
#include <algorithm>
#include <string>
#include <vector>

#include "common/json.hpp"
#include "timing/import_readers.hpp"

namespace talkface::detail {

std::vector<TimedUnit> read_words_json_units(std::string_view text, const std::string& source) {
    JsonReader json(text, source);
    const JsonValue document = json.read_document();
    if (document.type != JsonValue::Type::array) {
        json.fail(document.offset, "",
                  "expected a list of {\"text\": ..., \"start\": s, \"end\": s}, found " + json_found(document));
    }
    std::vector<TimedUnit> units;
    for (std::size_t k = 0; k < document.items.size(); ++k) {
        const JsonValue& entry = document.items[k];
        const std::string item = "[" + std::to_string(k) + "]";
        if (entry.type != JsonValue::Type::object) {
            json.fail(entry.offset, item, "expected {\"text\": ..., \"start\": s, \"end\": s}, found " + json_found(entry));
        }
        TimedUnit unit;
        unit.line = static_cast<int>(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(entry.offset), '\n'));
        const JsonValue* word = entry.find("text");
        if (word == nullptr || word->type != JsonValue::Type::string) {
            json.fail(word != nullptr ? word->offset : entry.offset, item + ".text",
                      word != nullptr ? "expected a string, found " + json_found(*word) : "\"text\" is missing");
        }
        unit.text = word->text;
        for (const char* key : {"start", "end"}) {
            const JsonValue* time = entry.find(key);
            if (time == nullptr || time->type != JsonValue::Type::number) {
                json.fail(time != nullptr ? time->offset : entry.offset, item + "." + key,
                          time != nullptr ? "expected a number of seconds, found " + json_found(*time)
                                          : "\"" + std::string(key) + "\" is missing");
            }
            (std::string(key) == "start" ? unit.start_s : unit.end_s) = time->number;
        }
        units.push_back(std::move(unit));
    }
    return units;
}

std::string words_json(const Timeline& timeline) {
    std::string json = "[";
    for (std::size_t k = 0; k < timeline.syllables.size(); ++k) {
        const Syllable& syllable = timeline.syllables[k];
        json += std::string(k == 0 ? "\n" : ",\n") + "{\"text\":" + json_quoted(syllable.text) +
                ",\"start\":" + json_number(syllable.start_s) + ",\"end\":" + json_number(syllable.end_s) + "}";
    }
    return json + (timeline.syllables.empty() ? "]\n" : "\n]\n");
}

}  // namespace talkface::detail
