#include "text/script_marks.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "text/code_points.hpp"
#include "text/written_number_scan.hpp"

namespace talkface::detail {

namespace {

// Sounds and actions that subtitles, interview transcripts and scripts write in brackets, in
// Simplified and Traditional characters, and English's; and how a game's or a script's line is said, its
// voice (（小声）其实我早就知道了: session 33, read as words).
constexpr std::string_view kDirectionWords[] = {
    "小声",     "小聲",       "大声",     "大聲",     "轻声",      "輕聲",      "低声",     "低聲",
    "低语",     "低語",       "耳语",     "耳語",     "喃喃",      "自言自语",  "自言自語", "大喊",
    "怒吼",     "whispering", "whispers", "shouting", "笑",        "大笑",      "微笑",     "苦笑",
    "冷笑",     "偷笑",       "笑声",     "笑聲",     "哄笑",      "掌声",      "掌聲",     "鼓掌",
    "拍手",     "欢呼",       "歡呼",     "欢呼声",   "歡呼聲",    "尖叫",      "口哨",     "音乐",
    "音樂",     "背景音乐",   "背景音樂", "配乐",     "配樂",      "音效",      "歌声",     "歌聲",
    "唱",       "哼唱",       "叹气",     "嘆氣",     "歎氣",      "叹息",      "嘆息",     "咳嗽",
    "清嗓子",   "哭",         "哭泣",     "哭声",     "哭聲",      "抽泣",      "哽咽",     "停顿",
    "停頓",     "沉默",       "静默",     "靜默",     "喘气",      "喘氣",      "喘息",     "吸气",
    "吸氣",     "呼吸",       "杂音",     "雜音",     "噪音",      "听不清",    "聽不清",   "画外音",
    "畫外音",   "旁白",       "独白",     "獨白",     "内心独白",  "內心獨白",  "内心os",   "內心os",
    "铃声",     "鈴聲",       "敲门声",   "敲門聲",   "片头",      "片頭",      "片尾",     "转场",
    "轉場",     "点头",       "點頭",     "摇头",     "搖頭",      "鞠躬",      "laughter", "laughs",
    "laughing", "laugh",      "applause", "clapping", "cheering",  "cheers",    "music",    "singing",
    "sighs",    "sigh",       "coughs",   "cough",    "inaudible", "crosstalk", "silence",  "pause",
    "noise"};

// Who makes the sound, before it; how it goes on, after it: 众人笑 全场鼓掌 掌声响起.
constexpr std::string_view kDirectionModifiers[] = {
    "众",   "眾",   "众人", "眾人", "全场", "全場", "观众", "觀眾",       "现场",     "現場", "大家",
    "轻",   "輕",   "轻轻", "輕輕", "热烈", "熱烈", "起",   "响起",       "響起",     "声",   "聲",
    "不断", "不斷", "渐弱", "漸弱", "渐起", "漸起", "停",   "background", "audience", "soft", "loud"};

constexpr std::size_t kLongestDirection = 16;  // code points between the brackets
constexpr std::size_t kLongestLabel = 8;       // code points before the colon

char32_t closing_bracket(char32_t open) {
    switch (open) {
        case '(':
            return ')';
        case '[':
            return ']';
        case 0x3010:
            return 0x3011;  // 【】
        case 0x3014:
            return 0x3015;  // 〔〕
        case 0x3016:
            return 0x3017;  // 〖〗
        default:
            return 0;
    }
}

bool is_direction_separator(char32_t c) {
    return c == ' ' || c == 0x3000 || c == 0x3001 /*、*/ || c == ',' || c == '/' || c == '&';
}

// Whether `piece` (lowercase) is direction words and modifiers, one word of the first kind at least.
bool is_direction_piece(std::string_view piece) {
    // best[k]: piece[0, k) is cut into listed words; whether one of them is a sound or action.
    std::vector<int> best(piece.size() + 1, -1);
    best[0] = 0;
    for (std::size_t k = 0; k < piece.size(); ++k) {
        if (best[k] < 0) continue;
        // `found`: 1 for a sound or action, 0 for a modifier.
        const auto extend = [&](const auto& words, int found) {
            for (const std::string_view word : words) {
                if (piece.compare(k, word.size(), word) == 0)
                    best[k + word.size()] = std::max(best[k + word.size()], best[k] | found);
            }
        };
        extend(kDirectionWords, 1);
        extend(kDirectionModifiers, 0);
    }
    return best[piece.size()] == 1;
}

bool is_direction(const std::vector<CodePoint>& text, std::size_t open, std::size_t close) {
    std::string piece;
    bool has_piece = false;
    for (std::size_t k = open + 1; k <= close; ++k) {
        const char32_t c = text[k].value;
        if (k == close || is_direction_separator(c)) {
            if (!piece.empty()) {
                if (!is_direction_piece(piece)) return false;
                has_piece = true;
            }
            piece.clear();
            continue;
        }
        if (c < 0x80) {
            piece += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        } else {
            piece += text[k].text;
        }
    }
    return has_piece;
}

// A space that may stand between a line's start and its label, or between a label and its words.
bool is_line_space(char32_t c) {
    return c == ' ' || c == 0x3000 || c == '\t';
}

// Whether the bracket text[open, close] is a voice heard over the picture or off it, OS or VO alone, as a
// script or a show's subtitles mark a line (（OS）我到底在干嘛, 内心OS too): only where the bracket opens its
// line or follows a colon, since inside a sentence OS glosses a term (操作系统（OS）).
bool is_voice_over(const std::vector<CodePoint>& text, std::size_t open, std::size_t close) {
    if (close != open + 3) return false;
    std::string letters;
    for (auto k = open + 1; k < close; ++k)
        letters += static_cast<char>(text[k].value >= 'a' && text[k].value <= 'z' ? text[k].value - 'a' + 'A'
                                                                                  : text[k].value);
    if (letters != "OS" && letters != "VO") return false;
    auto before = open;
    while (before > 0 && is_line_space(text[before - 1].value)) --before;
    return before == 0 || is_one_of(text[before - 1].value, U"\n:");
}

void add_directions(const std::vector<CodePoint>& text, std::vector<ScriptMark>& marks) {
    for (std::size_t open = 0; open < text.size(); ++open) {
        const char32_t closing = closing_bracket(text[open].value);
        if (closing == 0) continue;
        for (std::size_t k = open + 1; k < text.size() && k <= open + kLongestDirection + 1; ++k) {
            if (text[k].value == '\n' || closing_bracket(text[k].value) != 0) break;
            if (text[k].value != closing) continue;
            if (is_direction(text, open, k) || is_voice_over(text, open, k)) {
                marks.push_back({open, k + 1, false, open, k + 1});
                open = k;
            }
            break;
        }
    }
}

bool is_label_character(char32_t c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == ' ' ||
           c == '_' || c == '-' || c == 0xB7 /*·*/ || (c >= 0x3400 && c <= 0x9FFF);
}

// A verb of saying at a name's end makes it a sentence's start (他说：), not a name.
bool ends_with_saying(std::string_view name) {
    return ends_with_any(name, {"说", "說", "道", "讲", "講", "称", "稱", "曰", "表示", "指出", "认为",
                                "認為", "强调", "強調"});
}

// Whether a name is a body's: a ministry, a bureau, a commission, an agency, a court, a news desk or a
// company (外交部 国家统计局 国家卫健委 中央氣象署 国家网信办 新华社 港交所 最高法院 联合国), as a news
// digest heads each item with who reports it. A body speaks through its people (外交部发言人：, a person's
// head), never with a label of its own, in a script whose turns come back too.
bool names_body(std::string_view name) {
    if (name == "干部" || name == "幹部") return false;
    return ends_with_any(
        name,
        {"部",   "局",   "委",   "署",   "办",   "辦",     "社",     "院",     "厅",     "廳",     "处",
         "處",   "网",   "網",   "盟",   "府",   "馆",     "館",     "公司",   "集团",   "集團",   "银行",
         "銀行", "央行", "交所", "协会", "協會", "电视台", "電視台", "气象台", "氣象台", "联合国", "聯合國"});
}

bool is_field_name(std::string_view name) {
    // A seat's number names a player (1号：, 12号：).
    const auto digits = name.find_first_not_of("0123456789");
    if (digits > 0 && name.substr(digits) == "号") return false;
    // A worked example's number (例2：, 例12：) heads what follows, as a figure's does.
    if (starts_with_any(name, {"例"}) && name.size() > std::string_view("例").size() &&
        name.find_first_not_of("0123456789", std::string_view("例").size()) == std::string::npos)
        return true;
    // A form's field or a notice's heading names a thing, and a Chinese compound's head is its last
    // morpheme: 收件地址 联系电话 错误代码 本轮得分 当前版本 营业时间 are an address, a number, a code, a
    // score, a version and a time whatever comes before. A speaker's label names a person or role
    // (主持人 记者 嘉宾 队友 小明 A), whose heads are none of these.
    return ends_with_any(name, {"址", "号", "號", "码", "碼", "话", "話", "线", "線", "间", "間", "期", "限",
                                "价", "價", "格", "量", "分", "名", "数", "數", "点", "點", "率", "额", "額",
                                "本", "标", "標", "励", "勵", "榜", "法", "步", "课", "課", "轮", "輪", "报",
                                "報", "赛", "賽", "态", "態", "型", "品",
                                // A question's kind (判断题 选择题 填空题 例题; session 34: a label).
                                "题", "題"}) ||
           // Fields and headings whose heads also end roles (编: 小编 主编, 机: 司机, 警: 民警), or are no
           // attribute, named whole.
           ends_with_any(name, {"邮编", "郵編", "手机", "手機", "预警", "預警", "计算", "計算", "方程",
                                "大小", "注意", "提示", "说明", "說明", "备注", "備註", "通知", "公告"}) ||
           // Session 25: what 本 or 当前 opens is this round's, this book's or this page's own (本局MVP
           // 本场最佳 本书定价 当前状态), a thing the text shows, never a speaker; 本人 is one.
           (starts_with_any(name, {"本", "当前", "當前"}) && name != "本人") ||
           // A code's Latin name, whose last letter is no head to look at (ISBN：978-7-..., 玩家ID：).
           ends_with_any(name, {"ISBN", "ISSN", "IMEI", "ID", "IP", "URL", "SKU"}) || names_body(name);
}

struct Label {
    std::string name;
    ScriptMark mark;
};

// The words Chinese ends a person's word with: a role's suffix or noun (主持人 记者 老师 队友 主播 嘉宾
// 旁白), a kinship's (妈 哥), a title's (王总).
bool ends_with_role(std::string_view name) {
    return ends_with_any(
        name,
        {"人", "者", "员", "員", "师", "師", "生", "手", "家", "长", "長", "官", "主", "友", "客", "宾", "賓",
         "众", "眾", "妈", "媽", "爸", "哥", "姐", "弟", "妹", "叔", "姨", "婆", "爷", "爺", "奶", "子", "儿",
         "兒", "王", "总", "總", "娘", "公", "宝", "寶", "播", "导", "導", "警", "医", "醫", "兵", "将", "將",
         "帅", "帥", "父", "母", "嫂", "夫", "妻", "女", "男", "孩", "娃", "仔", "匠", "白", "音"});
}

// What a familiar name opens with (小明 老王 阿强), and the commonest surnames.
constexpr std::u32string_view kFamiliarOpenings = U"小老阿";
constexpr std::u32string_view kSurnames =
    U"王李张張刘劉陈陳杨楊黄黃赵趙吴吳周徐孙孫马馬朱胡郭何高林罗羅郑鄭梁谢謝宋唐许許韩韓冯馮邓鄧曹"
    U"彭曾肖萧蕭田董袁潘于蒋蔣蔡余杜叶葉程苏蘇魏吕呂丁任沈姚卢盧姜崔钟鍾谭譚陆陸汪范範金石廖贾賈夏韦韋"
    U"付方邹鄒孟熊秦邱江尹薛闫閻段雷侯龙龍史陶黎贺賀顾顧毛郝龚龔邵钱錢严嚴覃武戴莫孔向汤湯";

// Whether a name of two or three characters opens with one of `openings`.
bool opens_as_name(std::string_view name, std::u32string_view openings) {
    const auto characters = decode_utf8(name, "<label>");
    constexpr std::size_t kShortestName = 2;
    constexpr std::size_t kLongestName = 3;
    return characters.size() >= kShortestName && characters.size() <= kLongestName &&
           openings.find(characters.front().value) != std::u32string_view::npos;
}

// Whether a label's name names a person: a speaker whose turn need not come back (a guest's one line). A
// name with a Latin letter or a digit (A, Tom, 1号); a role, whose head is a person's (主持人 记者 老师 队友
// 主播 嘉宾 旁白: the suffixes and nouns Chinese ends a person's word with); a name of two or three
// characters opening with a common surname or with 小 老 阿 (小明 老王 阿强 张伟). A heading that names a
// task or a part of a lesson (化简 总结 解析 答案 注意事项) is none, and names no speaker.
bool names_person(std::string_view name) {
    // A name in Latin letters or digits (A, Tom, Speaker 2), but not capitals alone that spell an
    // organisation's or a league's initials (NBA, WHO); among characters, one that ends in them (玩家A,
    // 选手1), not one that only opens with them (F1阿布扎比站, a race's desk).
    const auto is_latin_or_digit = [](unsigned char c) { return is_ascii_letter(c) || is_ascii_digit(c); };
    if (std::any_of(name.begin(), name.end(), is_latin_or_digit)) {
        const bool has_han = std::any_of(name.begin(), name.end(), [](unsigned char c) { return c >= 0x80; });
        const bool initials = name.size() >= 2 && std::all_of(name.begin(), name.end(), [](unsigned char c) {
                                  return c >= 'A' && c <= 'Z';
                              });
        if (!has_han) return !initials;
        if (is_latin_or_digit(static_cast<unsigned char>(name.back()))) return true;
    }
    // A seat's number (1号, 12號), a crosstalk's or an interview's one-character roles (甲 乙, 问 答).
    const auto digits = name.find_first_not_of("0123456789");
    if (digits > 0 && digits != std::string_view::npos &&
        (name.substr(digits) == "号" || name.substr(digits) == "號"))
        return true;
    if (name == "甲" || name == "乙" || name == "丙" || name == "问" || name == "問" || name == "答")
        return true;
    if (ends_with_role(name)) return true;
    // A word whose head names a part of a lesson or a text (小结 总结, 金句, 任务, 小测, 小知识, 小练习,
    // 方案, 小贴士) is a heading, though it opens as a name does (小 of 小明; 金 任 方 are surnames; session
    // 35: 小结： among 老师： and 学生： was a speaker's and left out). No common given name ends so; a verb
    // of answering or commenting (小明答：) is left to the turn it opens.
    if (ends_with_any(
            name, {"结", "結", "句", "务", "務", "测", "測", "识", "識", "习", "習", "案", "贴士", "貼士"}))
        return false;
    return opens_as_name(name, kFamiliarOpenings) || opens_as_name(name, kSurnames);
}

// Whether the name's lines are a digest's items, who said what, rather than a dialogue's turns: every name
// is a body's or a person's full name, a surname and a given name (王毅 李强 刘德华; not 小明 老王 阿强,
// whom a dialogue calls by, nor 王总, a role), and no line speaks to another (你 您 吗 ？: a turn answers or
// asks). A dialogue whose turns never come back and whose speakers are named in full, saying nothing to each
// other, reads so too.
bool is_digest(const std::vector<CodePoint>& text, const std::vector<Label>& labels) {
    return std::all_of(labels.begin(), labels.end(), [&](const Label& label) {
        if (!names_body(label.name) && !(opens_as_name(label.name, kSurnames) && !ends_with_role(label.name)))
            return false;
        auto end = label.mark.end;
        while (end < text.size() && text[end].value != '\n') ++end;
        return !contains_any(text_between(text, label.mark.end, end), {"你", "您", "妳", "吗", "嗎", "?"});
    });
}

// A colon that introduces a formula (甲烷燃烧：CH4+2O2=CO2+2H2O, 化简：√12=2√3): the line goes on with a term
// (a letter, a digit, a bracket, a sign before one) and holds a relation or a reaction's arrow. What is named
// before it is the formula's heading, no speaker, whose turn is words (session 33: in a passage of such lines
// the headings were taken for labels and left out).
bool introduces_formula(const std::vector<CodePoint>& text, std::size_t after_colon) {
    auto k = after_colon;
    while (k < text.size() && is_line_space(text[k].value)) ++k;
    const auto first = value_at(text, k);
    if (!(is_ascii_letter(first) || is_digit_at(text, k) || is_one_of(first, U"(（√-－+"))) return false;
    for (; k < text.size() && text[k].value != '\n'; ++k)
        if (is_relation_sign(text[k].value) || is_one_of(text[k].value, U"＝→⇌⟶")) return true;
    return false;
}

// Where the time a chat log or a meeting's transcript stamps a line with ends, with the spaces after it,
// if one opens the line at text[start]: a clock time (10:30, 10:30:15), a date before it (2026-12-07,
// 2026/12/07, 12-07) allowed, in brackets or not. Else start.
std::size_t after_time_stamp(const std::vector<CodePoint>& text, std::size_t start) {
    auto k = start;
    const auto bracket = value_at(text, k);
    if (is_one_of(bracket, U"[(")) ++k;
    const auto digits = [&](std::size_t fewest, std::size_t most) {
        std::size_t count = 0;
        while (count < most && is_ascii_digit(value_at(text, k))) {
            ++k;
            ++count;
        }
        return count >= fewest && !is_ascii_digit(value_at(text, k));
    };
    const auto date_start = k;
    if (digits(2, 4) && is_one_of(value_at(text, k), U"-/")) {
        ++k;
        const bool date = digits(1, 2) && (!is_one_of(value_at(text, k), U"-/") || (++k, digits(1, 2))) &&
                          value_at(text, k) == ' ';
        k = date ? k + 1 : date_start;
    } else {
        k = date_start;
    }
    if (!digits(1, 2) || value_at(text, k) != ':') return start;
    ++k;
    if (!digits(2, 2)) return start;
    if (value_at(text, k) == ':') {
        ++k;
        if (!digits(2, 2)) return start;
    }
    if (bracket == '[' || bracket == '(') {
        if (value_at(text, k) != (bracket == '[' ? U']' : U')')) return start;
        ++k;
    } else if (!is_line_space(value_at(text, k)) && k < text.size() && !is_one_of(text[k].value, U"\r\n")) {
        return start;
    }
    while (k < text.size() && is_line_space(text[k].value)) ++k;
    return k;
}

// The label that starts the line at text[start], if it has one.
std::optional<Label> label_at(const std::vector<CodePoint>& text, std::size_t line_start) {
    const auto start = after_time_stamp(text, line_start);
    std::size_t k = start;
    std::string name;
    bool has_letter = false;
    while (k < text.size() && k - start <= kLongestLabel && is_label_character(text[k].value)) {
        has_letter = has_letter || (!(text[k].value >= '0' && text[k].value <= '9') && text[k].value != ' ');
        name += text[k].text;
        ++k;
    }
    if (k == start || k - start > kLongestLabel || k >= text.size() || text[k].value != ':')
        return std::nullopt;
    if (!has_letter || text[k - 1].value == ' ' || ends_with_saying(name)) return std::nullopt;
    // A clock time's colon (10:30) or a ratio's is no label's.
    if (text[k - 1].value >= '0' && text[k - 1].value <= '9' && k + 1 < text.size() &&
        text[k + 1].value >= '0' && text[k + 1].value <= '9') {
        return std::nullopt;
    }
    if (introduces_formula(text, k + 1)) return std::nullopt;
    auto end = k + 1;
    while (end < text.size() && is_line_space(text[end].value)) ++end;
    return Label{name, {line_start, end, true, start, k + 1}};
}

// A chat log's line that holds a speaker's name and the message's time alone, as an app exports the
// header of each message above its text (小明 10:30, 2026-12-07 10:30:15 小明), text[start, end) the line.
std::optional<Label> header_label_at(const std::vector<CodePoint>& text, std::size_t start, std::size_t end) {
    while (end > start && is_one_of(text[end - 1].value, U" \t\r\u3000")) --end;
    const auto name_from = [&](std::size_t from, std::size_t to) -> std::optional<std::string> {
        std::string name;
        bool has_letter = false;
        for (auto k = from; k < to; ++k) {
            if (!is_label_character(text[k].value) || text[k].value == ' ') return std::nullopt;
            has_letter = has_letter || !is_ascii_digit(text[k].value);
            name += text[k].text;
        }
        if (to == from || to - from > kLongestLabel || !has_letter) return std::nullopt;
        return name;
    };
    if (const auto after = after_time_stamp(text, start); after > start) {
        if (const auto name = name_from(after, end)) return Label{*name, {start, end, true, after, end}};
        return std::nullopt;
    }
    auto space = start;
    while (space < end && !is_line_space(text[space].value)) ++space;
    auto stamp = space;
    while (stamp < end && is_line_space(text[stamp].value)) ++stamp;
    if (stamp == space || stamp == end) return std::nullopt;
    const auto name = name_from(start, space);
    if (!name || after_time_stamp(text, stamp) < end) return std::nullopt;
    return Label{*name, {start, end, true, start, space}};
}

void add_labels(const std::vector<CodePoint>& text, std::vector<ScriptMark>& marks) {
    std::vector<Label> labels;
    // A header is followed by its message: lines of a name and a time one after another are a
    // schedule's (张老师 9:00), and none of them is kept.
    std::vector<Label> headers;
    std::optional<Label> pending;
    bool in_schedule = false;
    std::size_t lines = 0;
    for (std::size_t k = 0; k < text.size();) {
        auto start = k;
        while (start < text.size() && is_line_space(text[start].value)) ++start;
        auto end = start;
        while (end < text.size() && text[end].value != '\n') ++end;
        k = end + 1;
        if (end == start || text[start].value == '\r') continue;
        ++lines;
        if (auto header = header_label_at(text, start, end)) {
            in_schedule = in_schedule || pending.has_value();
            pending = std::move(header);
            continue;
        }
        if (pending && !in_schedule) headers.push_back(std::move(*pending));
        pending.reset();
        in_schedule = false;
        if (auto label = label_at(text, start)) labels.push_back(std::move(*label));
    }
    // A chat log's headers, two lines or more, are its speakers' labels as a colon's are.
    if (headers.size() >= 2) labels.insert(labels.end(), headers.begin(), headers.end());
    const auto named = labels.size();
    labels.erase(std::remove_if(labels.begin(), labels.end(),
                                [](const Label& label) { return is_field_name(label.name); }),
                 labels.end());
    const bool has_fields = labels.size() < named;
    if (labels.size() < 2) return;
    std::map<std::string, std::size_t> counts;
    for (const Label& label : labels) ++counts[label.name];
    const bool repeats =
        std::any_of(counts.begin(), counts.end(), [](const auto& entry) { return entry.second >= 2; });
    // Without a speaker's turn coming back, lines of fields make a form, whose 收件人 and 寄件人 are
    // fields too.
    if (!repeats && (has_fields || labels.size() * 2 < lines)) return;
    // Where no turn comes back, a label is a speaker's only where it names a person: a news digest opens
    // each item with its desk's, its body's or its league's name (国家卫健委： 外交部： 英超：
    // F1阿布扎比站：), said as its heading, and two persons at least make a dialogue (session 38: every such
    // line's name was a speaker's, left out with a warning).
    if (!repeats) {
        if (is_digest(text, labels)) return;
        labels.erase(std::remove_if(labels.begin(), labels.end(),
                                    [](const Label& label) { return !names_person(label.name); }),
                     labels.end());
        if (labels.size() < 2) return;
    }
    // Where turns come back, a name that labels one line only is a speaker's where it names a person; else
    // it heads what follows and is said (化简：, 总结：, 注意事项： among 老师： and 学生：; session 34: left
    // out).
    for (const Label& label : labels)
        if (!repeats || counts[label.name] >= 2 || names_person(label.name)) marks.push_back(label.mark);
}

}  // namespace

bool opens_turn(const std::vector<CodePoint>& text, std::size_t start) {
    auto line_start = start;
    while (line_start > 0 && text[line_start - 1].value != '\n') --line_start;
    auto line_end = start;
    while (line_end < text.size() && text[line_end].value != '\n') ++line_end;
    const auto is_turn_dash = [&](std::size_t k) {
        if (!is_dash(text[k].value)) return false;
        auto before = k;
        while (before > line_start && is_line_space(text[before - 1].value)) --before;
        return before == line_start || is_one_of(text[before - 1].value, U"\u3002!?\u2026");
    };
    if (start >= text.size() || !is_turn_dash(start) || !is_turn_dash(line_start)) return false;
    std::size_t turns = 0;
    for (auto k = line_start; k < line_end; ++k) turns += is_turn_dash(k) ? 1 : 0;
    return turns >= 2;
}

std::vector<ScriptMark> find_script_marks(const std::vector<CodePoint>& text) {
    std::vector<ScriptMark> marks;
    add_labels(text, marks);
    add_directions(text, marks);
    std::sort(marks.begin(), marks.end(),
              [](const ScriptMark& a, const ScriptMark& b) { return a.begin < b.begin; });
    return marks;
}

}  // namespace talkface::detail
