// Times a transcript by an imported timing (timed_units.hpp): the units' text is matched to the
// syllables in order, character by character, or syllable by syllable where the timing writes
// pinyin (Montreal Forced Aligner's syllable tiers, text-to-speech engines' word lists).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/number_format.hpp"
#include "talkface/errors.hpp"
#include "text/code_points.hpp"
#include "text/reading_tables.hpp"
#include "text/script_marks.hpp"
#include "timing/timed_units.hpp"

namespace talkface::detail {

namespace {

// A time a little past the audio's end still rounds to it: files keep times to the millisecond.
constexpr double kTimeToleranceS = 0.0005;

// One piece of a unit's text: a character (as its UTF-8 bytes) or a run of ASCII letters and
// digits (pinyin "ni3", "lv4"), with where it starts in the text.
struct Piece {
    std::string text;
    std::size_t offset = 0;
    bool is_latin = false;
};

std::size_t utf8_length(unsigned char lead) {
    return lead < 0x80 ? 1 : lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
}

char32_t code_point(std::string_view bytes) {
    const auto lead = static_cast<unsigned char>(bytes[0]);
    if (bytes.size() == 1) return lead;
    char32_t code = lead & (0x7F >> bytes.size());
    for (std::size_t k = 1; k < bytes.size(); ++k) code = (code << 6) | (static_cast<unsigned char>(bytes[k]) & 0x3F);
    return code;
}

// Spaces and punctuation a timing may hold that no syllable reads: ASCII punctuation, the CJK
// symbols and punctuation block, fullwidth forms of ASCII punctuation, general punctuation.
bool is_unread(char32_t c) {
    if (c < 0x80) return !((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'));
    return c == 0xA0 || c == 0xB7 || (c >= 0x2000 && c <= 0x206F) || (c >= 0x3000 && c <= 0x303F) ||
           (c >= 0xFE10 && c <= 0xFE1F) || (c >= 0xFE30 && c <= 0xFE6B) || (c >= 0xFF01 && c <= 0xFF0F) ||
           (c >= 0xFF1A && c <= 0xFF20) || (c >= 0xFF3B && c <= 0xFF40) || (c >= 0xFF5B && c <= 0xFF65);
}

std::vector<Piece> pieces_of(const std::string& text) {
    std::vector<Piece> pieces;
    for (std::size_t k = 0; k < text.size();) {
        const std::size_t length = std::min(utf8_length(static_cast<unsigned char>(text[k])), text.size() - k);
        const char32_t c = code_point(std::string_view(text).substr(k, length));
        const bool is_latin_letter = c < 0x80 && !is_unread(c);
        if (is_latin_letter && !pieces.empty() && pieces.back().is_latin && pieces.back().offset + pieces.back().text.size() == k) {
            pieces.back().text += text[k];
        } else if (is_latin_letter || c == 0xFC || c == 0xDC) {  // ü starts or continues pinyin
            if (!pieces.empty() && pieces.back().is_latin && pieces.back().offset + pieces.back().text.size() == k) {
                pieces.back().text += text.substr(k, length);
            } else {
                pieces.push_back({text.substr(k, length), k, true});
            }
        } else if (!is_unread(c)) {
            pieces.push_back({text.substr(k, length), k, false});
        }
        k += length;
    }
    return pieces;
}

// The syllable's reading without its tone ("hao3" -> "hao"), "" if it is not pinyin.
std::string toneless(std::string_view pinyin) {
    std::string normal = normalise_pinyin(pinyin);
    if (!normal.empty()) normal.pop_back();
    return normal;
}

std::string describe_place(const Timeline& transcript, std::size_t syllable_index) {
    if (syllable_index >= transcript.syllables.size()) return "the end of the transcript";
    const Syllable& syllable = transcript.syllables[syllable_index];
    std::size_t in_sentence = 1;
    for (std::size_t k = syllable_index; k > 0 && transcript.syllables[k - 1].sentence == syllable.sentence; --k) {
        ++in_sentence;
    }
    const std::string sentence_text =
        syllable.sentence < transcript.sentences.size() ? transcript.sentences[syllable.sentence].text : "";
    return "sentence " + std::to_string(syllable.sentence + 1) + " (\"" + sentence_text + "\"), syllable " +
           std::to_string(in_sentence) + " \"" + syllable.text + "\" (" + syllable.pinyin + ")";
}

// Walks the transcript's syllables as the units' pieces consume them.
class Matcher {
public:
    Matcher(const Timeline& transcript, const std::string& source) : transcript_(transcript), source_(source) {}

    // The syllables `unit` covers: [first, last) (empty for a unit with no readable text).
    std::pair<std::size_t, std::size_t> match(const TimedUnit& unit) {
        const std::size_t first = next_;
        const std::vector<Piece> pieces = pieces_of(unit.text);
        if (pieces.empty()) return {first, first};
        for (const Piece& piece : pieces) {
            if (next_ >= transcript_.syllables.size()) part(unit, piece, "the transcript has ended");
            const Syllable& syllable = transcript_.syllables[next_];
            if (piece.is_latin && offset_in_syllable_ == 0) {
                // A pinyin piece stands for one syllable: by reading (tone optional), or by text
                // where the transcript itself is pinyin.
                const std::string written = toneless(piece.text);
                if ((!written.empty() && written == toneless(syllable.pinyin)) || piece.text == syllable.text) {
                    ++next_;
                    continue;
                }
                part(unit, piece, "the transcript has \"" + syllable.text + "\" (" + syllable.pinyin + ")");
            }
            // A character: the next character of the syllable's text, skipping what no syllable reads.
            skip_unread_in_syllable();
            if (syllable.text.compare(offset_in_syllable_, piece.text.size(), piece.text) != 0) {
                part(unit, piece, "the transcript has \"" + syllable.text + "\" (" + syllable.pinyin + ")");
            }
            offset_in_syllable_ += piece.text.size();
            skip_unread_in_syllable();
            if (offset_in_syllable_ >= syllable.text.size()) {
                ++next_;
                offset_in_syllable_ = 0;
            }
        }
        // A unit that ends inside a syllable (a written form split between words) covers it too.
        return {first, offset_in_syllable_ > 0 ? next_ + 1 : next_};
    }

    void finish(const TimedUnit* last) const {
        if (next_ < transcript_.syllables.size()) {
            throw ParseError(source_, last != nullptr ? last->line : 0, 0, "",
                             "the timing ends, but the transcript goes on at " + describe_place(transcript_, next_));
        }
    }

private:
    [[noreturn]] void part(const TimedUnit& unit, const Piece& piece, const std::string& found) const {
        throw ParseError(source_, unit.line, 0, "\"" + unit.text + "\"",
                         "\"" + piece.text + "\" parts from the transcript at " + describe_place(transcript_, next_) +
                             ": " + found);
    }

    void skip_unread_in_syllable() {
        const std::string& text = transcript_.syllables[next_].text;
        while (offset_in_syllable_ < text.size()) {
            const std::size_t length = utf8_length(static_cast<unsigned char>(text[offset_in_syllable_]));
            if (!is_unread(code_point(std::string_view(text).substr(offset_in_syllable_, length)))) break;
            offset_in_syllable_ += length;
        }
    }

    const Timeline& transcript_;
    const std::string& source_;
    std::size_t next_ = 0;
    std::size_t offset_in_syllable_ = 0;
};

}  // namespace

void check_unit_times(const std::vector<TimedUnit>& units, double duration_s, const std::string& source) {
    double previous_end_s = 0.0;
    for (const TimedUnit& unit : units) {
        const auto refuse = [&](const std::string& problem) {
            throw ParseError(source, unit.line, 0, unit.text.empty() ? "" : "\"" + unit.text + "\"", problem);
        };
        if (!(unit.start_s >= 0.0) || !std::isfinite(unit.end_s)) refuse("expected times >= 0 s");
        if (unit.end_s < unit.start_s) {
            refuse("ends at " + format_shortest(unit.end_s) + " s, before it starts (" + format_shortest(unit.start_s) + " s)");
        }
        if (unit.start_s < previous_end_s - kTimeToleranceS) {
            refuse("starts at " + format_shortest(unit.start_s) + " s, before the one before it ends (" +
                   format_shortest(previous_end_s) + " s): times out of order");
        }
        if (duration_s > 0.0 && unit.end_s > duration_s + kTimeToleranceS) {
            refuse("ends at " + format_shortest(unit.end_s) + " s, past the end of the audio (" +
                   format_shortest(duration_s) + " s)");
        }
        previous_end_s = std::max(previous_end_s, unit.end_s);
    }
}

namespace {

std::vector<std::pair<std::size_t, std::size_t>> matched_ranges(const Timeline& transcript,
                                                                const std::vector<TimedUnit>& units,
                                                                const std::string& source) {
    Matcher matcher(transcript, source);
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    for (const TimedUnit& unit : units) ranges.push_back(matcher.match(unit));
    matcher.finish(units.empty() ? nullptr : &units.back());
    return ranges;
}

// `text` without the stage directions the transcript reader leaves out (script_marks.hpp).
std::string without_directions(const std::string& text) {
    auto code_points = decode_utf8(text, "<timing>");
    for (CodePoint& c : code_points) c.value = ascii_form(c.value);
    std::string out;
    std::size_t at = 0;
    for (const ScriptMark& mark : find_script_marks(code_points)) {
        if (mark.is_label) continue;
        for (; at < mark.begin; ++at) out += code_points[at].text;
        at = mark.end;
    }
    for (; at < code_points.size(); ++at) out += code_points[at].text;
    return out;
}

}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> unit_syllable_ranges(const Timeline& transcript,
                                                                      const std::vector<TimedUnit>& units,
                                                                      const std::string& source) {
    try {
        return matched_ranges(transcript, units, source);
    } catch (const ParseError&) {
        // A transcript read from the same subtitles left their stage directions out, 笑 of （笑）
        // is no syllable of it: matched again without them, the first error stands if that fails too.
        std::vector<TimedUnit> unsaid = units;
        for (TimedUnit& unit : unsaid) unit.text = without_directions(unit.text);
        try {
            return matched_ranges(transcript, unsaid, source);
        } catch (const ParseError&) {
        }
        throw;
    }
}

Timeline match_timed_units(const Timeline& transcript, const std::vector<TimedUnit>& units, double duration_s,
                           const std::string& source, UnitKind kind) {
    check_unit_times(units, duration_s, source);
    return time_matched_units(transcript, units, unit_syllable_ranges(transcript, units, source), duration_s, kind);
}

Timeline time_matched_units(const Timeline& transcript, const std::vector<TimedUnit>& units,
                            const std::vector<std::pair<std::size_t, std::size_t>>& ranges, double duration_s,
                            UnitKind kind) {
    Timeline timeline = transcript;
    for (std::size_t u = 0; u < units.size(); ++u) {
        const TimedUnit& unit = units[u];
        const auto [first, last] = ranges[u];
        if (first >= last) continue;
        // A syllable split across two units (a word boundary inside a written form) keeps the
        // first unit's start and takes the later unit's end.
        const std::size_t count = last - first;
        std::vector<double> starts(count);
        for (std::size_t k = 0; k < count; ++k) {
            starts[k] = unit.start_s + (unit.end_s - unit.start_s) * static_cast<double>(k) / static_cast<double>(count);
        }
        // WebVTT's cue timestamps name the syllables' starts where there is one per syllable.
        if (kind == UnitKind::cues && unit.inner_starts_s.size() + 1 == count) {
            for (std::size_t k = 1; k < count; ++k) starts[k] = unit.inner_starts_s[k - 1].second;
        }
        for (std::size_t k = 0; k < count; ++k) {
            Syllable& syllable = timeline.syllables[first + k];
            const bool is_continued = u > 0 && ranges[u - 1].second > first && k == 0;
            if (!is_continued) syllable.start_s = starts[k];
            syllable.end_s = k + 1 < count ? starts[k + 1] : unit.end_s;
            syllable.final_start_s.reset();
            syllable.confidence = 1.0;
        }
    }
    span_sentences(timeline);
    timeline.duration_s = duration_s;
    return timeline;
}

void span_sentences(Timeline& timeline) {
    for (Sentence& sentence : timeline.sentences) sentence.start_s = sentence.end_s = 0.0;
    std::vector<bool> is_timed(timeline.sentences.size(), false);
    for (const Syllable& syllable : timeline.syllables) {
        Sentence& sentence = timeline.sentences[syllable.sentence];
        if (!is_timed[syllable.sentence]) sentence.start_s = syllable.start_s;
        sentence.end_s = std::max(sentence.end_s, syllable.end_s);
        is_timed[syllable.sentence] = true;
    }
}

}  // namespace talkface::detail
