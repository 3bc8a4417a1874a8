// Written forms read aloud (issue 13): numbers, dates, times, amounts, units, phone numbers,
// letters and English words, as a native reader says them, in Simplified and Traditional text.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/transcript.hpp"
#include "text/latin_words.hpp"
#include "text/number_words.hpp"

using namespace talkface;

namespace {

// What is said: the syllables' texts, characters run together, Latin syllables apart.
std::string said(const Timeline& timeline) {
    std::string text;
    for (const auto& syllable : timeline.syllables) {
        const bool is_wide = (static_cast<unsigned char>(syllable.text.front()) & 0x80U) != 0;
        if (!text.empty() && !is_wide) text += ' ';
        text += syllable.text;
    }
    return text;
}

std::string said(const std::string& transcript) {
    return said(read_transcript(transcript));
}

std::string pinyin_of(const std::string& transcript) {
    std::string text;
    for (const auto& syllable : read_transcript(transcript).syllables) text += (text.empty() ? "" : " ") + syllable.pinyin;
    return text;
}

struct Case {
    std::string written;
    std::string said;
};

void check_cases(const std::vector<Case>& cases) {
    for (const auto& item : cases) {
        CAPTURE(item.written);
        const auto timeline = read_transcript(item.written);
        CHECK(said(timeline) == item.said);
        CHECK(timeline.warnings.empty());
    }
}

}  // namespace

TEST_SUITE("written forms") {
    TEST_CASE("cardinals are said with 万 and 亿 groups, 零 for inner zeros, 十 at the head") {
        const std::vector<Case> cases = {
            {"0", "零"},          {"7", "七"},           {"10", "十"},           {"12", "十二"},
            {"20", "二十"},       {"105", "一百零五"},    {"110", "一百一十"},     {"1010", "一千零一十"},
            {"12999", "一万二千九百九十九"},             {"10005", "一万零五"},   {"100010", "十万零一十"},
            {"1000000", "一百万"}, {"100000000", "一亿"}, {"120000000", "一亿二千万"},
            {"1000000001", "十亿零一"}, {"9999999999999999", "九千九百九十九万九千九百九十九亿九千九百九十九万九千九百九十九"},
        };
        for (const auto& item : cases) {
            CAPTURE(item.written);
            CHECK(detail::cardinal_words(item.written) == item.said);
        }
    }

    TEST_CASE("2 is 两 before a measure word and at the head of 千, 万 and 亿") {
        check_cases({
            {"2本书", "两本书"},       {"2個人", "兩個人"},          {"2400万", "两千四百万"},
            {"2000", "两千"},         {"20000", "两万"},            {"2亿", "两亿"},
            {"12000", "一万二千"},     {"22本", "二十二本"},          {"200000", "二十万"},
            {"2月", "二月"},          {"2号", "二号"},              {"第2名", "第二名"},
            {"2km", "两公里"},        {"2", "二"},                  {"2.5万", "二点五万"},
        });
    }

    TEST_CASE("years are said digit by digit, dates and clock times as read aloud") {
        check_cases({
            {"2026年", "二零二六年"},                    {"1998年", "一九九八年"},
            {"12月1日", "十二月一日"},                    {"2026年12月1日", "二零二六年十二月一日"},
            {"2026-12-01", "二零二六年十二月一日"},        {"2026/1/5", "二零二六年一月五日"},
            {"3:30", "三点三十分"},                       {"10:05", "十点零五分"},
            {"2:00", "两点"},                             {"10点05分", "十点零五分"},
            {"8:05:30", "八点零五分三十秒"},               {"2020-2025年", "二零二零到二零二五年"},
            {"比分3:2", "比分三比二"},
        });
    }

    TEST_CASE("percentages, decimals, fractions, ranges and signs") {
        check_cases({
            {"85%", "百分之八十五"},     {"0.5%", "百分之零点五"},   {"３％", "百分之三"},
            {"3.14", "三点一四"},        {"0.05", "零点零五"},       {"1/3", "三分之一"},
            {"2/3", "三分之二"},         {"3-5天", "三到五天"},       {"3~5", "三到五"},
            {"-3", "负三"},              {"-3℃", "零下三摄氏度"},     {"+5", "正五"},
            {"5‰", "千分之五"},          {"10%-20%", "百分之十到百分之二十"}, {"3-5%", "百分之三到五"},
        });
    }

    TEST_CASE("a dash after a date or a clock time is 到, not a minus sign") {
        check_cases({
            {"9月1日-9月5日", "九月一日到九月五日"},
            {"12:00-14:00", "十二点到十四点"},
            {"3点-5点", "三点到五点"},
            {"2020年~2025年", "二零二零年到二零二五年"},
            {"5月-6月", "五月到六月"},
            // Not after a number's date or time: a sign.
            {"今日-3℃", "今日零下三摄氏度"},
            {"星期日-3", "星期日负三"},
        });
        const auto timeline = read_transcript("时间12:00-14:00。");
        REQUIRE(timeline.written_forms.size() == 2);
        CHECK(timeline.written_forms[1].text == "-14:00");
    }

    TEST_CASE("thousands separators, money and units") {
        check_cases({
            {"1,234", "一千二百三十四"},       {"1,234,567", "一百二十三万四千五百六十七"},
            {"199元", "一百九十九元"},          {"¥199", "一百九十九元"},
            {"￥50", "五十元"},                 {"$5", "五美元"},
            {"$3.5", "三点五美元"},             {"NT$300", "新台币三百元"},
            {"$5万", "五万美元"},               {"€20", "二十欧元"},
            {"5km", "五公里"},                  {"60kg", "六十公斤"},
            {"25℃", "二十五摄氏度"},            {"100 m", "一百米"},
            {"120km/h", "一百二十公里每小时"}, {"¥1,299.00", "一千二百九十九元"},
            {"$3.50", "三点五美元"},
        });
    }

    TEST_CASE("phone and room numbers are said digit by digit, 1 as 幺 on the phone") {
        check_cases({
            {"13812345678", "幺三八幺二三四五六七八"},
            {"010-12345678", "零幺零幺二三四五六七八"},
            {"0912-345-678", "零九幺二三四五六七八"},
            {"请拨打110", "请拨打幺幺零"},
            {"電話：2345 6789", "電話二三四五六七八九"},
            {"305室", "三零五室"},
            {"302路公交车", "三零二路公交车"},
            {"007", "零零七"},
        });
    }

    TEST_CASE("full-width digits read as ASCII digits, in Simplified and Traditional text") {
        check_cases({
            {"１２３", "一百二十三"},
            {"今年是２０２６年", "今年是二零二六年"},
            {"兩岸有2400萬人", "兩岸有兩千四百萬人"},
            {"他買了2本書", "他買了兩本書"},
            {"這個月漲了3.5%，約1.2億", "這個月漲了百分之三點五約一點二億"},
        });
    }

    TEST_CASE("full-width letters and symbols read as their ASCII forms, the text kept as written") {
        check_cases({
            {"ＡＩ技术", "ei ai技术"},
            {"公司的ＣＥＯ", "公司的 xi yi ou"},
            {"一部ｉＰｈｏｎｅ", "一部 ai feng"},
            {"免费的Ｗｉ－Ｆｉ", "免费的 wai fa"},
            {"支援５Ｇ網路", "支援五 ji網路"},
            {"每天跑５ｋｍ", "每天跑五公里"},
            {"門票ＮＴ＄３５０", "門票新台幣三百五十元"},
            {"下午２：３０", "下午两点三十分"},
            {"ＧＤＰ增长５．３％", "ji di pi增长百分之五点三"},
        });
        CHECK(pinyin_of("ｎｉ３ｈａｏ３") == "ni3 hao3");
        const auto timeline = read_transcript("我用ｉＰｈｏｎｅ问ＡＩ。");
        CHECK(timeline.warnings.empty());
        CHECK(timeline.sentences.at(0).text == "我用ｉＰｈｏｎｅ问ＡＩ。");
        REQUIRE(timeline.written_forms.size() == 2);
        CHECK(timeline.written_forms[0].text == "ｉＰｈｏｎｅ");
        CHECK(timeline.written_forms[1].text == "ＡＩ");
        // A reading fix takes ASCII braces only: a full-width one is text, reported and skipped.
        const auto braces = read_transcript("行｛hang2｝");
        CHECK(braces.syllables.at(0).pinyin == "xing2");
        CHECK(braces.warnings.size() == 2);
    }

    TEST_CASE("acronyms are said letter by letter, English words by the dictionary") {
        const std::vector<Case> cases = {
            {"AI", "ei ai"},           {"CEO", "xi yi ou"},        {"GDP", "ji di pi"},
            {"USB", "you ai si bi"},   {"OK", "ou kei"},           {"iPhone", "ai feng"},
            {"Wi-Fi", "wai fa"},       {"email", "yi mei er"},         {"WeChat", "wei cha te"},
            {"5G", "五 ji"},           {"MP3", "ai mu pi三"},       {"iPhone15", "ai feng十五"},
        };
        check_cases(cases);
    }

    TEST_CASE("inside Chinese text a Latin word without tones is English or letters, not pinyin") {
        check_cases({
            {"men和long", "man和 long"},
            {"A股上涨", "ei股上涨"},
            // Capitals with a digit are a size or a model, not pinyin a4.
            {"请在A4纸上打印", "请在 ei四纸上打印"},
            {"E3游戏展", "yi三游戏展"},
            {"请发email给我", "请发 yi mei er给我"},
            {"我叫Xiaoming", "我叫 Xiao ming"},
            {"ni3 hao3", "ni3 hao3"},
            {"ni hao", "ni hao"},
        });
        // English (from the dictionary), not the pinyin men5 and long5 they also spell.
        CHECK(pinyin_of("men和long") == "man1 he2 long1");
        CHECK(pinyin_of("ni hao") == "ni5 hao5");
    }

    TEST_CASE("numbers named, dialled and multiplied: 号 before, service numbers, ×") {
        check_cases({
            {"房间号是1208", "房间号是一二零八"},
            {"编号：305", "编号三零五"},
            {"打110", "打幺幺零"},
            {"请拨打12345热线", "请拨打幺二三四五热线"},
            {"110报警", "幺幺零报警"},
            {"来了120人", "来了一百二十人"},
            {"时速120", "时速一百二十"},
            {"7×24小时", "七乘二十四小时"},
            {"这款手机售价5999元", "这款手机售价五千九百九十九元"},
            {"5G网络", "五 ji网络"},
            {"第3季度GDP增长5.2%", "第三季度 ji di pi增长百分之五点二"},
            {"2025-2026年度", "二零二五至二零二六年度"},
            {"00后和90年代", "零零后和九十年代"},
            // A five-digit service number is a name where it does not count; 12345 and 10000 count too.
            {"在12306购票", "在幺二三零六购票"},
            {"向12315投诉", "向幺二三幺五投诉"},
            {"共有12306人", "共有一万二千三百零六人"},
            {"数到12345", "数到一万二千三百四十五"},
        });
    }

    TEST_CASE("seasons, model, type and train numbers, signed percentages, dotted names and words in capitals") {
        check_cases({
            // Two years that follow each other are a season or a school or financial year: 至.
            {"2024/25赛季", "二零二四至二五赛季"},
            {"2024-25賽季", "二零二四至二五賽季"},
            {"2024-2025学年", "二零二四至二零二五学年"},
            {"2020-2025年", "二零二零到二零二五年"},
            {"2024/26", "二十六分之两千零二十四"},
            // A model's number after its maker's name or before 型 式; a train's before 次.
            {"波音737客机", "波音七三七客机"},
            {"空客 320", "空客三二零"},
            {"99式坦克", "九九式坦克"},
            {"2型糖尿病", "二型糖尿病"},
            {"G1234次列车", "ji幺二三四次列车"},
            {"RTX 4090显卡", "a er ti ai ke si四零九零显卡"},
            {"CPU 100%", "xi pi you百分之百"},
            // + before a percentage: 涨, or nothing where the clause names the change; - is 负.
            {"腾讯+2.35%", "腾讯涨百分之二点三五"},
            {"涨幅+2.35%", "涨幅百分之二点三五"},
            {"增速-6.8%", "增速负百分之六点八"},
            // A file's or a library's dotted name: the dot is 点, not the end of a sentence.
            {"我在学Node.js。", "我在学 nou de点 zhei ai si"},
            {"打开index.html", "打开 yin dai ke si点 ai qi ti ai mu ai le"},
            // English words in capitals for a rank or a product are words; acronyms stay spelled.
            {"TOP100", "ta pu一百"},
            {"TOP 10", "ta pu十"},
            {"WHO", "da bu liu ai qi ou"},
        });
        CHECK(read_transcript("我在学Node.js。").sentences.size() == 1);
    }

    TEST_CASE("a lesson's relations, a letter alone, an ID's digits, a game's bonus, a compound word") {
        check_cases({
            {"答案是x=5。", "答案是 ai ke si等于五"},
            {"1+1=2", "一加一等于二"},
            {"x ≠ 0", "ai ke si不等于零"},
            {"选a还是选b？", "选 ei还是选 bi"},
            {"我的ID是Tiger2024", "我的 ai di是 tai ge二零二四"},
            {"他用iPhone15拍照", "他用 ai feng十五拍照"},
            {"攻击力+15", "攻击力加十五"},
            {"经验值+50", "经验值加五十"},
            {"温差+12", "温差正十二"},
            // A compound the dictionary lacks: the split whose parts are nearest in length.
            {"她用Photoshop修图", "她用 fou tou sha pu修图"},
        });
    }

    TEST_CASE("a month and a day without a year are a date where the clause places something in time") {
        check_cases({
            {"9/18起将有强降雨", "九月十八日起将有强降雨"},
            {"颱風預計9/20晚間登陸", "颱風預計九月二十日晚間登陸"},
            {"請於12/31前完成報名", "請於十二月三十一日前完成報名"},
            {"于3/8举行", "于三月八日举行"},
            {"9/18周三开学", "九月十八日周三开学"},
            // Elsewhere a fraction: a measure word or 的 after it, a comparison's 于, the knockout rounds.
            {"倒入1/2杯牛奶", "倒入二分之一杯牛奶"},
            {"有1/3的学生", "有三分之一的学生"},
            {"答案是3/4", "答案是四分之三"},
            {"小于1/3", "小于三分之一"},
            {"进入1/8决赛", "进入八分之一决赛"},
            {"于1/4决赛中出局", "于四分之一决赛中出局"},
            {"于1/3的地区", "于三分之一的地区"},
            {"占1/3~1/2", "占三分之一到二分之一"},
            {"9/40", "四十分之九"},
        });
    }

    TEST_CASE("a race's minutes, seconds and hundredths, a respirator's grade, and 2 before a range's measure word") {
        check_cases({
            {"成绩是1:28.65。", "成绩是一分二十八秒六五"},
            {"以3:27.46夺冠", "以三分二十七秒四六夺冠"},
            {"用时2:05.03", "用时两分零五秒零三"},
            {"下午3:30", "下午三点三十分"},
            // N95, KN95: a filter grade's name, digit by digit, before any word; other two digits count.
            {"符合N95标准", "符合 en九五标准"},
            {"戴KN95口罩", "戴 kei en九五口罩"},
            {"G20峰会", "ji二十峰会"},
            // 2 at the head of a range takes 两 where the last end's measure word does (勺 is one).
            {"加入2-3勺白糖", "加入两到三勺白糖"},
            {"2-3月", "二到三月"},
            // A licence plate's middle dot: the digits after the capital are a name.
            {"京A·12345", "京 ei一二三四五"},
        });
    }

    TEST_CASE("100%, a game's bonus, a chat's laugh, a span of years, a + after a square") {
        check_cases({
            {"100%纯棉", "百分之百纯棉"},
            {"增长100.5%", "增长百分之一百点五"},
            {"10%-100%", "百分之十到百分之百"},
            // + after a game's stat (alone or with 率) is 加; after a share's name it is a rise.
            {"暴击率+5%", "暴击率加百分之五"},
            {"攻击速度+10%", "攻击速度加百分之十"},
            {"防御+20", "防御加二十"},
            {"收益率+18%", "收益率涨百分之十八"},
            // A 2 and three or more 3s: a laugh; 233 alone counts.
            {"笑死我了233333", "笑死我了二三三三三三"},
            {"2333", "二三三三"},
            {"233人", "二百三十三人"},
            // Four digits before 年 that count years.
            {"距今约5000年", "距今约五千年"},
            {"公元前2070年", "公元前两千零七十年"},
            {"已有1200年历史", "已有一千二百年历史"},
            {"2100年", "二一零零年"},
            {"2026年", "二零二六年"},
            // A + or - after a square joins two terms.
            {"x²+2x+1=0", "ai ke si平方加二 ai ke si加一等于零"},
        });
    }

    TEST_CASE("a duration after a word of how long, a set list's scores, an ID's 号码, a room after its floor") {
        check_cases({
            {"他跑出了2:05:30的成绩", "他跑出了两小时零五分三十秒的成绩"},
            {"用时25:30", "用时二十五分三十秒"},
            {"下午2:05:30", "下午两点零五分三十秒"},
            // A result later in the clause makes each dashed pair before it a score; a range stays one.
            {"她以6-3、6-4直落两盘获胜", "她以六比三六比四直落两盘获胜"},
            {"3-5天后获胜", "三到五天后获胜"},
            {"3-5，最后获胜", "三到五最后获胜"},
            // 号码 of a card or a document is read out with 一; a phone's is dialled with 幺.
            {"身份证号码后四位是0317", "身份证号码后四位是零三一七"},
            {"我的号码是0317", "我的号码是零三幺七"},
            // A floor's, a building's or a staircase's number, then the room's.
            {"会议在B栋3楼302举行", "会议在 bi栋三楼三零二举行"},
            {"5栋2单元301", "五栋二单元三零一"},
            {"3楼有200人", "三楼有二百人"},
        });
    }

    TEST_CASE("a word the dictionary lacks and without a vowel is spelled letter by letter, with a warning") {
        const auto timeline = read_transcript("用Xqzt吧", {}, "t.txt");
        CHECK(said(timeline) == "用 ai ke si qiu zei ti吧");
        REQUIRE(timeline.warnings.size() == 1);
        CHECK(timeline.warnings[0].find("t.txt:1:2: \"Xqzt\" is not in the English pronouncing dictionary") == 0);
        CHECK(timeline.syllables[1].generic_speech == false);
    }

    TEST_CASE("a word no table reads is generic speech, about a syllable per group of its vowels") {
        const auto timeline = read_transcript("我用Zorblax打电话", {}, "t.txt");
        CHECK(said(timeline) == "我用 Zor blax打电话");
        REQUIRE(timeline.syllables.size() == 7);
        for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
            CAPTURE(i);
            CHECK(timeline.syllables[i].generic_speech == (i == 2 || i == 3));
        }
        CHECK(timeline.syllables[2].pinyin == kGenericSpeechPinyin);
        CHECK(is_valid_pinyin(kGenericSpeechPinyin));
        CHECK_NOTHROW(syllable_mouth_shapes(kGenericSpeechPinyin));
        REQUIRE(timeline.written_forms.size() == 1);
        CHECK(timeline.written_forms[0].text == "Zorblax");
        CHECK(timeline.written_forms[0].syllable_count == 2);
        REQUIRE(timeline.warnings.size() == 1);
        CHECK(timeline.warnings[0] ==
              "t.txt:1:3: \"Zorblax\" is not in the English pronouncing dictionary; aligned as generic speech of "
              "about 2 syllables (fix it in place: Zorblax{...})");
        // A part the dictionary has keeps its reading beside a part it lacks.
        const auto mixed = read_transcript("WeZorb");
        REQUIRE(mixed.syllables.size() == 2);
        CHECK_FALSE(mixed.syllables[0].generic_speech);
        CHECK(mixed.syllables[1].generic_speech);
        CHECK(mixed.syllables[1].text == "Zorb");
        // A fix in place replaces the guess with a reading.
        const auto fixed = read_transcript("Zorblax{zuo3 bu4 la1}");
        REQUIRE(fixed.syllables.size() == 3);
        CHECK_FALSE(fixed.syllables[0].generic_speech);
        CHECK(fixed.warnings.empty());
    }

    TEST_CASE("a spelling is cut into syllables at its groups of vowels") {
        using Cuts = std::vector<std::string>;
        CHECK(detail::spelled_syllables("Zorblax") == Cuts{"Zor", "blax"});
        CHECK(detail::spelled_syllables("blade") == Cuts{"blade"});        // a final e is silent
        CHECK(detail::spelled_syllables("Tumble") == Cuts{"Tum", "ble"});  // but -le after a consonant is not
        CHECK(detail::spelled_syllables("boy") == Cuts{"boy"});
        CHECK(detail::spelled_syllables("gym") == Cuts{"gym"});
        CHECK(detail::spelled_syllables("Yelp") == Cuts{"Yelp"});          // y before a vowel is a consonant
        CHECK(detail::spelled_syllables("Kardashian") == Cuts{"Kar", "da", "shian"});
        CHECK(detail::spelled_syllables("Xqzt").empty());
        for (const std::string word : {"Zorblax", "Kardashian", "Tumble", "strengths", "a"}) {
            std::string joined;
            for (const auto& piece : detail::spelled_syllables(word)) joined += piece;
            CHECK(joined == word);
        }
    }

    TEST_CASE("a few capitals are an acronym, a longer run a word where it can be said") {
        check_cases({
            {"CCTV", "xi xi ti wei"},
            {"NASA", "na sa"},                // four capitals the dictionary has (session 14)
            {"APEC会议", "ei pi yi xi会议"},  // spelled, as Mandarin says it (session 26)
            {"HDMI", "ai qi di ai mu ai"},
            {"WHO", "da bu liu ai qi ou"},
            {"Google发布", "gu ge发布"},
            {"HTTPS", "ai qi ti ti pi ai si"},      // no vowel
            {"WCDMA", "da bu liu xi di ai mu ei"},  // four consonants in a row
            {"COVID-19疫情", "kou wei de十九疫情"},
            {"SARS", "sa si"},
        });
        const auto timeline = read_transcript("ZOLAXO");
        REQUIRE(timeline.syllables.size() == 3);
        CHECK(timeline.syllables[0].generic_speech);
        CHECK(timeline.warnings.empty());
    }

    TEST_CASE("a word in capitals with a Chinese name is said by it, an acronym inside a word letter by letter") {
        check_cases({
            {"NVIDIA的股价", "ying wei da的股价"},
            {"iOS 17系统", "ai ou ai si十七系统"},
            {"iPhone", "ai feng"},
        });
    }

    TEST_CASE("a sweep of news and game lines: service numbers, scores, 两 and extensions") {
        check_cases({
            // A dialling word further back, with the service's name or 给 between.
            {"打给120", "打给幺二零"},
            {"快叫救护车，打给120！", "快叫救护车打给幺二零"},
            {"请立即拨打急救中心120", "请立即拨打急救中心幺二零"},
            {"打败了120名对手", "打败了一百二十名对手"},
            // A score where the clause speaks of a match; a time elsewhere.
            {"比分是21:19，主队赢了", "比分是二十一比十九主队赢了"},
            {"主队21:19获胜", "主队二十一比十九获胜"},
            {"中国队以2:0战胜对手", "中国队以二比零战胜对手"},
            {"下午3:30开会", "下午三点三十分开会"},
            {"21:19出发", "二十一点十九分出发"},
            // 两 before more measure words; 二代 stays.
            {"走了2步", "走了两步"},
            {"我们组有2男3女", "我们组有两男三女"},
            {"砍了2刀", "砍了两刀"},
            {"富2代", "富二代"},
            // An extension after a landline.
            {"座机是010-88886666转203", "座机是零幺零八八八八六六六六转二零三"},
        });
    }

    TEST_CASE("news figures: model numbers, generations, sprint times, units per unit, signed ranges") {
        check_cases({
            // Three or more digits after a model's capitals are said digit by digit; fewer count.
            {"C919大飞机", "xi九一九大飞机"},
            {"空客A380", "空客 ei三八零"},
            {"G20峰会", "ji二十峰会"},
            {"B-52轰炸机", "bi五十二轰炸机"},
            {"iPhone 15", "ai feng十五"},
            // A number after letters is a name, not a count: CO2 is 二, not 两.
            {"CO2排放", "xi ou二排放"},
            // A generation, the hundredths of a sprint.
            {"90后", "九零后"},
            {"10后", "一零后"},
            {"9秒83", "九秒八三"},
            {"5分钟后", "五分钟后"},
            // KB MB GB TB are units: the number counts (两, and not a phone number's digits).
            {"手机有256GB存储", "手机有二百五十六 ji bi存储"},
            {"2TB硬盘", "两 ti bi硬盘"},
            // A slash between units after a number is 每; elsewhere it is not said.
            {"25元/公斤", "二十五元每公斤"},
            {"2,350.5美元/盎司", "两千三百五十点五美元每盎司"},
            {"男/女", "男女"},
            // Signs on both ends of a range; a temperature's + is 零上.
            {"-8~-3℃", "零下八到零下三摄氏度"},
            {"-5~3℃", "零下五到三摄氏度"},
            {"+5℃", "零上五摄氏度"},
            {"+5", "正五"},
        });
    }

    TEST_CASE("a train's or a flight's number is said digit by digit with 幺, as announcers say it") {
        check_cases({
            {"G101次列车", "ji幺零幺次列车"},
            {"G1次", "ji幺次"},
            {"车次：D2218", "车次 di二二幺八"},
            {"CA1831航班", "xi ei幺八三幺航班"},
            {"航班号MU5101", "航班号 ai mu you五幺零幺"},
            // Without a flight's word it is a model's number, and a model's number keeps 一.
            {"国产C919客机", "国产 xi九一九客机"},
            {"MU5101", "ai mu you五一零一"},
            {"RTX 4090显卡", "a er ti ai ke si四零九零显卡"},
        });
    }

    TEST_CASE("a formula is read as a lesson reads it: signs between terms, roots, squares, Greek letters") {
        check_cases({
            {"已知x+y=10", "已知 ai ke si加 wai等于十"},
            {"如果a-b>0", "如果 ei减 bi大于零"},
            {"x-1=0", "ai ke si减一等于零"},
            {"5-3=2", "五减三等于二"},
            {"12÷3=4", "十二除以三等于四"},
            {"求a×b", "求 ei乘 bi"},
            {"x≥1，y≤2", "ai ke si大于等于一 wai小于等于二"},
            {"A+B轮融资", "ei加 bi轮融资"},
            {"π≈3.14", "派约等于三点一四"},
            {"S=πr²", "ai si等于派 a er平方"},
            {"√2约等于1.414", "根号二约等于一点四一四"},
            {"3²=9", "三的平方等于九"},
            {"α+β=90°", "阿尔法加贝塔等于九十度"},
            // Outside a formula a hyphen joins, a dash is a range, angle brackets are brackets.
            {"免费Wi-Fi", "免费 wai fa"},
            {"3-5天", "三到五天"},
            {"<通知>", "通知"},
        });
    }

    TEST_CASE("dotted groups of digits are a date, an IP address or a version, and a middle dot names a day") {
        check_cases({
            {"2026.03.15起施行", "二零二六年三月十五日起施行"},
            {"地址是192.168.1.1", "地址是一九二点一六八点一点一"},
            {"升级到1.2.3版本", "升级到一点二点三版本"},
            {"macOS 10.15.7", "ma ke ou ai si十点十五点七"},
            {"3.14", "三点一四"},
            {"3·15晚会", "三一五晚会"},
            {"5·12地震", "五一二地震"},
            {"9・11事件", "九一一事件"},
        });
    }

    TEST_CASE("a dash score, a number that names a day, a room or a building, and one digit said over") {
        check_cases({
            {"主队2-1领先", "主队二比一领先"},
            {"比分3-0", "比分三比零"},
            {"今天是520", "今天是五二零"},
            {"618大促", "六一八大促"},
            {"来了520人", "来了五百二十人"},
            {"股价涨到了520", "股价涨到了五百二十"},
            {"666，带带我", "六六六带带我"},
            {"¥666", "六百六十六元"},
            {"第111名", "第一百一十一名"},
            {"请到302会议室", "请到三零二会议室"},
            {"共有200间教室", "共有二百间教室"},
            {"台北101大樓", "台北一零一大樓"},
            {"面积约1.6万km²", "面积约一点六万平方公里"},
            {"支持4K 120帧", "支持四 kei一百二十帧"},
            {"请登录www.12306.cn", "请登录 da bu liu da bu liu da bu liu点幺二三零六点 xi en"},
        });
    }

    TEST_CASE("a code's digits one by one, a letter between two numbers no unit, a range of 万") {
        check_cases({
            {"密码是86753090", "密码是八六七五三零九零"},
            {"验证码：5408", "验证码五四零八"},
            {"我们5V5开黑", "我们五 wei五开黑"},
            {"3V电池", "三伏电池"},
            {"价格在3万-5万元之间", "价格在三万到五万元之间"},
            {"3亿~5亿美元", "三亿到五亿美元"},
            {"3-5万元", "三到五万元"},
        });
    }

    TEST_CASE("news units by their Chinese names, and a unit per another with 每") {
        check_cases({
            {"采用3nm工艺", "采用三纳米工艺"},
            {"主频3.2GHz", "主频三点二吉赫兹"},
            {"降噪50dB", "降噪五十分贝"},
            {"装机1.2GW", "装机一点二吉瓦"},
            {"气压950hPa", "气压九百五十百帕"},
            {"提速至500Mbps", "提速至五百兆比特每秒"},
            {"速率5.8Gbps", "速率五点八吉比特每秒"},
            {"血糖7.0mmol/L", "血糖七点零毫摩尔每升"},
            {"浓度35μg/m³", "浓度三十五微克每立方米"},
            {"含量80mg/100ml", "含量八十毫克每一百毫升"},
            {"读取速度7,000MB/s", "读取速度七千 ai mu bi每秒"},
            {"12GB+256GB", "十二 ji bi加二百五十六 ji bi"},
            {"限速120km/h", "限速一百二十公里每小时"},
        });
    }

    TEST_CASE("a stock's code, the Nikkei's number, a programme's and a resolution are said digit by digit") {
        check_cases({
            {"宁德时代（300750）", "宁德时代三零零七五零"},
            {"台積電（2330）", "台積電二三三零"},
            {"人口（2000）万", "人口两千万"},
            {"贵州茅台（600519）股价", "贵州茅台六零零五一九股价"},
            {"国发〔2024〕10号", "国发二零二四十号"},
            {"日经225指数", "日经二二五指数"},
            {"沪深300指数", "沪深三百指数"},
            {"985、211高校", "九八五二一一高校"},
            {"211工程", "二一一工程"},
            {"有985人", "有九百八十五人"},
            {"支持1080P", "支持一零八零 pi"},
            {"720p视频", "七二零 pi视频"},
        });
    }

    TEST_CASE("a version after a software's name, a tier's round thousand, a designation's hyphen") {
        check_cases({
            {"要求Python 3.12", "要求 pai san三点十二"},
            {"iOS 17.12", "ai ou ai si十七点十二"},
            {"小数3.12", "小数三点一二"},
            {"WTA 1000赛事", "da bu liu ti ei一千赛事"},
            {"RTX 4090", "a er ti ai ke si四零九零"},
            {"歼-20", "歼二十"},
            {"东风-41", "东风四十一"},
            {"气温-5℃", "气温零下五摄氏度"},
            {"PCIe 5.0", "pi xi ai yi五点零"},
        });
    }

    TEST_CASE("a range of two days, scores drawn, relations after a character, hours with a zero, 连") {
        check_cases({
            {"10/1-10/7期间", "十月一日到十月七日期间"},
            {"于10/1-10/7举行", "于十月一日到十月七日举行"},
            {"时间为12/3-12/5", "时间为十二月三日到十二月五日"},
            {"1/3~1/2", "三分之一到二分之一"},
            {"英超1-1战平", "英超一比一战平"},
            {"中国女足1∶0击败对手", "中国女足一比零击败对手"},
            {"比例尺1∶50000", "比例尺一比五万"},
            {"含量≥80", "含量大于等于八十"},
            {"06时发布", "六时发布"},
            {"编号06", "编号零六"},
            {"取得2连胜", "取得两连胜"},
            {"交管12123", "交管幺二幺二三"},
            {"股价12100点", "股价一万二千一百点"},
        });
    }

    TEST_CASE("a dialled number's 1 is 一 in a Traditional transcript, as Taiwan says it, and a train keeps 幺") {
        check_cases({
            {"如遇緊急狀況，請撥打119或110。", "如遇緊急狀況請撥打一一九或一一零"},
            {"消費者可撥打免付費專線0800-211-511洽詢。", "消費者可撥打免付費專線零八零零二一一五一一洽詢"},
            {"如发现火情，请立即拨打119报警。", "如发现火情请立即拨打幺幺九报警"},
            {"複興號G1次列車從北京南站出發。", "複興號 ji幺次列車從北京南站出發"},
        });
    }

    TEST_CASE("a year before a word it names is said digit by digit, without 年") {
        check_cases({
            {"苹果2025财年营收创新高", "苹果二零二五财年营收创新高"},
            {"2025赛季中超联赛", "二零二五赛季中超联赛"},
            {"2025届毕业生", "二零二五届毕业生"},
            {"教材为2024版", "教材为二零二四版"},
            {"共2000人", "共两千人"},
            {"约2000多人", "约两千多人"},
            {"第2025届", "第二千零二十五届"},
        });
    }

    TEST_CASE("brands and words said their own way, and names that start as only pinyin does") {
        check_cases({
            {"*ST康美今日复牌", "星 ai si ti康美今日复牌"},
            {"OPPO手机", "ou po手机"},
            {"HarmonyOS NEXT", "ha me ni ou ai si nai ke si te"},
            {"Tesla汽车", "te si la汽车"},
            {"下载App", "下载 ei pi pi"},
            {"xinhua新闻", "xin hua新闻"},
            {"来信请发送至news@xinhua.org", "来信请发送至 nu si艾特 xin hua点 o ge"},
        });
    }

    TEST_CASE("a lesson's powers, subscripts, signed terms after a relation, geometry's signs and physics units") {
        check_cases({
            {"10的5次方写作10⁵。", "十的五次方写作十的五次方"},
            {"10⁻³", "十的负三次方"},
            {"10¹²", "十的十二次方"},
            {"光速约为3×10⁸m/s", "光速约为三乘十的八次方米每秒"},
            {"约为1.01×10⁵Pa", "约为一点零一乘十的五次方帕"},
            {"用2^10表示", "用二的十次方表示"},
            {"x⁴", "ai ke si的四次方"},
            {"x^2+1", "ai ke si平方加一"},
            {"3²", "三的平方"},
            {"面积为5m²", "面积为五平方米"},
            {"化学式是CO₂", "化学式是 xi ou二"},
            {"x₁和x₂", "ai ke si一和 ai ke si二"},
            {"x=-2是方程的解", "ai ke si等于负二是方程的解"},
            {"比较：-3<-1", "比较负三小于负一"},
            {"∠A=30°", "角 ei等于三十度"},
            {"AB⊥CD", "ei bi垂直于 xi di"},
            {"1kW·h的电能", "一千瓦时的电能"},
            {"等于3.6×10⁶J", "等于三点六乘十的六次方焦耳"},
            {"重力是20N", "重力是二十牛"},
            {"电流为0.5A。", "电流为零点五安"},
            {"电阻R=10Ω", "电阻 a er等于十欧"},
            {"5A景区", "五 ei景区"},
            {"在△ABC中", "在三角形 ei bi xi中"},
            {"g取9.8m/s²", "ji取九点八米每二次方秒"},
            {"求a²+b²的值", "求 ei平方加 bi平方的值"},
            {"男子4x400米接力", "男子四乘四百米接力"},
            {"分辨率1920x1080", "分辨率一千九百二十乘一千零八十"},
        });
    }

    TEST_CASE("a chat's laugh, an uploader, a chip's model and a code's dash") {
        check_cases({
            {"hhh你太逗了", "哈哈哈你太逗了"},
            {"大家好，我是UP主", "大家好我是 a pu主"},
            {"搭载天玑9400芯片", "搭载天玑九四零零芯片"},
            {"骁龙865", "骁龙八六五"},
            {"麒麟9000", "麒麟九千"},
            {"文件编号为A2024-0315", "文件编号为 ei二零二四杠零三一五"},
            {"3-5天", "三到五天"},
            {"哈哈哈233", "哈哈哈二三三"},
            {"共233人", "共二百三十三人"},
            {"88，下次再聊！", "八八下次再聊"},
            {"886~", "八八六"},
            {"他考了88分", "他考了八十八分"},
            {"得分：88", "得分八十八"},
            {"三局2胜", "三局两胜"},
            {"2胜1负", "两胜一负"},
            {"本週三（12/4）舉行", "本週三十二月四日舉行"},
            {"周五(3/8)发布", "周五三月八日发布"},
        });
    }

    TEST_CASE("numbers written as one character, a chat's +1, 1314, initials and levels, a postcode, × after a word") {
        check_cases({
            {"①水 ②二氧化碳", "一水二二氧化碳"},
            {"⑴⒉❸", "一二三"},
            {"第Ⅱ卷", "第二卷"},
            {"ⅲ", "三"},
            {"答案是½", "答案是二分之一"},
            {"¾杯", "四分之三杯"},
            {"sin30°=1/2", "sai yin三十度等于二分之一"},
            {"25%=1/4", "百分之二十五等于四分之一"},
            {"+1，我也觉得", "加一我也觉得"},
            {"温差+1", "温差正一"},
            {"我爱你1314", "我爱你一三一四"},
            {"1314人", "一千三百一十四人"},
            {"yyds！", "wai wai di ai si"},
            {"等级到了Lv.50。", "等级到了 ai le wei五十"},
            {"我LV50了", "我 ai le wei五十了"},
            {"邮编100080", "邮编一零零零八零"},
            {"经验值×2", "经验值乘二"},
            {"△ABC≌△DEF", "三角形 ei bi xi全等于三角形 di yi ai fu"},
            {"△ABC∽△DEF", "三角形 ei bi xi相似于三角形 di yi ai fu"},
            {"請洽(07)123-4567", "請洽零七一二三四五六七"},
            {"台灣選手奪得2金5銅", "台灣選手奪得兩金五銅"},
            {"价格(元)123-456", "价格元一百二十三到四百五十六"},
        });
        // A choice's letter and its dot end no sentence (A.正确 B.错误); a dot before a space does.
        CHECK(read_transcript("这是一道选择题：A.正确 B.错误").sentences.size() == 1);
        CHECK(said("选择题：A.正确 B.错误") == "选择题 ei正确 bi错误");
        CHECK(read_transcript("我选A. 然后交卷。").sentences.size() == 2);
    }

    TEST_CASE("a tilde and a topic's # are punctuation, and a symbol without a reading is warned of by its own code point") {
        check_cases({
            {"#春节快乐# 祝大家新年好！", "春节快乐祝大家新年好"},
            {"＃话题＃", "话题"},
            {"好的呀～", "好的呀"},
            {"嗯嗯~", "嗯嗯"},
            {"3~5天", "三到五天"},
        });
        // A sign alone (between two words ＆ is said, and: since session 32).
        const auto full_width = read_transcript("价格＆", {}, "t.txt");
        REQUIRE(full_width.warnings.size() == 1);
        CHECK(full_width.warnings[0] == "t.txt:1:3: \"＆\" (U+FF06) has no Mandarin reading; skipped");
        // A # with no partner on its line is a symbol.
        CHECK(read_transcript("价格#5").warnings.size() == 1);
        CHECK(read_transcript("# 标题 #").warnings.size() == 2);
    }

    TEST_CASE("an emoji and a face drawn in signs are unsaid and unwarned, and stay in the sentence's text") {
        // Every row but the first failed on main d388cc3 (session 31, dev26): a warning for each sign, and
        // the Greek letters drawn in a face said as a formula's (欧米伽, 西格马).
        check_cases({
            {"今天好开心😄", "今天好开心"},
            {"谢谢老板的火箭🚀🚀", "谢谢老板的火箭"},
            {"早上好☀️今天也要加油", "早上好今天也要加油"},
            {"好耶(≧∇≦)ﾉ", "好耶"},
            {"晚安(｡･ω･｡)ﾉ♡", "晚安"},
            {"吓死我了Σ(っ °Д °;)っ", "吓死我了"},
            {"什么？？？(╯°□°)╯︵ ┻━┻", "什么"},
            {"收到(^_^)谢谢", "收到谢谢"},
        });
        const auto after_end = read_transcript("好的。👍");
        REQUIRE(after_end.sentences.size() == 1);
        CHECK(after_end.sentences[0].text == "好的。👍");
        CHECK(read_transcript("晚安(｡･ω･｡)ﾉ♡").sentences[0].text == "晚安(｡･ω･｡)ﾉ♡");
        // The limits: a formula's Greek letter and brackets, a list's circled digit, a rating's stars, a
        // bracket of the text's own, a sign alone.
        check_cases({
            {"Σ(a+b)", "西格马 ei加 bi"},
            {"ω=2πf", "欧米伽等于二派 ai fu"},
            {"❶水", "一水"},
            {"评分：★★★★☆", "评分四星"},
            {"这件衣服88元（包邮）", "这件衣服八十八元包邮"},
            {"x²(^_^)", "ai ke si平方"},
        });
        CHECK(read_transcript("★重要通知★").warnings.size() == 2);
        CHECK(read_transcript("价格(＆)").warnings.size() == 1);
        CHECK(read_transcript("好的(?)").warnings.empty());
    }

    TEST_CASE(
        "a game's gauge in 度 takes a bonus, a Chinese dash is no sign, a day's word names 520 without 是") {
        // Every row but the limits failed on main d388cc3 (session 31, dev26): 正十, 负一, 负三, 五百二十.
        check_cases({
            {"好感度+10", "好感度加十"},
            {"熟练度-1", "熟练度减一"},
            {"——3年后。", "三年后"},
            {"今天520，你送礼物了吗？", "今天五二零你送礼物了吗"},
            {"明天618", "明天六一八"},
            // The limits: a measure in degrees, a share, one em dash, a count after the day's word.
            {"温度+5", "温度正五"},
            {"角度-30", "角度负三十"},
            {"满意度+5%", "满意度涨百分之五"},
            {"—3年后", "负三年后"},
            {"今天520人", "今天五百二十人"},
        });
    }

    TEST_CASE("a chat's initials with one vowel syllable are said as letters") {
        // awsl failed on main d388cc3 (session 31, dev26): generic speech of one syllable, with a warning.
        check_cases({
            {"awsl，太可爱了", "ei da bu liu ai si ai le太可爱了"},
            {"ojbk", "ou zhei bi kei"},
        });
        // The limits: a hum drawn out is 嗯 (session 33; generic speech before), pinyin stays pinyin.
        CHECK(pinyin_of("emmm") == "n2");
        CHECK(said("ang") == "ang");
    }

    TEST_CASE("a country calling code is 加 and its digits, with the groups of the number after it") {
        check_cases({
            {"电话：+86 10 6512 3456", "电话加八六幺零六五幺二三四五六"},
            {"+86-10-65123456", "加八六幺零六五幺二三四五六"},
            {"国际区号是+86", "国际区号是加八六"},
            {"区号：+852", "区号加八五二"},
        });
        // Without a group after it, a phone word or 区号, a + and digits is a sign.
        CHECK(said("温差+12") == "温差正十二");
    }

    TEST_CASE("e-mail and web addresses: @ 艾特, dots 点, labels as words, pinyin or letters, digits one by one") {
        check_cases({
            {"邮箱zhangwei@163.com", "邮箱 zhang wei艾特一六三点 ka mu"},
            {"12345678@qq.com", "一二三四五六七八艾特 qiu qiu点 ka mu"},
            {"访问www.gov.cn", "访问 da bu liu da bu liu da bu liu点 ji ou wei点 xi en"},
            // The scheme is not said; a path's slashes are.
            {"https://www.example.com/news",
             "da bu liu da bu liu da bu liu点 yi ge zan pa点 ka mu斜杠 nu si"},
            {"user_name@example.com", "yu ze下划线 nei mu艾特 yi ge zan pa点 ka mu"},
            // A mention; an @ before no name is a symbol without a reading (a warning).
            {"@新华社", "艾特新华社"},
        });
        // The dot after an address ends the sentence; the address keeps its text.
        const auto timeline = read_transcript("请访问www.gov.cn. 谢谢。");
        REQUIRE(timeline.written_forms.size() == 1);
        CHECK(timeline.written_forms[0].text == "www.gov.cn");
        CHECK(timeline.sentences.size() == 2);
        // Not addresses: a decimal, a number with a unit, No.1.
        CHECK(said("3.14") == "三点一四");
        CHECK(said("1.5kg") == "一点五公斤");
    }

    TEST_CASE("No.1 is said the English way, number one") {
        check_cases({
            {"世界No.1", "世界 nan ba wan"},
            {"排名NO. 7", "排名 nan ba sai wen"},
            {"排名No.12", "排名 nan ba tai er fu"},
        });
        auto word = [](const char* english) { return *detail::english_word_syllables(english); };
        auto joined = [](std::vector<std::vector<std::string>> words) {
            std::vector<std::string> syllables;
            for (const auto& w : words) syllables.insert(syllables.end(), w.begin(), w.end());
            return syllables;
        };
        CHECK(detail::english_number_syllables("42") == joined({word("forty"), word("two")}));
        CHECK(detail::english_number_syllables("07") == word("seven"));
        CHECK(detail::english_number_syllables("101") == joined({word("one"), word("oh"), word("one")}));
    }

    TEST_CASE(
        "an English word's consonants after its vowels are syllables of their own, as Mandarin says them") {
        // Each row but the last two failed on main 348e35c (fei si, yi sai, zun, yin, ma si, bi).
        check_cases({
            {"这个bug我明天fix一下", "这个 ba ge我明天 fei ke si一下"},
            {"我用Excel做了个表", "我用 yi ke sai er做了个表"},
            {"Zoom链接发群里了", "zu mu链接发群里了"},
            {"这个team很好", "这个 ti mu很好"},
            {"iPhone 16 Pro Max", "ai feng十六 pu lou ma ke si"},
            {"Bill来了", "bi er来了"},
            // An m before p or b is said n (camp 坎普); an l after a back vowel goes into it (call 扣).
            {"去camp", "去 kan pu"},
            {"有事call我", "有事 kou我"},
        });
    }

    TEST_CASE("an English word's vowel as the loans keep it: ai before n, ie after ch and j, a final s si") {
        // Each row but the last two failed on main 436b8aa: dai de lan, lan, wen, chai ke, zhai fu, fan zi,
        // wen dou zi.
        check_cases({
            {"周五deadline", "周五 dai de lai en"},
            {"加我line", "加我 lai en"},
            {"Wayne来了", "wei en来了"},
            {"你先check一下", "你先 qie ke一下"},
            {"Jeff来了", "jie fu来了"},
            {"10万fans", "十万 fan si"},
            {"Windows 11", "wen dou si十一"},
            // No fai keeps the glide: the n stays in the final (find fan de). A z written z stays zi (Liz).
            {"Find X8", "fan de ai ke si八"},
            {"Liz来了", "li zi来了"},
        });
    }

    TEST_CASE("an aw before n is ang, a name's -stein si tan, as the loans write them") {
        // Each row failed on main 61e9b85: ban, dan tan, ai en si tai en, ben si tai en.
        check_cases({
            {"Brown先生", "bu lang先生"},
            {"downtown", "dang tang"},
            {"Einstein的相对论", "ai en si tan的相对论"},
            {"Bernstein指挥", "ben si tan指挥"},
        });
    }

    TEST_CASE("every letter name and every English reading is a syllable the aligner and the lips take") {
        for (char letter = 'A'; letter <= 'Z'; ++letter) {
            CAPTURE(letter);
            for (const auto& syllable : detail::letter_syllables(std::string(1, letter))) {
                CAPTURE(syllable);
                CHECK(is_valid_pinyin(syllable));
                CHECK_NOTHROW(syllable_mouth_shapes(syllable));
            }
        }
        std::size_t checked = 0;
        CHECK(detail::english_lines().keys_ascend());
        for (const auto line : detail::english_lines().lines()) {
            const auto tab = line.find('\t');
            std::string_view rest = line.substr(tab + 1);
            while (!rest.empty()) {
                const auto space = rest.find(' ');
                const std::string syllable(rest.substr(0, space));
                if (!is_valid_pinyin(syllable)) {
                    CAPTURE(line);
                    CHECK(is_valid_pinyin(syllable));
                }
                ++checked;
                rest.remove_prefix(space == std::string_view::npos ? rest.size() : space + 1);
            }
        }
        CHECK(checked > 200000);
        for (const std::string word : {"street", "hello", "microsoft", "strengths", "the", "rhythm", "quick", "judge"}) {
            CAPTURE(word);
            const auto syllables = detail::english_word_syllables(word);
            REQUIRE(syllables);
            for (const auto& syllable : *syllables) {
                CAPTURE(syllable);
                CHECK(is_valid_pinyin(syllable));
                CHECK_NOTHROW(syllable_mouth_shapes(syllable));
            }
        }
    }

    TEST_CASE("each written form keeps its text beside the syllables it became") {
        const auto timeline = read_transcript("今天是2026年12月1日，我用iPhone。");
        CHECK(timeline.sentences.at(0).text == "今天是2026年12月1日，我用iPhone。");
        REQUIRE(timeline.written_forms.size() == 4);
        const auto& year = timeline.written_forms[0];
        CHECK(year.text == "2026年");
        CHECK(year.first_syllable == 3);
        CHECK(year.syllable_count == 5);
        CHECK(timeline.syllables[3].text == "二");
        CHECK(timeline.syllables[3].pinyin == "er4");
        CHECK(timeline.syllables[7].pinyin == "nian2");
        CHECK(timeline.written_forms[1].text == "12");
        CHECK(timeline.written_forms[2].text == "1");
        CHECK(timeline.written_forms[3].text == "iPhone");
        CHECK(timeline.written_forms[3].first_syllable == 15);
        CHECK(timeline.written_forms[3].syllable_count == 2);
        CHECK(timeline.syllables[12].pause_after);  // the comma after 日
    }

    TEST_CASE("news: an exchange's suffix, floors, a jump's centimetres, a clock's zero, a loss, 度 of weather, a final a, sin") {
        // Each row failed on main a3e2d62 but the ones that show the rule's limits (session 15).
        check_cases({
            {"腾讯控股（00700.HK）", "腾讯控股零零七零零"},
            {"贵州茅台(600519.SH)", "贵州茅台六零零五一九"},
            {"台積電（2330.TW）股價", "台積電二三三零股價"},
            {"港股00700.HK今天涨了", "港股零零七零零今天涨了"},
            {"上证600519.SH收涨", "上证六零零五一九收涨"},
            {"官网是12306.cn", "官网是幺二三零六点 xi en"},
            {"這個觀景台在89F", "這個觀景台在八十九樓"},
            {"1F為服務台", "一樓為服務台"},
            {"會議在2F舉行", "會議在二樓舉行"},
            {"停車場在B2", "停車場在 bi二"},
            {"华氏100°F", "华氏一百华氏度"},
            {"他跳出了8米22的成绩", "他跳出了八米二二的成绩"},
            {"身高1米75", "身高一米七五"},
            {"长3米20厘米", "长三米二十厘米"},
            {"100米10名选手", "一百米十名选手"},
            {"凌晨02:00至06:00", "凌晨两点至六点"},
            {"00:30", "零点三十分"},
            {"曼城客场1-2不敌利物浦", "曼城客场一比二不敌利物浦"},
            {"气温降至-2.5度", "气温降至零下二点五度"},
            {"氣溫-3~5度", "氣溫零下三到五度"},
            {"向左旋转-30度", "向左旋转负三十度"},
            {"NASA宣布", "na sa宣布"},
            {"求sin x的值", "求 sai yin ai ke si的值"},
            // Seen in dev5's held-out part (session 15): 0-0 was a phone's digits, a house's number a name's.
            {"比分定格在0-0", "比分定格在零比零"},
            {"气温0-3度", "气温零到三度"},
            {"電話02-23456789", "電話零二二三四五六七八九"},
            {"文化路一段100號3F", "文化路一段一百號三樓"},
            {"中山路128号", "中山路一百二十八号"},
            {"1203号房间", "一二零三号房间"},
        });
        CHECK(read_transcript("港股00700.HK今天涨了。").sentences.size() == 1);
        // Where usage varies the transcript decides in place: -2℃ is 零下两摄氏度 by default.
        CHECK(said("最低气温-2℃") == "最低气温零下两摄氏度");
        CHECK(said("最低气温-2℃{零下二摄氏度}") == "最低气温零下二摄氏度");
        CHECK(said("会议在2F{二楼}") == "会议在二楼");
    }

    TEST_CASE("subtitles' timings, a place in a video, scores between teams, a game's record, versions, IP ratings, the Republic's dates, 2度") {
        // Each row failed on main e095aa7 but the ones that show the rule's limits (session 16, dev6's tuning misses).
        check_cases({
            {"[00:12.50]我们一起走过的路", "我们一起走过的路"},
            {"[00:12.00][01:30.00]副歌", "副歌"},
            {"00:01:23,450 --> 00:01:25,900 你终于来了", "你终于来了"},
            {"00:00:01.000 --> 00:00:04.000 你好", "你好"},
            {"会议[12:30]开始", "会议十二点三十分开始"},
            {"视频1:23处有彩蛋", "视频一分二十三秒处有彩蛋"},
            {"进度条拉到12:45", "进度条拉到十二分四十五秒"},
            {"下午3:30开会", "下午三点三十分开会"},
            {"英超第20轮：曼城2-1阿森纳", "英超第二十轮曼城二比一阿森纳"},
            {"上海海港3-3北京国安", "上海海港三比三北京国安"},
            {"增长了2-3倍", "增长了两到三倍"},
            {"连续5-3天", "连续五到三天"},
            {"战绩0-10，带不动", "战绩零杠十带不动"},
            {"这把战绩5-2-10", "这把战绩五杠二杠十"},
            {"每周5-10次", "每周五到十次"},
            {"新版本13.24更新了", "新版本十三点二十四更新了"},
            {"蓝牙版本升级到5.3", "蓝牙版本升级到五点三"},
            {"防水等级IP68", "防水等级 ai pi六八"},
            {"申請期限至113/12/31止", "申請期限至一百一十三年十二月三十一日止"},
            {"113.10.15公告", "一百一十三年十月十五日公告"},
            {"2026-12-01~2026-12-05", "二零二六年十二月一日到二零二六年十二月五日"},
            {"升级到v115.3.1", "升级到 wei一百一十五点三点一"},
            {"今天最低气温只有2度", "今天最低气温只有两度"},
            {"夹角是2度", "夹角是两度"},
            {"路面温度下降2度左右", "路面温度下降两度左右"},
            {"他的手臂是2度烫伤", "他的手臂是二度烫伤"},
            {"他2度夺冠", "他二度夺冠"},
            {"他以2杆优势夺冠", "他以两杆优势夺冠"},
            {"梅西进了2球", "梅西进了两球"},
            {"中国队获得2枚金牌", "中国队获得两枚金牌"},
            {"疫苗要打2针", "疫苗要打两针"},
            {"酒店住2晚", "酒店住两晚"},
            {"第2道题", "第二道题"},
            {"我去，99+了", "我去九十九加了"},
            {"这个价格太离谱了吧233", "这个价格太离谱了吧二三三"},
            {"他的分数是233", "他的分数是二百三十三"},
            {"好啊233人报名", "好啊二百三十三人报名"},
            {"1+1=2", "一加一等于二"},
            // Seen in dev6's held-out part (session 16): a range of versions joined by 到.
            {"支持Python 3.8到3.11", "支持 pai san三点八到三点十一"},
            {"从3.8到3.11", "从三点八到三点一一"},
        });
        // A short line of Taiwan's shows its readings in Traditional characters (樓, not 楼).
        CHECK(said("台北101大樓89F觀景台") == "台北一零一大樓八十九樓觀景台");
        CHECK(said("1樓大廳見") == "一樓大廳見");
        // The timing stays in the sentence's text; nothing of it is said or warned about.
        const auto cue = read_transcript("00:01:23,450 --> 00:01:25,900 你终于来了");
        CHECK(cue.sentences.at(0).text == "00:01:23,450 --> 00:01:25,900 你终于来了");
        CHECK(cue.syllables.size() == 5);
        CHECK(cue.warnings.empty());
        CHECK(said("今天最低气温只有2{二}度") == "今天最低气温只有二度");
        // A list item's number and its dot end no sentence (a results table's rows); after a word they do.
        const auto table = read_transcript("积分榜：1.利物浦 68分 2.阿森纳 65分");
        CHECK(table.sentences.size() == 1);
        CHECK(said(table) == "积分榜一利物浦六十八分二阿森纳六十五分");
        CHECK(read_transcript("今年增长了3.接下来看天气").sentences.size() == 2);
    }

    TEST_CASE("full-width commas between digits, the Republic's two-digit years, a season's record, frequencies, isotopes, formulas") {
        // Each row failed on main 7a4d98a but the ones that show the rule's limits (session 17, dev7's tuning misses).
        check_cases({
            {"他考了68，123人参加", "他考了六十八一百二十三人参加"},
            {"这次考试他得了96，112人里排第3", "这次考试他得了九十六一百一十二人里排第三"},
            {"全年共接待游客1，200万人次", "全年共接待游客一千二百万人次"},
            {"共有12，500人", "共有一万二千五百人"},
            {"票价：¥1，280", "票价一千二百八十元"},
            {"1，234，567", "一百二十三万四千五百六十七"},
            {"售价68，123元", "售价六万八千一百二十三元"},
            {"繳費期限：99/12/31前", "繳費期限九十九年十二月三十一日前"},
            {"921大地震發生於88/9/21", "九二一大地震發生於八十八年九月二十一日"},
            {"湖人目前战绩30-12，排名西部第2", "湖人目前战绩三十胜十二负排名西部第二"},
            {"勇士本赛季战绩45-37", "勇士本赛季战绩四十五胜三十七负"},
            {"战绩0-10，带不动", "战绩零杠十带不动"},
            {"第2盘抢七7-5，辛纳拿下", "第二盘抢七七比五辛纳拿下"},
            {"首盘6-4", "首盘六比四"},
            {"欢迎收听FM103.9交通广播", "欢迎收听 ai fu ai mu一零三点九交通广播"},
            {"调频97.4", "调频九七点四"},
            {"大蒜2-3瓣切末", "大蒜两到三瓣切末"},
            {"加入生抽2汤匙", "加入生抽两汤匙"},
            {"空气质量指数AQI 152", "空气质量指数 ei qiu ai一百五十二"},
            {"显卡RTX 4060", "显卡 a er ti ai ke si四零六零"},
            {"系统升级到Android 15后更流畅了", "系统升级到 an zhuo十五后更流畅了"},
            {"00后", "零零后"},
            {"#2024高考# 作文题目出炉", "二零二四高考作文题目出炉"},
            {"碳-14的半衰期", "碳十四的半衰期"},
            {"铀-235可以发生裂变", "铀二三五可以发生裂变"},
            {"补钙2片", "补钙两片"},
            {"每天摄入钠500毫克", "每天摄入钠五百毫克"},
            {"铯137", "铯一三七"},
            {"2H2+O2=2H2O", "二 ai qi二加 ou二等于二 ai qi二 ou"},
            {"Fe2O3是铁锈", "ai fu yi二 ou三是铁锈"},
            {"0.9%的NaCl溶液", "百分之零点九的 en ei xi ai le溶液"},
            {"升级到Win10", "升级到 wen十"},
            {"溶液的pH值", "溶液的 pi ai qi值"},
            // Seen in dev7's held-out part (session 17).
            {"糖、醋、生抽按2:1:1调成酱汁", "糖醋生抽按二比一比一调成酱汁"},
            {"第4节还剩2:35", "第四节还剩两分三十五秒"},
            {"下午3:30开会", "下午三点三十分开会"},
            {"该股报15.60元", "该股报十五点六元"},
            {"2.0版", "二点零版"},
            {"2024Q4营收", "二零二四 qiu四营收"},
        });
    }

    TEST_CASE("a blood pressure, a strength's ratio, a two-digit discount, a count's 万+, frame rates") {
        // Each row but the limits failed on main ca87fb8 (session 18, dev8's tuning misses).
        check_cases({
            {"血压140/90mmHg属于高血压", "血压一百四十比九十毫米汞柱属于高血压"},
            {"他的血压是130/85", "他的血压是一百三十比八十五"},
            {"注射液规格为2ml:0.1g", "注射液规格为两毫升比零点一克"},
            {"会员再享95折", "会员再享九五折"},
            {"已售10万+件", "已售十万加件"},
            {"帧率稳定在60fps", "帧率稳定在六十帧每秒"},
            // The rules' limits: a fraction without a pressure, a discount of one digit or with a point, a
            // plain count after 万, and a colon after a number without a unit.
            {"盐1/2小勺", "盐二分之一小勺"},
            {"全场3.8折起", "全场三点八折起"},
            {"全场8折", "全场八折"},
            {"已售10万件", "已售十万件"},
            {"比分2:1", "比分二比一"},
        });
    }

    TEST_CASE("a seat's row and letter is no floor") {
        // Seen in dev8's held-out part (session 18): 12F was a floor, 十二楼.
        check_cases({
            {"您的座位是7车12F号", "您的座位是七车十二 ai fu号"},
            {"座位在5车3F", "座位在五车三 ai fu"},
            // A floor stays one: no 号 after it and no carriage before it.
            {"餐厅在12F", "餐厅在十二楼"},
        });
    }

    TEST_CASE("a seat's letter before 座 or after a numbered carriage is no floor, and Nike is 耐克") {
        // The first four rows fail on main c056d46 (session 45, dev46's tuning misses and Nike's maker's
        // neighbour): 十二楼, 三樓, nai qi, e di de si.
        check_cases({
            {"您的座位在3号车厢12F座", "您的座位在三号车厢十二 ai fu座"},
            {"我在5車廂3F", "我在五車廂三 ai fu"},
            {"这双Nike的鞋子", "这双 nai ke的鞋子"},
            {"Adidas的鞋子", "a di da si的鞋子"},
            // The limits: a floor stays one before a place and after a building's block.
            {"会议室在12F", "会议室在十二楼"},
            {"A座12F有餐厅", "ei座十二楼有餐厅"},
        });
    }

    TEST_CASE("a seat named before a row and its letter makes them no floor and no amperes") {
        // The first four rows fail on main 4076fe4 (session 45, text23's leftovers): 十二楼, 三十二安.
        check_cases({
            {"我的座位是12F", "我的座位是十二 ai fu"},
            {"登机牌上写着32A", "登机牌上写着三十二 ei"},
            {"您的座位是32A，请从前门登机", "您的座位是三十二 ei请从前门登机"},
            {"選座時我選了12A，靠窗", "選座時我選了十二 ei靠窗"},
            // The limits: amperes and a floor where no seat is named in the clause.
            {"这个充电器输出2A", "这个充电器输出两安"},
            {"座位很舒服，餐厅在12F", "座位很舒服餐厅在十二楼"},
        });
    }

    TEST_CASE("a row and its letter sat in, a window's or an aisle's, or a 位子 is a seat") {
        // The first five rows fail on main bea23b7 (session 46): 三十二安, 十二楼, 十二安, 三十一安, 十五安.
        check_cases({
            {"我坐32A，你坐32B", "我坐三十二 ei你坐三十二 bi"},
            {"他坐在12F", "他坐在十二 ai fu"},
            {"我要靠窗的12A", "我要靠窗的十二 ei"},
            {"我換到靠走道的31A", "我換到靠走道的三十一 ei"},
            {"我们的位子是15A", "我们的位子是十五 ei"},
            // The limits: sitting elsewhere names no seat, nor does a window far from the number's clause.
            {"我坐电梯到12F", "我坐电梯到十二楼"},
            {"坐下来，充电器输出2A", "坐下来充电器输出两安"},
        });
    }

    TEST_CASE(
        "a pack's unit, a unit per a measure word, a building's 号, a card's groups, a range's 零下, x and "
        "w") {
        // Each row but the limits failed on main 2d28134 (session 19, dev9's tuning misses).
        check_cases({
            {"每箱6×1.5L", "每箱六乘一点五升"},
            {"一箱12×2L", "一箱十二乘两升"},
            {"整箱24×330ml/箱", "整箱二十四乘三百三十毫升每箱"},
            {"规格：0.5g/片", "规格零点五克每片"},
            {"每次10mg/次", "每次十毫克每次"},
            {"他住在3号楼502", "他住在三号楼五零二"},
            {"银行卡号：6217 0001 2345 6789", "银行卡号六二一七零零零一二三四五六七八九"},
            {"气温在-5至3度之间", "气温在零下五至三度之间"},
            {"气温-8到2℃", "气温零下八到两摄氏度"},
            {"奖励钻石x300", "奖励钻石乘三百"},
            {"粉丝涨到3w了", "粉丝涨到三万了"},
            {"已售1.5w件", "已售一点五万件"},
            // The rules' limits: a lesson's variable, a count without 号 or a unit, a sign without a
            // temperature, a phone's groups, a letter after the w, a product without a unit.
            {"两根为x1、x2", "两根为 ai ke si一 ai ke si二"},
            {"已知x1=2", "已知 ai ke si一等于二"},
            {"3号楼有120户", "三号楼有一百二十户"},
            {"向左旋转-30至30度", "向左旋转负三十至三十度"},
            {"电话 010 1234 5678", "电话零幺零幺二三四五六七八"},
            {"分辨率1920×1080", "分辨率一千九百二十乘一千零八十"},
        });
    }

    TEST_CASE("a pickup code's groups after its name, a range mark between two quantities with their units") {
        // Seen in dev9's held-out part (session 19): 三二幺幺零八 dialled, and the tilde silent.
        check_cases({
            {"取件码12-3-4021", "取件码一二杠三杠四零二一"},
            {"提货码：5-1-2033", "提货码五杠一杠二零三三"},
            {"夜间气温-10℃~-2℃", "夜间气温零下十摄氏度到零下两摄氏度"},
            {"每天跑5km-10km", "每天跑五公里到十公里"},
            // The limits: a phone's groups after 号码, three groups without a name before them, a second
            // end without the unit.
            {"号码：010-1234-5678", "号码零幺零幺二三四五六七八"},
            {"请拨3-2-1108", "请拨三二幺幺零八"},
        });
    }

    TEST_CASE(
        "arrows and ±, a range's one percent sign, listed years, small w and k, 9494, 我+1, ISBNs, vs") {
        // Each row but the limits failed on main d81690e (session 20, dev10's tuning misses).
        check_cases({
            {"宁德时代↑3.2%，比亚迪↓1.5%", "宁德时代涨百分之三点二比亚迪跌百分之一点五"},
            {"测量误差为±0.5mm", "测量误差为正负零点五毫米"},
            {"北京→上海的高铁", "北京到上海的高铁"},
            {"房价同比下跌5~8%", "房价同比下跌百分之五到八"},
            {"2022、2023年连续增长", "二零二二二零二三年连续增长"},
            {"这款充电头功率5w", "这款充电头功率五瓦"},
            {"应届生月薪8k", "应届生月薪八千"},
            {"9494，我也是这么想的", "九四九四我也是这么想的"},
            {"我+1，明天一起去", "我加一明天一起去"},
            {"本书ISBN 978-7-02-008701-9", "本书 ai ai si bi en九七八杠七杠零二杠零零八七零一杠九"},
            {"ISBN 9787020087019", "ai ai si bi en九七八七零二零零八七零一九"},
            {"湖人vs勇士", "湖人 wei ai si勇士"},
            // Found by hand, in no set: an item's upgrade level, a spec sheet's sum of parts.
            {"装备强化+12成功", "装备强化加十二成功"},
            {"5000万像素主摄+1200万超广角", "五千万像素主摄加一千二百万超广角"},
            {"CPU是i7-13700H", "xi pi you是 ai七一三七零零 ai qi"},
            // The rules' limits: a sign on each end, a chat's w without a word of power, a k of a picture,
            // a sign that closes no agreement, a count listed before another, a pair that counts.
            {"增长10%-20%", "增长百分之十到百分之二十"},
            {"存够5w就去旅游", "存够五万就去旅游"},
            {"这块4k屏很清晰", "这块四 kei屏很清晰"},
            {"温差+1", "温差正一"},
            {"人数分别为100、200人", "人数分别为一百二百人"},
            {"共9494人", "共九千四百九十四人"},
        });
    }

    TEST_CASE(
        "a runner's k, a game's clear time and a wait, an aircraft's variant, a lamp's w, star ratings") {
        // Each row but the limits failed on main 8650c86 (session 21, dev11's tuning misses).
        check_cases({
            {"今天晨跑跑了个5k", "今天晨跑跑了个五公里"},
            {"周末的5K趣味跑", "周末的五公里趣味跑"},
            {"通关时间：02:35", "通关时间两分三十五秒"},
            {"预计等待时间05:20", "预计等待时间五分二十秒"},
            {"预计等待时间00:45", "预计等待时间四十五秒"},
            {"一架空客A320-200客机", "一架空客 ei三二零二百客机"},
            {"这架波音737-800", "这架波音七三七八百"},
            // Found by hand, in no set: a newer family's variant of one digit.
            {"波音737-8复飞", "波音七三七八复飞"},
            {"买了一个5w的台灯", "买了一个五瓦的台灯"},
            {"这个灯泡才3w", "这个灯泡才三瓦"},
            {"评分★★★★☆", "评分四星"},
            {"酒店为★★★★★级", "酒店为五星级"},
            {"沪A·8K321的车辆", "沪 ei八 kei三二一的车辆"},
            {"笑死我了233", "笑死我了二三三"},
            {"今天上分+50", "今天上分加五十"},
            {"mRNA疫苗", "ai mu a er en ei疫苗"},
            {"我只能orz了", "我只能 ou a er zei了"},
            // The rules' limits: a k of money or a picture, a clock after a wait without the timer's zero, a
            // range of models, a lantern show's 灯 and a count's measure word, a sign of no score.
            {"月薪8k", "月薪八千"},
            {"这个4K视频", "这个四 kei视频"},
            {"等待时间：12:30开始", "等待时间十二点三十分开始"},
            {"RTX 3060-4090", "a er ti ai ke si三零六零到四零九零"},
            {"灯会现场来了5w游客", "灯会现场来了五万游客"},
            {"灯光秀吸引了5w人", "灯光秀吸引了五万人"},
            {"我考了233", "我考了二百三十三"},
            {"温差+1", "温差正一"},
        });
    }

    TEST_CASE(
        "empty star rows, a rating star, a pace in primes, KDA in slashes, 999+, listed scores, tickers") {
        // Each row but the limits failed on main b61459a (session 22, dev12's tuning misses).
        check_cases({
            {"这家店我只给☆☆☆☆☆", "这家店我只给零星"},
            {"差评☆☆☆☆☆，再也不来了", "差评零星再也不来了"},
            {"评分：★，不推荐", "评分一星不推荐"},
            {"他今天配速5'30\"", "他今天配速五分三十秒"},
            {"半马平均配速4'45\"/km", "半马平均配速四分四十五秒每公里"},
            {"她的配速稳定在6′05″", "她的配速稳定在六分零五秒"},
            {"我KDA 12/3/5", "我 kei di ei十二杠三杠五"},
            {"群里有999+条消息", "群里有九百九十九加条消息"},
            {"比分为25-18、25-20、25-22", "比分为二十五比十八二十五比二十二十五比二十二"},
            {"特斯拉（$TSLA）大涨", "特斯拉 ti ai si ai le ei大涨"},
            // The rules' limits: a record of two parts, a cheer of one digit, a list of ranges, dollars.
            {"战绩3/5", "战绩五分之三"},
            {"666，太秀了", "六六六太秀了"},
            {"666+1", "六六六加一"},
            {"第5-8名、第10-12名", "第五到八名第十到十二名"},
            {"一杯$5", "一杯五美元"},
        });
        // A lone star where nothing rates is a decoration or a mark, unsaid and warned of.
        const auto decorated = read_transcript("★重要通知★ 请给☆标记的题目打钩。", {}, "t.txt");
        CHECK(said(decorated) == "重要通知请给标记的题目打钩");
        CHECK(decorated.warnings.size() == 3);
        CHECK(read_transcript("特斯拉（$TSLA）大涨。", {}, "t.txt").warnings.empty());
    }

    TEST_CASE(
        "a landmark after its city, a height in primes, 两兆, a player's record, a count after ×, + between "
        "words") {
        // Each row but the limits failed on main 0d8cc91 (session 23: session 22's leftovers and dev13's
        // tuning misses).
        check_cases({
            {"台北101今晚將點燈", "台北一零一今晚將點燈"},
            {"北京798艺术区", "北京七九八艺术区"},
            {"台北市101很高", "台北市一零一很高"},
            {"他身高6'2\"，", "他身高六英尺两英寸"},
            {"只有5′7″。", "只有五英尺七英寸"},
            {"身高5'10\"。", "身高五英尺十英寸"},
            {"總額為2兆9,000億元", "總額為兩兆九千億元"},
            {"这把我0-8，太坑了", "这把我零杠八太坑了"},
            {"内含金币×888。", "内含金币乘八百八十八"},
            {"关注+转发，抽3位", "关注加转发抽三位"},
            // The rules' limits: a count after a city, a round thousand, a pace, a range, a team's score, a
            // product's 2.
            {"上海101人确诊", "上海一百零一人确诊"},
            {"北京300多所高校", "北京三百多所高校"},
            {"深圳500强企业", "深圳五百强企业"},
            {"上海3000，", "上海三千"},
            {"配速5'10\"", "配速五分十秒"},
            {"我3-5天后到", "我三到五天后到"},
            {"我们2-1赢了", "我们二比一赢了"},
            {"金币×2", "金币乘二"},
        });
    }

    TEST_CASE("a pair listed before a score is one too, as a list of sets ends with its result") {
        // The first two rows failed on main 5842241 (session 23's held-out miss: 六到四、三到六).
        check_cases({
            {"他以6-4、3-6、7-5赢下比赛。", "他以六比四三比六七比五赢下比赛"},
            {"她以2-6、6-3、6-4胜出", "她以二比六六比三六比四胜出"},
            // The rule's limits: a list of ranges, a range closing a list (a measure word after it).
            {"第5-8名、第10-12名", "第五到八名第十到十二名"},
            {"每组3-5、5-7人", "每组三到五五到七人"},
        });
    }

    TEST_CASE(
        "a pair right after a player's pronoun, closing its clause, in a clause naming a match is a score") {
        // The first two rows failed on main 5842241 (三到一, 二到零: session 23 left them as ranges).
        check_cases({
            {"决赛他3-1，", "决赛他三比一"},
            {"比賽她2-0。", "比賽她二比零"},
            // The rule's limits: a record outside a match, a range with its measure word.
            {"这把我0-8，", "这把我零杠八"},
            {"决赛他3-5天后到", "决赛他三到五天后到"},
        });
    }

    TEST_CASE("a side's pronoun (他们 她們) before such a pair is a player's") {
        check_cases({
            {"决赛他们3-1，", "决赛他们三比一"},
            {"比賽她們2-0。", "比賽她們二比零"},
            {"决赛他们3-5天后到", "决赛他们三到五天后到"},
        });
    }

    TEST_CASE("a game's opening score, a pair right before 开局, is a score") {
        // The first two rows failed on main 348e35c (二到五, 零到三: ranges).
        check_cases({
            {"这把2-5开局，", "这把二比五开局"},
            {"這把0-3開局", "這把零比三開局"},
            // The rule's limit: a range with its measure word before 开局.
            {"3-5分钟开局", "三到五分钟开局"},
        });
    }

    TEST_CASE("a subtitle's dash before a speaker's turn is no minus sign, where the line opens with one") {
        // The first two rows failed on main 348e35c (负十二, 负两个).
        check_cases({
            {"-明天几号？-12号，周五。", "明天几号十二号周五"},
            {"-你要几个？ -2个就够了。", "你要几个两个就够了"},
            // A line of one dash keeps its sign, and so does a dash inside a sentence.
            {"-5℃，晴。", "零下五摄氏度晴"},
            {"-好的。气温-3℃。", "好的气温零下三摄氏度"},
        });
    }

    TEST_CASE(
        "a consonant letter before a word the dictionary has, starting no syllable with it, is the letter "
        "and the word") {
        // Each row but the last failed on main 5842241 (one syllable of generic speech each, with a warning;
        // mail alone mei).
        check_cases({
            {"我把文件发到你的Gmail了。", "我把文件发到你的 ji mei er了"},
            {"新买的Xbox到了", "新买的 ai ke si ba ke si到了"},
            {"她在拍vlog", "她在拍 wei lo ge"},
            // mail alone as in email, 伊妹儿; the rule's limit: a name's Mc the dictionary has, said by its
            // Chinese name since session 36.
            {"请发mail给我", "请发 mei er给我"},
            {"McLaren车队", "mai kai lun车队"},
        });
        CHECK(read_transcript("我把文件发到你的Gmail了。", {}, "t.txt").warnings.empty());
    }

    TEST_CASE("a motorway's stake, K and its kilometres, a + and the metres, counts") {
        // The first two rows failed on main 5842241 (a model's digits: K 一二三四, K 一零八).
        check_cases({
            {"G15沈海高速K1234+500处双向封闭", "ji十五沈海高速 kei一千二百三十四加五百处双向封闭"},
            {"京港澳高速K108+300处", "京港澳高速 kei一百零八加三百处"},
            // The rule's limits: a model's number without the +, two capitals before it, a stake of two
            // digits.
            {"K1234次列车", "kei幺二三四次列车"},
            {"SK1234+5", "ai si kei一二三四加五"},
            {"K35+200处", "kei三十五加二百处"},
        });
    }

    TEST_CASE("a fix right after a written form replaces its reading, in characters or pinyin") {
        CHECK(said("2026{两千零二十六}年") == "两千零二十六年");
        CHECK(pinyin_of("OK{ou1 kei4}") == "ou1 kei4");
        CHECK(pinyin_of("3:30{san1 dian3 ban4}") == "san1 dian3 ban4");
        const auto timeline = read_transcript("共2026{两千 零二十六}人");
        REQUIRE(timeline.written_forms.size() == 1);
        CHECK(timeline.written_forms[0].text == "2026");
        CHECK(timeline.written_forms[0].syllable_count == 6);
        CHECK(timeline.sentences[0].text == "共2026人");
        CHECK(said(timeline) == "共两千零二十六人");
    }

    TEST_CASE("a bad fix of a written form is an error naming it and where it stands") {
        CHECK_THROWS_WITH_AS(read_transcript("买2026{xyz9}个", {}, "t.txt"),
                             doctest::Contains("t.txt:1:6: reading fix \"{xyz9}\" for \"2026\""), ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("OK{}", {}, "t.txt"), doctest::Contains("the fix is empty"), ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("5{★}", {}, "t.txt"),
                             doctest::Contains("neither a Chinese character with a reading nor numbered pinyin"),
                             ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("5 {wu3}", {}, "t.txt"), doctest::Contains("must directly follow"),
                             ParseError);
    }

    TEST_CASE("a number of more than 16 digits is read digit by digit with a warning") {
        const std::string digits = "12345678901234567";
        const auto timeline = read_transcript("号码是" + digits + "。", {}, "t.txt");
        CHECK(said(timeline) == "号码是一二三四五六七八九零一二三四五六七");
        REQUIRE(timeline.warnings.size() == 1);
        CHECK(timeline.warnings[0] ==
              "t.txt:1:4: \"" + digits + "\": a number of more than 16 digits; read digit by digit");
        const auto long_decimal = read_transcript(std::string(40, '9') + ".5");
        CHECK(long_decimal.syllables.size() == 42);
        CHECK(long_decimal.warnings.size() == 1);
        // Every form a long run of digits can stand in is read digit by digit with a warning,
        // never thrown on (a date's day was parsed as a number and overflowed).
        const std::string long_run(24, '7');
        for (const auto& form :
             {"2026-12-" + long_run, "2026/12/" + long_run, long_run + ":30", "3:" + long_run,
              long_run + "×2", "1.2." + long_run, "2026.03." + long_run, long_run + "-3=1",
              "比分" + long_run + "-1", "+86 " + long_run, "010-" + long_run, long_run + "万km",
              "今天是" + long_run, long_run + "会议室", "CA" + long_run + "航班", "2e" + long_run,
              "学习率1e-" + long_run}) {
            CAPTURE(form);
            const auto read = read_transcript(form);
            CHECK(read.warnings.size() == 1);
            CHECK(said(read).find(std::string(long_run.size(), ' ')) == std::string::npos);
            CHECK(said(read).find("七七七七七七七七七七七七七七七七七七七七七七七七") != std::string::npos);
        }
        const auto sixteen = read_transcript("1234567890123456");
        CHECK(sixteen.warnings.empty());
        CHECK(said(sixteen).find("万") != std::string::npos);
    }

    TEST_CASE("a plus between a Latin word or a number and a word, and in a plan's quoted X+, is 加") {
        // The first three failed on main 61e9b85 (session 26: the + skipped with a warning).
        check_cases({
            {"AI+教育", "ei ai加教育"},
            {"5G+工业互联网", "五 ji加工业互联网"},
            {"推进“互联网+”行动", "推进互联网加行动"},
            {"关注+转发", "关注加转发"},
        });
    }

    TEST_CASE("an angle's minutes with their prime and no seconds are 分") {
        // The first two failed on main 61e9b85 (session 26: the prime skipped, 二十三).
        check_cases({
            {"东经116°23′", "东经一百一十六度二十三分"},
            {"北纬39°54'", "北纬三十九度五十四分"},
            {"东经116°23′17″", "东经一百一十六度二十三分十七秒"},
        });
    }

    TEST_CASE("a round hundred after capitals is a tier, as a round thousand is") {
        // The first two failed on main 61e9b85 (session 26, dev16's HDR400: 四零零).
        check_cases({
            {"支持HDR400", "支持 ai qi di a er四百"},
            {"英伟达A100芯片", "英伟达 ei一百芯片"},
            // The limits: a train's and a flight's number, a model's number that is no round hundred.
            {"G100次列车", "ji幺零零次列车"},
            {"乘坐CA100航班", "乘坐 xi ei幺零零航班"},
            {"空客A380", "空客 ei三八零"},
        });
    }

    TEST_CASE(
        "a match's sets listed with colons, a period's days with 至, Latin words that split into "
        "interjections") {
        // Each row but the limits failed on main 61e9b85 (session 26, dev16's tuning misses and a leftover).
        check_cases({
            {"比分为23:25、25:20、22:25、15:12", "比分为二十三比二十五二十五比二十二十二比二十五十五比十二"},
            {"活動期間為12/1至12/31，憑發票", "活動期間為十二月一日至十二月三十一日憑發票"},
            // Session 27: Elon said as Mandarin news says it, 埃隆 (session 26 read el + on, ai er an).
            {"马斯克（Elon Musk）", "马斯克 ai long ma si ke"},
            // The limits: times listed with no score named, fractions joined by 至.
            {"比赛时间为19:30、21:00", "比赛时间为十九点三十分二十一点"},
            {"比例在1/3至2/3之间", "比例在三分之一至三分之二之间"},
        });
        // A line of Latin words alone: team splits as te a m, but m is only an interjection's syllable; an
        // interjection alone and pinyin that holds none stay pinyin.
        CHECK(pinyin_of("Zoom team camp") == "zu1 mu5 ti1 mu5 kan1 pu5");
        CHECK(pinyin_of("wo men hm") == "wo5 men5 hm5");
    }

    TEST_CASE("a phone's data and memory in G, a release's 24H2, a model's o1, Elon, a line in English") {
        // Each row but the limits failed on main 5bb18ac (session 27, dev17's tuning misses and session 26's
        // leftovers).
        check_cases({
            {"我手机只剩2G流量了", "我手机只剩两 ji流量了"},
            {"这台手机只有2G内存", "这台手机只有两 ji内存"},
            {"升级到Windows 11 24H2后", "升级到 wen dou si十一二四 ai qi二后"},
            {"25Q1营收同比增长", "二五 qiu一营收同比增长"},
            {"OpenAI发布了o1模型", "ou pen ei ai发布了 ou一模型"},
            {"Elon Musk发文称", "ai long ma si ke发文称"},
            // The limits: a network's generation, a year's half, numbered pinyin's o5 and a4 among
            // characters.
            {"这是2G网络", "这是二 ji网络"},
            {"2025H1营收", "二零二五 ai qi一营收"},
            {"这里o5 fa5 si5", "这里 o5 fa5 si5"},
            {"字母R读a4 er5", "字母 a er读 a4 er5"},
        });
        // A line of English whose words the dictionary has though they split into pinyin (can, man, see);
        // a line of pinyin with a name or a brand in it stays pinyin.
        CHECK(pinyin_of("I can fix it.") == "ai4 kan1 fei1 ke5 si5 yi1 te5");
        CHECK(pinyin_of("The man can see.") == "de5 man1 kan1 si1");
        CHECK(pinyin_of("wo xi huan iPhone") == "wo5 xi5 huan5 ai1 feng5");
        CHECK(pinyin_of("ni hao Tom") == "ni5 hao5 ta1 mu5");
        CHECK(pinyin_of("Zhang Wei, Li Na") == "zhang5 wei5 li5 na5");
    }

    TEST_CASE(
        "a signed change after 同比 or 环比 is a rise or a fall, after 涨跌幅 a sign, after an index a "
        "fall") {
        check_cases({
            {"营收同比+15%，环比-3.2%", "营收同比增长百分之十五环比下降百分之三点二"},
            {"营收同比 +5%", "营收同比增长百分之五"},
            {"CPI环比+0.4%", "xi pi ai环比上涨百分之零点四"},
            {"消费价格同比-0.3%，环比+0.1%", "消费价格同比下降百分之零点三环比上涨百分之零点一"},
            {"毛利率同比+0.5个百分点", "毛利率同比提高零点五个百分点"},
            {"该股涨跌幅+2.35%", "该股涨跌幅正百分之二点三五"},
            {"今日恒指-0.8%", "今日恒指跌百分之零点八"},
            // A comparison with an earlier time is one too.
            {"利润较上年-12%", "利润较上年下降百分之十二"},
            {"毛利率较去年同期+1.8个百分点", "毛利率较去年同期提高一点八个百分点"},
            // The limits: a change already named, a rate's or a value's sign, a loss.
            {"同比增长+12.3%", "同比增长百分之十二点三"},
            {"收益率为-12.35%", "收益率为负百分之十二点三五"},
            {"涨跌幅-1.87%", "涨跌幅负百分之一点八七"},
            {"净利润-12亿元", "净利润负十二亿元"},
        });
    }

    TEST_CASE(
        "a code after a name's hyphen and a card's number before its suffix, a slash after a power, a size") {
        check_cases({
            {"mRNA-1273疫苗", "ai mu a er en ei一二七三疫苗"},
            {"当年的9800 GT显卡", "当年的九八零零 ji ti显卡"},
            {"速度约为2×10⁷米/秒", "速度约为二乘十的七次方米每秒"},
            {"Qwen2.5-72B大模型", "qian wen二点五七十二 bi大模型"},
            {"开源了Llama-3-8B", "开源了 la ma三八 bi"},
            // The limits: two digits after the hyphen, a price, a range after a word.
            {"COVID-19疫情", "kou wei de十九疫情"},
            {"售价8800元", "售价八千八百元"},
            {"参数量为3-5B", "参数量为三到五 bi"},
        });
    }

    TEST_CASE(
        "a card's suffix in small letters and Ti, two sizes with a slash, an amount's signed change, "
        "TikTok, stoppage time") {
        check_cases({
            {"我还留着一块8800gt", "我还留着一块八八零零 ji ti"},
            {"显卡是RTX 4070 Ti", "显卡是 a er ti ai ke si四零七零 ti ai"},
            {"老显卡1080ti", "老显卡一零八零 ti ai"},
            {"开源了8B/70B两个版本", "开源了八 bi和七十 bi两个版本"},
            {"净利润-5%，营收+3%", "净利润下降百分之五营收增长百分之三"},
            {"他在TikTok上", "他在 ti ke tuo ke上"},
            {"第90+2分钟绝杀", "第九十加二分钟绝杀"},
            // The limits: a price counts, a byte unit's slash is unsaid, a loss keeps its sign, an index
            // falls.
            {"售价8800元", "售价八千八百元"},
            {"内存8GB/256GB", "内存八 ji bi二百五十六 ji bi"},
            {"净利润-12亿元", "净利润负十二亿元"},
            {"今日恒指-0.8%", "今日恒指跌百分之零点八"},
        });
    }

    TEST_CASE(
        "a Roman numeral in letters, a card named again, a list of sizes, a lobby's count, 24/7, E "
        "notation") {
        check_cases({
            {"他患有II型糖尿病", "他患有二型糖尿病"},
            {"文集的第IV卷", "文集的第四卷"},
            {"这块RTX 3090用了三年，我打算换4090", "这块 a er ti ai ke si三零九零用了三年我打算换四零九零"},
            {"该模型有1.5B/7B/32B三个版本", "该模型有一点五 bi七 bi和三十二 bi三个版本"},
            {"3=1，来个人", "三等一来个人"},
            {"客服24/7在线", "客服二十四七在线"},
            {"学习率设为1e-3", "学习率设为一乘十的负三次方"},
            // The limits: letters among letters stay letters, a count beside a card counts, a sum says 等于,
            // a fraction stays one, a hex code keeps its letters.
            {"IVF技术", "ai wei ai fu技术"},
            {"RTX 4090售价2060元", "a er ti ai ke si四零九零售价两千零六十元"},
            {"1+2=3", "一加二等于三"},
            {"24/5", "五分之二十四"},
        });
    }

    TEST_CASE("session 28's leftovers: = before ±, a version before 下, a card's number before 升到") {
        check_cases({
            {"方程的解为x=±3", "方程的解为 ai ke si等于正负三"},
            {"这个脚本在Python 3.11下运行", "这个脚本在 pai san三点十一下运行"},
            {"他的显卡从RTX 2060升到了3060", "他的显卡从 a er ti ai ke si二零六零升到了三零六零"},
            // The limits: a decimal before 下 stays a decimal, litres stay litres.
            {"指数收在3.11下方", "指数收在三点一一下方"},
            {"每天饮水2升为宜", "每天饮水两升为宜"},
        });
    }

    TEST_CASE("a figure's or a table's number in a textbook") {
        check_cases({
            {"如图3-2所示", "如图三杠二所示"},
            {"由表2-1可知", "由表二杠一可知"},
            {"见图1-4，", "见图一杠四"},
            // The limits: a range that counts after 表 stays one.
            {"发表3-5篇论文", "发表三到五篇论文"},
            {"代表3-5人", "代表三到五人"},
        });
    }

    TEST_CASE("an approximate count written with 、") {
        check_cases({
            {"屋里坐着3、4个人", "屋里坐着三四个人"},
            {"他等了2、3天", "他等了两三天"},
            {"70、80年代出生的人", "七八十年代出生的人"},
            {"团队有30、40个人", "团队有三四十个人"},
            // The limits: an ordinal's list and an ordering measure keep the list, a countdown is no count.
            {"第2、3名", "第二三名"},
            {"住在2、3层", "住在二三层"},
            {"准备，3、2、1！", "准备三二一"},
        });
    }

    TEST_CASE("the dot in a lineage's name ends no sentence") {
        CHECK(read_transcript("目前流行的主要毒株为XBB.1.5。后来又出现了新的毒株。").sentences.size() == 2);
        CHECK(said("毒株为XBB.1.5。") == "毒株为 ai ke si bi bi一点五");
        CHECK(read_transcript("BA.2传播更快。").sentences.size() == 1);
        // A capital alone before a dot and a digit is no lineage's: a choice's or an initial's dot.
        CHECK(read_transcript("答案是A.2后来改了。").sentences.size() == 2);
    }

    TEST_CASE("the dots of an initialism end no sentence") {
        // The first three checks failed on main 3fee0f9 (session 33, dev32): cut after K. and after O.
        CHECK(read_transcript("一套连招直接K.O.！").sentences.size() == 1);
        CHECK(said("他被K.O.了") == "他被 kei ou了");
        CHECK(read_transcript("J.K.罗琳出新书了。后来又出了一本。").sentences.size() == 2);
        // The limits: a letter alone before a dot with no other beside it, and a word before one.
        CHECK(read_transcript("答案选A.不对。").sentences.size() == 1);
        CHECK(read_transcript("版本x.y").sentences.size() == 2);
        CHECK(read_transcript("他来了. 我走了.").sentences.size() == 2);
    }

    TEST_CASE("a toll's dead and injured are counted with 两") {
        // Each row but the limits failed on main 1e85796 (session 29, dev21's tuning miss): 二死, 二伤.
        check_cases({
            {"已致2死5伤", "已致两死五伤"},
            {"事故造成1死2伤", "事故造成一死两伤"},
            {"車禍釀2死1傷", "車禍釀兩死一傷"},
            // The limit: 2 before a name's word stays 二.
            {"2号线", "二号线"},
        });
    }

    TEST_CASE("SaaS and PaaS are said as words") {
        // Each row failed on main 1e85796 (session 29, dev21's tuning miss): Saa and S, de ai si.
        check_cases({
            {"国内SaaS企业", "国内 sa si企业"},
            {"PaaS平台", "pa si平台"},
        });
    }

    TEST_CASE("a year by its last two digits before a month is said digit by digit") {
        // The first and third rows failed on main 1e85796 (session 29, found by probing news beyond dev21):
        // 二十四年, 二十五年; 08 was 零八 already.
        check_cases({
            {"24年12月5日，公司发布公告", "二四年十二月五日公司发布公告"},
            {"08年8月8日", "零八年八月八日"},
            {"该项目将于25年6月至26年1月完工", "该项目将于二五年六月至二六年一月完工"},
            // The limits: years counted, a year of the Republic after 民国 and in a Traditional transcript.
            {"这是23年以来的最高水平", "这是二十三年以来的最高水平"},
            {"他服刑12年3个月", "他服刑十二年三个月"},
            {"民国38年10月", "民国三十八年十月"},
            {"88年9月21日發生大地震", "八十八年九月二十一日發生大地震"},
        });
    }

    TEST_CASE("names in the news said as Mandarin news writes them, a chip's series in Latin letters") {
        // Each row failed on main 1e85796 (session 29, found by probing news beyond dev21): generic speech
        // (Sora, Bezos, Ethereum, Zeekr), the mapping (ai de mi, si na pu da gen), the number counted.
        check_cases({
            {"Sora正式开放", "suo la正式开放"},
            {"杰夫·贝索斯（Jeff Bezos）", "杰夫贝索斯 jie fu bei suo si"},
            {"Ethereum价格上涨", "yi tai fang价格上涨"},
            {"极氪Zeekr", "极氪 ji ke"},
            {"Redmi K80", "hong mi kei八十"},
            {"Snapdragon 865处理器", "xiao long八六五处理器"},
            {"联发科Dimensity 9400芯片", "联发科 tian ji九四零零芯片"},
            {"Boeing 737客机", "bo yin七三七客机"},
            // The limit: a round thousand is a tier, as after 麒麟.
            {"Kirin 9000芯片", "qi lin九千芯片"},
        });
    }

    TEST_CASE("a case as health news counts it, a foreign company by its Chinese name") {
        // The first four rows fail on main 18103f3 (session 38, dev40's tuning misses and session 37's
        // leftover): 二例, 二宗, ai ba si, bo ying.
        check_cases({
            {"新增2例境外移入病例", "新增两例境外移入病例"},
            {"過去24小時新增2宗個案", "過去二十四小時新增兩宗個案"},
            {"Airbus公布订单", "kong ke公布订单"},
            {"Boeing与Airbus", "bo yin与 kong ke"},
            // The limits: an ordinal keeps 二.
            {"第2例患者", "第二例患者"},
        });
    }

    TEST_CASE("a worked example's number in a textbook is said with 杠") {
        // The first two rows failed on main 532928e (session 30, dev24's tuning miss): 三到二, 一到两.
        check_cases({
            {"请看例3-2，这是一道追及问题", "请看例三杠二这是一道追及问题"},
            {"如例1-2所示", "如例一杠二所示"},
            // The limits: cases count, and a range before a measure word stays one.
            {"病例3-5", "病例三到五"},
            {"举例3-5个", "举例三到五个"},
        });
    }

    TEST_CASE("an approximate count after a verb's 了 before an ordering measure") {
        // The first two rows failed on main 532928e (session 30, dev24's tuning miss): 二三期, 二三层.
        check_cases({
            {"这个综艺我只看了2、3期", "这个综艺我只看了两三期"},
            {"爬了2、3层楼", "爬了两三层楼"},
            // The limits: floors named and an ordinal's list stay lists.
            {"2、3层为办公区", "二三层为办公区"},
            {"第2、3期", "第二三期"},
        });
    }

    TEST_CASE("a list of generations is said digit by digit") {
        // The first two rows failed on main 532928e (session 30, dev24's tuning miss): 八十, 七十 八十.
        check_cases({
            {"80、90后是主要用户", "八零九零后是主要用户"},
            {"70、80、90后都爱用", "七零八零九零后都爱用"},
            // The limit: decades before 年代 are an approximate count.
            {"80、90年代", "八九十年代"},
        });
    }

    TEST_CASE("a work schedule, 996 and 955, is said digit by digit") {
        // The first two rows failed on main 532928e (session 30, dev24's tuning miss): 九百九十六,
        // 九百五十五.
        check_cases({
            {"又是996的一周", "又是九九六的一周"},
            {"拒绝955", "拒绝九五五"},
            // The limits: a price, a measure and an ordinal count.
            {"售价996", "售价九百九十六"},
            {"996元一件", "九百九十六元一件"},
            {"第996名", "第九百九十六名"},
        });
    }

    TEST_CASE("< and > after a word or opening a clause bound a measured number") {
        // The first three rows failed on main 532928e (session 30, dev24's tuning miss): the sign unsaid.
        check_cases({
            {"及格，<60分为不及格", "及格小于六十分为不及格"},
            {"体温>38.5℃要就医", "体温大于三十八点五摄氏度要就医"},
            {"每片<5mg", "每片小于五毫克"},
            // The limits: brackets around words or a number, and a chat's heart, are unsaid.
            {"<标题>", "标题"},
            {"选项<1>", "选项一"},
            {"爱你<3", "爱你三"},
        });
    }

    TEST_CASE("a game's debuff, a - after an attribute, is 减") {
        // The first three rows failed on main 532928e (session 30, found by probing beyond dev24): 跌, 负.
        check_cases({
            {"攻击力-10%", "攻击力减百分之十"},
            {"移速-15%，持续3秒", "移速减百分之十五持续三秒"},
            {"防御-5", "防御减五"},
            {"攻击力+15", "攻击力加十五"},
            // The limits: a value's sign after a word in 值, a market's fall, a temperature.
            {"基金净值-2%", "基金净值负百分之二"},
            {"恒指-0.8%", "恒指跌百分之零点八"},
            {"体温-2℃", "体温零下两摄氏度"},
        });
    }

    TEST_CASE("÷ between two words is 除以") {
        // The first two rows failed on main 532928e (session 30, found by probing beyond dev24): skipped
        // with a warning.
        check_cases({
            {"总价÷数量=单价", "总价除以数量等于单价"},
            {"体重(kg)÷身高", "体重 kei ji除以身高"},
            {"12÷3=4", "十二除以三等于四"},
        });
    }

    TEST_CASE("markets, funds and rates in capitals said by their Mandarin names, and PHEIC, IaaS and Gen") {
        // Each row failed on main 532928e (session 30, dev23 and session 29's leftovers): the dictionary's
        // na zi da ke, ou pai ke, ai ci, hai ba, jie ne e; generic speech for SHIBOR and PHEIC; de ai si.
        check_cases({
            {"NASDAQ指数收涨", "na si da ke指数收涨"},
            {"OPEC+宣布减产", "ou pei ke加宣布减产"},
            {"公募REITs上涨", "公募 rui ci上涨"},
            {"3个月HIBOR升至高位", "三个月 hai bo升至高位"},
            {"隔夜SHIBOR下行", "隔夜 xi bo下行"},
            {"疫情构成PHEIC", "疫情构成 fei ke"},
            {"提供IaaS服务", "提供 ai ei ei ai si服务"},
            {"骁龙8 Gen 3处理器", "骁龙八 zhen三处理器"},
        });
    }

    TEST_CASE("a price per a unit written in Latin letters, and a battery's watt-hours") {
        // Each row but the limits failed on main 532928e (session 30, dev23): the symbol was spelled after an
        // unsaid slash (元 da bu liu, 元 kei da ba lu ei qi), Wh was W and h.
        check_cases({
            {"光伏组件价格跌至0.7元/W", "光伏组件价格跌至零点七元每瓦"},
            {"电价为0.5元/kWh", "电价为零点五元每千瓦时"},
            {"租金3元/m²", "租金三元每平方米"},
            {"停车费10元/h", "停车费十元每小时"},
            {"能量密度达160Wh/kg", "能量密度达一百六十瓦时每公斤"},
            // The limits: a per unit of Chinese characters and after a byte unit, as before; a letter before
            // a Chinese word is no unit.
            {"25元/公斤", "二十五元每公斤"},
            {"读取速度7000MB/s", "读取速度七千 ai mu bi每秒"},
            {"12元/T恤", "十二元 ti恤"},
        });
    }

    TEST_CASE("a battery cell's format is said digit by digit") {
        // The first four rows failed on main 532928e (session 30, dev23 and session 29's leftover 4680):
        // 四千六百八十, 一万八千六百五十, 两万一千七百, 一万八千六百五十锂电池.
        check_cases({
            {"特斯拉4680大圆柱电池", "特斯拉四六八零大圆柱电池"},
            {"使用了6节18650电芯", "使用了六节一八六五零电芯"},
            {"21700电池", "二一七零零电池"},
            {"18650锂电池", "一八六五零锂电池"},
            // The limits: a round thousand and a capacity's unit count.
            {"2000电池", "两千电池"},
            {"5000mAh电池", "五千毫安时电池"},
        });
    }

    TEST_CASE("a range of a year's quarters or halves is said with 到") {
        // The first three rows failed on main 532928e (session 30, dev23, session 29's leftover 2024Q1-Q3):
        // the dash or ~ unsaid, Q 一 Q 三.
        check_cases({
            {"公司2024Q1-Q3累计净利润", "公司二零二四 qiu一到 qiu三累计净利润"},
            {"Q2~Q4营收", "qiu二到 qiu四营收"},
            {"25Q1-Q2", "二五 qiu一到 qiu二"},
            // The limits: no quarter's number past 4 nor a half's past 2, nor a longer code (H1N1).
            {"Q1-Q12", "qiu一 qiu十二"},
            {"H1N1-H3", "ai qi一 en一 ai qi三"},
        });
    }

    TEST_CASE("a capital, a small letter and a capital are letters") {
        // Each row failed on main 532928e (session 30, dev23): you wai, de qiu, ma mu.
        check_cases({
            {"营收YoY增长8%", "营收 wai ou wai增长百分之八"},
            {"QoQ下降", "qiu ou qiu下降"},
            {"MoM", "ai mu ou ai mu"},
        });
    }

    TEST_CASE("a capital before 系列 is a series' letter, not a unit") {
        // The first row failed on main 532928e (session 30, dev23, session 29's leftover): 二百伏系列.
        check_cases({
            {"英特尔Core Ultra 200V系列处理器", "英特尔 kou a te la二百 wei系列处理器"},
            // The limits: volts before any other word.
            {"800V高压平台", "八百伏高压平台"},
            {"220V电压", "二百二十伏电压"},
        });
    }

    TEST_CASE("a name of two parts joined by & is said whole where the table has it") {
        // The first two rows failed on main 532928e (session 30, dev23): ai si pi and pi ji, the & unsaid
        // with a warning.
        check_cases({
            {"S&P 500指数涨0.9%", "biao pu五百指数涨百分之零点九"},
            {"P&G公布财报", "bao jie公布财报"},
        });
    }

    TEST_CASE("a fiscal year after FY and a year after a quarter are said digit by digit") {
        // The first three rows failed on main 532928e (session 30, probing news beyond dev23): 二十五,
        // 两千零二十四, 两千零二十五.
        check_cases({
            {"FY25营收", "ai fu wai二五营收"},
            {"Q4 2024财报", "qiu四二零二四财报"},
            {"H1 2025", "ai qi一二零二五"},
            {"FY2024", "ai fu wai二零二四"},
            // The limits: a count after a quarter, a number after other capitals.
            {"Q4 2000人", "qiu四两千人"},
            {"Q4 3000", "qiu四三千"},
        });
    }

    TEST_CASE("a charger's volts and current with a slash are said as a pair") {
        // The first three rows failed on main d388cc3 (session 31, dev25): 五伏每二安, and A before a
        // character was a letter, 九伏二 A.
        check_cases({
            {"规格为5V/2A，", "规格为五伏两安"},
            {"支持9V/2A两档输出", "支持九伏两安两档输出"},
            {"输出20V/3.25A", "输出二十伏三点二五安"},
            // The limits: a quantity per another stays 每.
            {"80mg/100ml", "八十毫克每一百毫升"},
            {"220V/50Hz", "二百二十伏每五十赫兹"},
        });
    }

    TEST_CASE("a memory's speed after its generation is a figure of its own") {
        // The first two rows failed on main d388cc3 (session 31, dev25): a range, 五到六千四百, 四到三二零零.
        check_cases({
            {"DDR5-6400内存", "di di a er五六千四百内存"},
            {"DDR4-3200", "di di a er四三千二百"},
            // The limits: a range elsewhere.
            {"3-5天", "三到五天"},
        });
    }

    TEST_CASE("a share's code after its exchange's or its board's name is said digit by digit") {
        // The first three rows failed on main d388cc3 (session 31, dev25): counted, 九十二万零九十九.
        check_cases({
            {"北交所920099今日上市", "北交所九二零零九九今日上市"},
            {"科创板688256今年", "科创板六八八二五六今年"},
            {"创业板300059成交额", "创业板三零零零五九成交额"},
            // The limits: a count after a board's or a market's name.
            {"创业板100家公司", "创业板一百家公司"},
            {"沪市2000只股票", "沪市两千只股票"},
        });
    }

    TEST_CASE(
        "Ryzen, BRICS and ASEAN are said by their Chinese names and a chip's model after its tier digit by "
        "digit") {
        // Each row failed on main d388cc3 (session 31, dev25): generic speech, de de, and e zi en;
        // 九千九百五十.
        check_cases({
            {"Ryzen 9 9950X处理器", "rui long九九九五零 ai ke si处理器"},
            {"BRICS峰会", "jin zhuan峰会"},
            {"ASEAN秘书长", "dong meng秘书长"},
            {"锐龙7 7840HS", "锐龙七七八四零 ai qi ai si"},
        });
    }

    TEST_CASE("a room's number after a wing's or an area's letter is said digit by digit") {
        // The first three rows failed on main d388cc3 (session 31, dev25): counted, 八百零三.
        check_cases({
            {"放到A座803门口", "放到 ei座八零三门口"},
            {"科技大厦C座2107", "科技大厦 xi座二一零七"},
            {"行政楼A区305", "行政楼 ei区三零五"},
            // The limits: a round hundred and a count after an area's letter.
            {"C区200个车位", "xi区二百个车位"},
        });
    }

    TEST_CASE("a year and a month with a dot are a date where the clause names one") {
        // The first three rows failed on main d388cc3 (session 31, dev25): a decimal, 两千零二十七点零三.
        check_cases({
            {"有效期至2027.03。", "有效期至二零二七年三月"},
            {"护照有效期：2019.05-2029.05", "护照有效期二零一九年五月到二零二九年五月"},
            {"自2025.10起施行", "自二零二五年十月起施行"},
            // The limits: a price, and a value where no date is named.
            {"2026.08元", "两千零二十六点零八元"},
            {"期货收于2025.10。", "期货收于两千零二十五点一零"},
        });
    }

    TEST_CASE("a cube root and a fourth root are said and a word's square is 的平方") {
        // The first four rows failed on main d388cc3 (session 31, dev25): ∛ and ∜ skipped with a warning, the
        // ² after a word unsaid.
        check_cases({
            {"∛27=3", "三次根号二十七等于三"},
            {"∜81=3", "四次根号八十一等于三"},
            {"计算∛125+√9", "计算三次根号一百二十五加根号九"},
            {"除以身高²", "除以身高的平方"},
            // The limits: a letter's square and a digit's, as before.
            {"x²", "ai ke si平方"},
            {"3²", "三的平方"},
        });
    }

    TEST_CASE("a masked number is said digit by digit with a star for each masked digit") {
        // The first two rows failed on main d388cc3 (session 31, dev25): the stars skipped, 一百五十九.
        check_cases({
            {"中奖用户：159****0317", "中奖用户幺五九星星星星零三幺七"},
            {"卡号6222****1234", "卡号六二二二星星星星一二三四"},
        });
    }

    TEST_CASE("a place in a whole after 第 is the place and the whole") {
        // The first two rows failed on main d388cc3 (session 31, dev25): a fraction, 第十分之三篇.
        check_cases({
            {"第3/10篇", "第三篇共十篇"},
            {"第27/50关", "第二十七关共五十关"},
            // The limits: a fraction without 第, and a knockout round.
            {"1/3的学生", "三分之一的学生"},
            {"第1/4决赛", "第四分之一决赛"},
        });
    }

    TEST_CASE("a slot's form factor M.2 says its dot") {
        // The first row failed on main d388cc3 (session 31, dev25, and dev23's held-out line): ai mu 二, the
        // dot ending the sentence.
        check_cases({
            {"1个M.2插槽", "一个 ai mu点二插槽"},
            {"U.2固态硬盘", "you点二固态硬盘"},
            // The limits: a lineage's dots, and a choice's letter (the dot in a lineage's name, above).
            {"B.1.1.7毒株", "bi一点一点七毒株"},
        });
        CHECK(read_transcript("答案是A.2后来改了。").sentences.size() == 2);
    }

    TEST_CASE("the @ of a screen's mode between its resolution and its rate is unsaid without a warning") {
        // The first two rows failed on main d388cc3 (session 31, dev25; dev23's 8K@60fps): read so, but with
        // a warning that the @ has no reading.
        check_cases({
            {"显示器支持4K@144Hz", "显示器支持四 kei一百四十四赫兹"},
            {"拍摄1080P@240fps", "拍摄一零八零 pi二百四十帧每秒"},
        });
        // The limits: a mention is still said (艾特).
        CHECK(said("转发@新华社") == "转发艾特新华社");
    }

    TEST_CASE("a standard's number and the year of its edition are said digit by digit") {
        // The first four rows failed on main 7f699e1 (session 31, dev27): a range, 二二一六五到二零二二,
        // ISO's colon a ratio, 比, and YY/T's number dialled, 零二八七二零幺七.
        check_cases({
            {"执行标准：GB/T 22165-2022。", "执行标准 ji bi ti二二一六五杠二零二二"},
            {"依据GB 2762-2022规定", "依据 ji bi二七六二杠二零二二规定"},
            {"通过ISO 14001:2015认证", "通过 ai ai si ou一四零零一二零一五认证"},
            {"YY/T 0287-2017标准", "wai wai ti零二八七杠二零一七标准"},
            // The limits: no edition's year after the number, or no standard's prefix before it.
            {"ISO 9001认证", "ai ai si ou九零零一认证"},
            {"RTX 3060-4090", "a er ti ai ke si三零六零到四零九零"},
        });
    }

    TEST_CASE("the metres past a motorway's stake count before a road section's word") {
        // The first row failed on main 7f699e1 (session 31, dev27): a bus route's digits, 二零零.
        check_cases({
            {"K15+200路段施工", "kei十五加二百路段施工"},
            // The limits: a route's number without a stake, and a stake's metres elsewhere.
            {"302路公交", "三零二路公交"},
            {"K35+200处", "kei三十五加二百处"},
        });
    }

    TEST_CASE("a range of years before a word that names a year is said as years") {
        // The first row failed on main 7f699e1 (session 31, dev27): counted, 两千零二十四到两千零二十六届.
        check_cases({
            {"面向2024-2026届毕业生", "面向二零二四到二零二六届毕业生"},
            // The limits: a range of counts, a range that falls, and two school years that follow each other.
            {"2000-3000人", "两千到三千人"},
            {"2026-2024届", "两千零二十六到两千零二十四届"},
            {"2024-2025学年", "二零二四至二零二五学年"},
        });
    }

    TEST_CASE("a lab's nanograms, micromoles and an enzyme's units are said by their names") {
        // The first four rows failed on main 7f699e1 (session 31, dev27): spelled, en ji ai mu ai le, the
        // pinyin mo, you ai le.
        check_cases({
            {"维生素D为18ng/mL", "维生素 di为十八纳克每毫升"},
            {"尿酸420μmol/L", "尿酸四百二十微摩尔每升"},
            {"ALT 68U/L", "ei ai le ti六十八单位每升"},
            {"5U/mL", "五单位每毫升"},
        });
        // The limit: a capital U after a number elsewhere is a letter (a chip's suffix, a rack's height).
        CHECK(said("2U服务器") == "二 you服务器");
    }

    TEST_CASE(
        "a standard's number after a local, a group or an industry's prefix, or with a part after its "
        "point") {
        // The first four rows failed on main 7a33214 (session 32, dev28): the year a range's end, 到, and
        // JJF's number counted, 一千零五十九点一.
        check_cases({
            {"执行GB/T 1.1-2020起草", "执行 ji bi ti一点一杠二零二零起草"},
            {"DB11/T 1234-2015标准", "di bi十一 ti一二三四杠二零一五标准"},
            {"符合T/CAS 115-2005要求", "符合 ti xi ei ai si一一五杠二零零五要求"},
            {"按JJF 1059.1-2012评定", "按 zhei zhei ai fu一零五九点一杠二零一二评定"},
            // The limits: capitals outside the list where no standard is spoken of, and a range of cards.
            {"CBA 2023-2024赛季", "xi bi ei二零二三至二零二四赛季"},
            {"RTX 3060-4090", "a er ti ai ke si三零六零到四零九零"},
        });
    }

    TEST_CASE("a memory's speed after its generation's letter counts") {
        // The first row failed on main 7a33214 (session 32, dev28): a code's digits, 七五零零.
        check_cases({
            {"搭载LPDDR5X-7500内存", "搭载 ai le pi di di a er五 ai ke si七千五百内存"},
            // The limit: a code after a capital and a dash, no generation before it.
            {"型号X-7500", "型号 ai ke si七五零零"},
        });
    }

    TEST_CASE("a room's number after a building named by a word in 楼 is said digit by digit") {
        // The first two rows failed on main 7a33214 (session 32, dev28): counted, 四百零八.
        check_cases({
            {"会议改在东楼408召开", "会议改在东楼四零八召开"},
            {"教学楼203", "教学楼二零三"},
            // The limits: a unit after the number, and a round hundred.
            {"大楼632米", "大楼六百三十二米"},
            {"东楼400", "东楼四百"},
        });
    }

    TEST_CASE("a number masked from its start leaves its stars unsaid and says its digits one by one") {
        // The first row failed on main 7a33214 (session 32, dev28): each star skipped with a warning, the
        // digits counted, 五千六百七十八.
        check_cases({
            {"您尾号****5678的银行卡", "您尾号五六七八的银行卡"},
            // The limit: stars between digits hold their places, 星.
            {"138****5678", "幺三八星星星星五六七八"},
        });
    }

    TEST_CASE("a length's unit in characters squared or cubed by its sign says the power first") {
        // Both rows failed on main 7a33214 (session 32, dev28): the sign skipped with a warning.
        check_cases({
            {"面积约为3.5厘米²", "面积约为三点五平方厘米"},
            {"体积为5米³", "体积为五立方米"},
        });
    }

    TEST_CASE("two models after a maker's capitals joined by a slash are each a model's digits") {
        // The first row failed on main 7a33214 (session 32, dev28): a fraction, 一千五百分之一千二百.
        check_cases({
            {"适用于HP 1200/1500系列", "适用于 ai qi pi一二零零一五零零系列"},
            // The limit: after a colon, a game's hit points, a fraction as before.
            {"HP：1200/1500", "ai qi pi一千五百分之一千二百"},
        });
    }

    TEST_CASE("a body's length, width and height joined by slashes are three numbers and their unit") {
        // The first row failed on main 7a33214 (session 32, dev28): a fraction, then the third number.
        check_cases({
            {"长宽高分别为5130/1999/1800mm", "长宽高分别为五千一百三十一千九百九十九一千八百毫米"},
            // The limit: two numbers where no dimensions are named stay a fraction.
            {"5130/1999", "一千九百九十九分之五千一百三十"},
        });
    }

    TEST_CASE("a rising range after ISO is a camera's sensitivities, not a model's variant") {
        // The first row failed on main 7a33214 (session 32, dev28): a model and its variant, 一零零四百.
        check_cases({
            {"ISO 100-400", "ai ai si ou一百到四百"},
            // The limit: an aircraft's variant after its maker's capital.
            {"A320-200", "ei三二零二百"},
        });
    }

    TEST_CASE("newton-metres, nits and kelvin are said by their names") {
        // The four rows failed on main 7a33214 (session 32, dev28): N·m's m a letter, Nm and nits spelled or
        // generic speech with a warning, the kelvin a letter.
        check_cases({
            {"峰值扭矩为700N·m", "峰值扭矩为七百牛米"},
            {"扭矩700Nm", "扭矩七百牛米"},
            {"峰值亮度3000nits", "峰值亮度三千尼特"},
            {"日冕的温度可达100万K以上", "日冕的温度可达一百万开尔文以上"},
            // The limit: a picture's K where no temperature is named in its clause.
            {"高温下看4K电视", "高温下看四 kei电视"},
        });
    }

    TEST_CASE("capitals glued to a number are spelled and a 2 before basis points is 两") {
        // The first two rows failed on main 7a33214 (session 32, dev28): the dictionary's tops, ta pu si, and
        // 二 bi pi.
        check_cases({
            {"算力达到45TOPS", "算力达到四十五 ti ou pi ai si"},
            {"较年初下降2bp", "较年初下降两 bi pi"},
            // The limits: a word said in capitals (PRO) and basis points after another number.
            {"15PRO", "十五 pu lou"},
            {"下行3bp", "下行三 bi pi"},
        });
    }

    TEST_CASE("school tiers joined by a slash are each said digit by digit") {
        // The first four rows failed on main 532a7fd (session 32, dev30): a fraction,
        // 二百一十一分之九百八十五, before 双一流 counts, 九百八十五二百一十一, and a slash before 双一流 每.
        check_cases({
            {"一所985/211高校", "一所九八五二一一高校"},
            {"一所985/211双一流高校", "一所九八五二一一双一流高校"},
            {"985、211双一流高校", "九八五二一一双一流高校"},
            {"985/211/双一流高校", "九八五二一一双一流高校"},
            // The limits: a slash between numbers no school word follows is a fraction's, and one between a
            // number and a pair's 双 is a price's per.
            {"完成了985/1000", "完成了千分之九百八十五"},
            {"袜子10元/双", "袜子十元每双"},
        });
    }

    TEST_CASE("a plural's s after an acronym's capitals is the s of a plural") {
        // The first two rows failed on main 532a7fd (session 32, dev30): the letter's name, ai si.
        check_cases({
            {"可持续发展目标SDGs", "可持续发展目标 ai si di ji si"},
            {"数千块GPUs", "数千块 ji pi you si"},
            // The limits: an acronym's last small letter that is no plural's (PCIe), and REITs, said as a
            // word.
            {"PCIe 5.0", "pi xi ai yi五点零"},
            {"公募REITs", "公募 rui ci"},
        });
    }

    TEST_CASE("Hong Kong's floor n/F is the floor") {
        // The first two rows failed on main 7a33214 (session 32, dev29): the letter said, 三 ai fu.
        check_cases({
            {"九龍彌敦道123號3/F", "九龍彌敦道一百二十三號三樓"},
            {"中环德辅道中88号12/F", "中环德辅道中八十八号十二楼"},
            // The limit: a fraction.
            {"3/4的人", "四分之三的人"},
        });
    }

    TEST_CASE("a number right before a hotline's word is dialled") {
        // The first two rows failed on main 7a33214 (session 32, dev29): counted, 一千八百二十三.
        check_cases({
            {"1823熱線全日運作", "一八二三熱線全日運作"},
            {"1999专线", "幺九九九专线"},
            // The limits: a count of hotlines, and a number with a word between.
            {"开通了3条热线", "开通了三条热线"},
            {"24小时热线", "二十四小时热线"},
        });
    }

    TEST_CASE("a bare dollar sign in Traditional text is the local dollar") {
        // The first two rows failed on main 7a33214 (session 32, dev29): 美元.
        check_cases({
            {"入場費每位$150", "入場費每位一百五十元"},
            {"這杯拿鐵才$60", "這杯拿鐵才六十元"},
            // The limits: Simplified text, and a dollar named by its country.
            {"入场费每位$150", "入场费每位一百五十美元"},
            {"這杯拿鐵才US$6", "這杯拿鐵才六美元"},
        });
    }

    TEST_CASE("a hundred counted in 块 is 两百, as casual speech says it") {
        // The first three rows failed on main 7a33214 (session 32, dev29): 二百.
        check_cases({
            {"借我200塊錢", "借我兩百塊錢"},
            {"一人出250块就够了", "一人出两百五十块就够了"},
            {"花了200多块", "花了两百多块"},
            // The limits: 元, as news says it, and a 2 inside a number.
            {"罚款200元", "罚款二百元"},
            {"1200块", "一千二百块"},
        });
    }

    TEST_CASE("a face typed in ASCII signs outside a bracket is unsaid and unwarned") {
        // Every row failed on main 7a33214 (session 32, dev29): a warning for each ^ and =, the letters of
        // T_T and o_o said (ti ti, ou ou), the D of :D said di.
        check_cases({
            {"你好啊 ^_^", "你好啊"},
            {"考試又考砸了 T_T", "考試又考砸了"},
            {"無言 =_=", "無言"},
            {"好啊^^", "好啊"},
            {"好 o_o", "好"},
            {"太好了 :D", "太好了"},
        });
        // The limits: a formula's letters and a choice's letter after a colon are read.
        check_cases({
            {"x-x=0", "ai ke si减 ai ke si等于零"},
            {"答案選:D", "答案選 di"},
        });
    }

    TEST_CASE("an ampersand between two words is said and") {
        // The first three rows failed on main 7a33214 (session 32, dev29): the sign skipped with a warning.
        check_cases({
            {"本店提供早午餐＆咖啡", "本店提供早午餐 an de咖啡"},
            {"R&D部门", "a er an de di部门"},
            {"咖啡 & 甜点", "咖啡 an de甜点"},
            // The limit: a name the dictionary has whole.
            {"S&P 500指数", "biao pu五百指数"},
        });
        // The limit: a sign alone still has no reading.
        CHECK(read_transcript("价格＆").warnings.size() == 1);
    }

    TEST_CASE("a Japanese word in kana is said a syllable a mora, a long vowel one") {
        // Every row failed on main 7a33214 (session 32, dev29): each kana skipped with a warning.
        check_cases({
            {"這個角色超かわいい的", "這個角色超 ka wa yi的"},
            {"ありがとう", "a li ga duo"},  // 阿里嘎多, a word chat took whole: below
            {"ラーメン", "la men"},
            {"チョコ", "qiao ke"},
            {"がんばって", "gan ba te"},
        });
        // Every kana's syllable is one the aligner and the lips know.
        const auto three_bytes = [](char32_t c) {  // UTF-8 of a code point from U+0800 to U+FFFF
            return std::string{static_cast<char>(0xE0 | (c >> 12)),
                               static_cast<char>(0x80 | ((c >> 6) & 0x3F)),
                               static_cast<char>(0x80 | (c & 0x3F))};
        };
        std::string kana;
        for (char32_t c = 0x3041; c <= 0x3096; ++c) {
            if (c == 0x3063) continue;  // っ alone says nothing: below
            kana += three_bytes(c) + three_bytes(c + 0x60) + " ";
        }
        const auto timeline = read_transcript(kana);
        CHECK(timeline.warnings.empty());
        for (const auto& syllable : timeline.syllables) {
            CAPTURE(syllable.pinyin);
            CHECK(is_valid_pinyin(syllable.pinyin));
        }
        // The limit: a small っ alone (好っ) cuts a sound off, says nothing and is warned of.
        CHECK(read_transcript("好っ").warnings.size() == 1);
    }

    TEST_CASE("a lone 2 after a currency sign is said 两 as before the money's word") {
        // The first four rows failed on main e0d5f85 (session 32, dev29's held out): 二港元, 二美元, 二元.
        check_cases({
            {"長者HK$2", "長者兩港元"},
            {"票价$2", "票价两美元"},
            {"¥2", "两元"},
            {"NT$2", "新台币两元"},
            // The limits: a 2 with a point or inside a number, and an ordinal.
            {"$2.5", "二点五美元"},
            {"$20", "二十美元"},
            {"第$2", "第二美元"},
        });
    }

    TEST_CASE("a camera's sensitivity after ISO counts where a standard's number is a code") {
        // The first two rows failed on main e0d5f85 (session 32, dev28's leftovers): 三二零零.
        check_cases({
            {"ISO 3200", "ai ai si ou三千二百"},
            {"ISO 100-3200", "ai ai si ou一百到三千二百"},
            {"ISO 6400", "ai ai si ou六千四百"},
            // The limits: standards off the series, and 1280, which cameras write 1250.
            {"ISO 9001", "ai ai si ou九零零一"},
            {"ISO 639", "ai ai si ou六三九"},
            {"ISO 1280", "ai ai si ou一二八零"},
            {"RTX 3200", "a er ti ai ke si三二零零"},
        });
    }

    TEST_CASE("a standard's part after a dash and its year after a colon are said as a code") {
        // The first two rows failed on main e0d5f85 (session 32, dev28's leftovers): 七十一到三, the year
        // counted.
        check_cases({
            {"EN 71-3:2019", "yi en七一杠三二零一九"},
            {"IEC 62368-1:2018", "ai yi xi六二三六八杠一二零一八"},
            // The limits: no year after the part, and a score before a time.
            {"EN 71-3", "yi en七十一到三"},
            {"比分71-3:2019", "比分七十一比三两千零一十九"},
        });
    }

    TEST_CASE("a sign after a game's gauge written in capitals adds or takes away") {
        // The first two rows failed on main 3fee0f9 (session 33, dev32): the - unsaid, a model's hyphen.
        check_cases({
            {"使用火球术，MP-20。", "使用火球术 ai mu pi减二十"},
            {"EXP-100", "yi ai ke si pi减一百"},
            {"HP+500", "ai qi pi加五百"},
            // The limits: other capitals before a hyphen name a model.
            {"AMP-20", "ei ai mu pi二十"},
            {"F-35战机", "ai fu三十五战机"},
        });
    }

    TEST_CASE("a game's stage before 关 is its world and its place") {
        // The first two rows failed on main 3fee0f9 (session 33, dev32): 一到三, a range.
        check_cases({
            {"我卡在1-3关好久了", "我卡在一杠三关好久了"},
            {"打到10-12關了", "打到十槓十二關了"},
            // The limits: a range of stages takes 第, and 关 beginning another word.
            {"第1-3关", "第一到三关"},
            {"3-5关注", "三到五关注"},
        });
    }

    TEST_CASE("a moment of a video pointed at with 那里 is minutes and seconds") {
        // The first two rows failed on main 3fee0f9 (session 33, dev32): 零点四十五分, a time of day.
        check_cases({
            {"视频0:45那里笑死我了", "视频四十五秒那里笑死我了"},
            {"这集12:30那段", "这集十二分三十秒那段"},
            // The limits: no video named, a time to meet.
            {"今晚12:30那里见", "今晚十二点三十分那里见"},
            {"视频将于20:00上线", "视频将于二十点上线"},
        });
    }

    TEST_CASE("a Japanese word chat has taken whole is said as its settled transliteration") {
        // The first three rows failed on main 3fee0f9 (session 33, dev32 and dev29): the mora table's si ge
        // yi, ba ka, da mei.
        check_cases({
            {"すごい！這招太帥了", "si guo yi這招太帥了"},
            {"ばか", "ba ga"},
            {"ダメ", "da mie"},
            // The limits: the word inside a longer run of kana, and a word not listed.
            {"すごいね", "si ge yi nei"},
            {"かわいい", "ka wa yi"},
        });
    }

    TEST_CASE("a set's signs, an absolute value and a ratio of two letters are said as a lesson reads them") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): the set's signs and the bars were
        // skipped, the colon and the slash unsaid.
        check_cases({
            {"x∈A", "ai ke si属于 ei"},
            {"x∉B", "ai ke si不属于 bi"},
            {"A∩B=∅", "ei交 bi等于空集"},
            {"A∪B", "ei并 bi"},
            {"x∈[0,1)", "ai ke si属于零到一"},
            {"|x|=3", "ai ke si的绝对值等于三"},
            {"a:b=3:2", "ei比 bi等于三比二"},
            {"v=s/t", "wei等于 ai si比 ti"},
            {"A={1,2,3}", "ei等于一二三"},
            {"集合{x|x>0}", "集合 ai ke si ai ke si大于零"},
            // The limits: a slash without a relation, a slash in a word, and a reading fix's braces.
            {"阅读/写作", "阅读写作"},
            {"v=72km/h", "wei等于七十二公里每小时"},
            {"行{hang2}", "行"},
        });
        CHECK(pinyin_of("行{hang2}") == "hang2");
    }

    TEST_CASE("a judgement question's tick and cross in brackets are said 对 and 错") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): 根号, and the cross unsaid.
        check_cases({
            {"0是最小的自然数。（√）", "零是最小的自然数对"},
            {"两个锐角的和一定是钝角。（×）", "两个锐角的和一定是钝角错"},
            // The limits: a root and a product.
            {"√2", "根号二"},
            {"3×4", "三乘四"},
        });
    }

    TEST_CASE("a logarithm, a repeating decimal and an interval are said as a lesson reads them") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): log was the dictionary's word, the dots
        // were skipped with a warning, the interval's comma a pause.
        check_cases({
            {"log₂8=3", "以二为底八的对数等于三"},
            {"log_3 9", "以三为底九的对数"},
            {"0.3̇", "零点三循环"},
            {"0.1̇2̇", "零点一二循环"},
            {"0.16̇", "零点一六循环"},
            {"[0,1)", "零到一"},
            {"[0,+∞)", "零到正无穷"},
            {"区间(0,2)", "区间零到二"},
            // The limits: a point's coordinates, and a decimal without dots.
            {"点A(1,2)", "点 ei一二"},
            {"0.3", "零点三"},
        });
    }

    TEST_CASE("a bracket's power and ten's square or cube in scientific notation are said with 的 and 次方") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): 负二立方, the = after ¹⁰⁰ skipped,
        // 十的立方 and the unit spelled.
        check_cases({
            {"(-2)³=-8", "负二的立方等于负八"},
            {"(-1)¹⁰⁰=1", "负一的一百次方等于一"},
            {"1.0×10³kg/m³", "一点零乘十的三次方千克每立方米"},
            {"2.5×10²m", "二点五乘十的二次方米"},
            // The limits: a square after a letter or a digit, and ten squared alone.
            {"x²", "ai ke si平方"},
            {"10³", "十的立方"},
        });
    }

    TEST_CASE("units a physics lesson writes are said by the names textbooks give them") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): μF was a letter, N/kg 牛每公斤, a unit
        // named alone spelled.
        check_cases({
            {"47μF", "四十七微法"},
            {"9.8N/kg", "九点八牛每千克"},
            {"3.0×10⁷J/kg", "三点零乘十的七次方焦耳每千克"},
            {"速度的单位是m/s", "速度的单位是米每秒"},
            {"功率的单位是W", "功率的单位是瓦"},
            // The limits: a dose and a battery per body weight and per mass keep 公斤; a unit of characters.
            {"0.5mg/kg", "零点五毫克每公斤"},
            {"160Wh/kg", "一百六十瓦时每公斤"},
            {"长度的单位是米", "长度的单位是米"},
        });
    }

    TEST_CASE("a word's phonetic spelling after it is not said") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): pl pi ai le, the rest warned of.
        CHECK(said("英语单词apple [ˈæpl] 的意思是苹果") == said("英语单词apple 的意思是苹果"));
        CHECK(read_transcript("apple /ˈæpl/").warnings.empty());
        CHECK(said("apple /ˈæpl/") == said("apple"));
        // The limits: brackets of letters or words are read.
        CHECK(said("[注]") == "注");
        CHECK(said("[ok]") == said("ok"));
    }

    TEST_CASE(
        "a camera's range, a standard's two parts and a rate's basis points are read as their kinds are") {
        // The first rows failed on main 3fee0f9 (session 32's leftovers): 五一二零零, 六零三三五二 and the
        // year a ratio's, a standard of 2000, B P S by their letters.
        check_cases({
            {"ISO 50-51200", "ai ai si ou五十到五万一千二百"},
            {"ISO 100-2000", "ai ai si ou一百到两千"},
            {"IEC 60335-2-29:2019", "ai yi xi六零三三五杠二杠二九二零一九"},
            {"网速只有20bps", "网速只有二十比特每秒"},
            {"央行下调利率20bps", "央行下调利率二十 bi pi si"},
            // The limits: a standard's year after ISO, and bp alone.
            {"ISO 9001-2000", "ai ai si ou九零零一杠二零零零"},
            {"下调20bp", "下调二十 bi pi"},
        });
    }

    TEST_CASE(
        "a reaction's arrows, a formula counted in subscripts and a right triangle's Rt are read without a "
        "warning") {
        // The first rows failed on main 3fee0f9 (session 33, dev31): each warned (the arrow skipped, KMn and
        // Rt read letter by letter as words the dictionary lacks).
        check_cases({
            {"2H₂O₂=2H₂O+O₂↑", "二 ai qi二 ou二等于二 ai qi二 ou加 ou二"},
            {"Na₂CO₃+CaCl₂=CaCO₃↓+2NaCl",
             "en ei二 xi ou三加 xi ei xi ai le二等于 xi ei xi ou三加二 en ei xi ai le"},
            {"实验室用KMnO₄制取O₂", "实验室用 kei ai mu en ou四制取 ou二"},
            {"Rt△ABC", "a er ti三角形 ei bi xi"},
            // The limits: an arrow after a word is a market's rise, and a lesson's variable is no symbol.
            {"宁德时代↑3.2%", "宁德时代涨百分之三点二"},
            {"x₁+x₂=5", "ai ke si一加 ai ke si二等于五"},
        });
    }

    TEST_CASE("a keyboard shortcut's keys are said by their names and joined by 加") {
        // The first four rows failed on main 3aa3425 (session 33, dev33): Ctrl spelled, ⌘ unsaid, +4 正四,
        // Esc generic speech.
        check_cases({
            {"按Ctrl+C复制", "按 ken chuo加 xi复制"},
            {"按⌘+空格搜索", "按 ke man de加空格搜索"},
            {"截屏是Shift+⌘+4", "截屏是 shi fu te加 ke man de加四"},
            {"按Esc退出", "按 yi ai si xi退出"},
            // The limits: cmd that names a program is its letters, a signed number stays signed.
            {"输入cmd后回车", "输入 xi ai mu di后回车"},
            {"气温+4度", "气温零上四度"},
        });
    }

    TEST_CASE("a path, a name joined by underscores and a hexadecimal code are said mark by mark") {
        // The first five rows failed on main 3aa3425 (session 33, dev33): the marks unsaid, the digits
        // counted, 0x read 零乘.
        check_cases({
            {"打开C:\\Users\\Admin文件夹", "打开 xi冒号反斜杠 yu ze si反斜杠 a de min文件夹"},
            {"编辑/etc/hosts文件", "编辑斜杠 yi ti xi斜杠 hou si ci文件"},
            {"Wi-Fi名称为Home_5G", "wai fa名称为 hou mu下划线五 ji"},
            {"关注@dance_2024", "关注艾特 dan si下划线二零二四"},
            {"错误代码0x80070005", "错误代码零 ai ke si八零零七零零零五"},
            // The limits: a face drawn as T_T, a unit's slash, one name after a slash.
            {"哭了T_T", "哭了"},
            {"速度500MB/s", "速度五百 ai mu bi每秒"},
            {"每人/天", "每人天"},
        });
    }

    TEST_CASE("a port, an error code and a model's second number are said digit by digit") {
        // The first five rows failed on main 3aa3425 (session 33, dev33): they counted.
        check_cases({
            {"把端口改成8080", "把端口改成八零八零"},
            {"输入192.168.0.1:8080进入", "输入一九二点一六八点零点一冒号八零八零进入"},
            {"提示错误502", "提示错误五零二"},
            {"页面显示404", "页面显示四零四"},
            {"戴尔XPS 13 9340", "戴尔 ai ke si pi ai si十三九三四零"},
            // The limits: a short port counts, a count shown on no page, a model's price.
            {"端口是22", "端口是二十二"},
            {"屏幕显示404人", "屏幕显示四百零四人"},
            {"XPS 13售价9999元", "ai ke si pi ai si十三售价九千九百九十九元"},
        });
    }

    TEST_CASE(
        "a reward after an action, a role's record, a mark to draw, lg and ln, and a chat's hum are said") {
        // The first rows failed on main 587d49b (session 33, dev34): 正, a range's 到, 根号 and ✓ unsaid, the
        // letters of lg and ln, emmm generic speech.
        check_cases({
            {"助攻+1", "助攻加一"},
            {"邀请好友+50钻石", "邀请好友加五十钻石"},
            {"中单1-4了", "中单一杠四了"},
            {"正确的打√，错误的打×", "正确的打勾错误的打叉"},
            {"请打✓", "请打勾"},
            {"lg100=2", "一百的常用对数等于二"},
            {"ln10", "十的自然对数"},
            {"emmm，好吧", "嗯好吧"},
            // The limits: a value's sign, a range of minutes, a root, and letters before lg.
            {"温差+12", "温差正十二"},
            {"打野3-5分钟", "打野三到五分钟"},
            {"√2", "根号二"},
        });
    }

    TEST_CASE(
        "a home's layout, a rate per a power of ten, a sprint's hundredths before the men's race and CRISPR "
        "are said as news reads them") {
        // The first rows failed on main 8eff8bb (session 34, dev36): a layout's 2 二 (三室二厅二卫), the
        // slash of a rate unsaid (三点二十万), 五十八 counting men, CRISPR spelled.
        check_cases({
            {"3室2厅2卫", "三室两厅两卫"},
            {"该户型为2室1厅1卫", "该户型为两室一厅一卫"},
            {"1梯2户", "一梯两户"},
            {"3房2廳2衛", "三房兩廳兩衛"},
            {"发病率为3.2/10万", "发病率为十万分之三点二"},
            {"1/100万", "百万分之一"},
            {"死亡率为5.6/1000", "死亡率为千分之五点六"},
            {"9秒58男子100米", "九秒五八男子一百米"},
            {"CRISPR技术", "ke li si po技术"},
            // The limits: a part alone is a name, a pair of sexes counts, a fraction of a small whole keeps
            // its numerator whole, and a mark out of ten is no rate.
            {"影院2厅", "影院二厅"},
            {"3男2女组合", "三男两女组合"},
            {"1/10", "十分之一"},
        });
    }

    TEST_CASE(
        "a letter's logarithm, a typed name's abbreviation, a brand's words and a key's name are said") {
        // The rows before the limits failed on main 8eff8bb (session 34, session 33's leftovers): lo ge and
        // the letter, log_2 a typed name, 正五, et cetera, Gi thub generic speech, ken tou, 二百二十一.
        check_cases({
            {"log₃x=2", "以三为底 ai ke si的对数等于二"},
            {"log_2 n", "以二为底 en的对数"},
            {"lnx", "ai ke si的自然对数"},
            {"答对一题+5分", "答对一题加五分"},
            {"编辑/etc/fstab", "编辑斜杠 yi ti xi斜杠 ai fu si ta bu"},
            {"上传到Github", "上传到 ji te ha bu"},
            {"上传到GitHub", "上传到 ji te ha bu"},
            {"按Ctrl键", "按 ken chuo键"},
            {"秦于公元前221年统一六国", "秦于公元前二二一年统一六国"},
            {"唐朝建于公元618年", "唐朝建于公元六一八年"},
            // The limits: a number's log, four digits after 公元前 count, etc. in a sentence is et cetera.
            {"log₂8=3", "以二为底八的对数等于三"},
            {"公元前2070年", "公元前两千零七十年"},
            {"苹果、香蕉etc.", "苹果香蕉 ai te sai te e"},
        });
    }

    TEST_CASE("a season and an episode, a group's name in capitals and a year in a title are said") {
        // The rows before the limits failed on main 8eff8bb (session 34, dev35): the letters S and E, the
        // capitals spelled, the year counted.
        check_cases({
            {"《老友记》S3E5", "老友记第三季第五集"},
            {"S01E10更新了", "第一季第十集更新了"},
            {"TFBOYS十周年", "ti ai fu bao si十周年"},
            {"BLACKPINK新歌", "bu la ke ping ke新歌"},
            {"《歌手2024》第3期", "歌手二零二四第三期"},
            // The limits: a console's name, capitals that spell no words, a title of digits alone.
            {"PS5", "pi ai si五"},
            {"NASA发布", "na sa发布"},
            {"《1984》", "一千九百八十四"},
        });
    }

    TEST_CASE(
        "a goodbye after a particle, a face's hands, a post's +1, a flight's code, a gene's name, a "
        "thousandth and an amount in K, M or B are said as chat, notices and science read them") {
        // The rows before the limits failed on main 029c10d (session 35, dev37 and session 34's leftovers):
        // 八十八, ou, 正一, 八千六百三十三, 幺 in Taiwan's, C A S, 一千分之一, 二房, the letter after the
        // amount, 跌 and 正 of a game's stats.
        check_cases({
            {"那明天见啦88～", "那明天见啦八八"},
            {"今天也要加油ヾ(≧▽≦*)o", "今天也要加油"},
            {"我的号被盗了o(╥﹏╥)o", "我的号被盗了"},
            {"溜了ε=ε=ε=┏(゜ロ゜;)┛", "溜了"},
            {"樓上說得對+1", "樓上說得對加一"},
            {"3U8633航班", "三 you八六三三航班"},
            {"搭乘長榮BR189班機", "搭乘長榮 bi a er一八九班機"},
            {"Cas9蛋白", "ka si九蛋白"},
            {"1/1000", "千分之一"},
            {"1/100", "百分之一"},
            {"1/10000", "万分之一"},
            {"2房單位", "兩房單位"},
            {"比特币跌破$90K", "比特币跌破九万美元"},
            {"营收$94.9B", "营收九百四十九亿美元"},
            {"融资$1.2M", "融资一百二十万美元"},
            {"冷却-20%", "冷却减百分之二十"},
            {"装备+15", "装备加十五"},
            // The limits: a count before a particle, a key's name, a password's letters, a letter in a word,
            // a temperature's sign, a tenth, a hall's name, a mainland train in Traditional text, a letter
            // that begins a unit.
            {"他今年88了吧", "他今年八十八了吧"},
            {"按Esc键", "按 yi ai si xi键"},
            {"密码是abc123", "密码是 ei bi xi一二三"},
            {"温差+1", "温差正一"},
            {"1/10", "十分之一"},
            {"影院2厅", "影院二厅"},
            {"複興號G1次列車", "複興號 ji幺次列車"},
            {"$5MB", "五美元 ai mu bi"},
        });
    }

    TEST_CASE(
        "a lap's thousandths, a mixed number, a quantity's value, a tablet, an ordinal's list, a place after "
        "第, a table's number and a train without a class's letter are said as results, labels, documents "
        "and timetables read them") {
        // The rows before the limits failed on main f33f325 (session 36, dev38 and session 35's leftovers): a
        // clock time and 一百二十三, 一二分之一, 七点三十五, 二錠, 两项, 七五二, 两 before 列 and 所,
        // 兩千一百零一次, 四千二百三十五, 一千四百六十一, an de lao de, * skipped, 一到零 and 一到一
        // (自強號123次 was read after 號 digit by digit already).
        check_cases({
            {"以1:27.123的圈速拿下杆位", "以一分二十七秒一二三的圈速拿下杆位"},
            {"面粉1½杯", "面粉一又二分之一杯"},
            {"血液pH 7.35~7.45", "血液 pi ai qi七点三五到七点四五"},
            {"這個藥每次2錠", "這個藥每次兩錠"},
            {"有前款第1、2项情形的", "有前款第一二项情形的"},
            {"依照第3、4、5条", "依照第三四五条"},
            {"国务院令第752号", "国务院令第七百五十二号"},
            {"表2列出了主要指标", "表二列出了主要指标"},
            {"如图2所示", "如图二所示"},
            {"见附件2", "见附件二"},
            {"搭乘自強號123次", "搭乘自強號一二三次"},
            {"2101次區間車誤點", "二一零一次區間車誤點"},
            {"台鐵4235車次", "台鐵四二三五車次"},
            {"普快1461次", "普快幺四六幺次"},
            {"Android 15", "an zhuo十五"},
            {"规格：10mg*30片", "规格十毫克乘三十片"},
            {"武磊推射破门，1-0。", "武磊推射破门一比零"},
            {"终场前扳平，1-1。", "终场前扳平一比一"},
            // The limits: a fraction alone, a software's version, a count of times, a room's number, a watch
            // counted, a count of rides, a share at risk's star, a rising pair alone.
            {"牛奶½杯", "牛奶二分之一杯"},
            {"Python 3.12", "pai san三点十二"},
            {"第2次", "第二次"},
            {"1203号", "一二零三号"},
            {"手表2块", "手表两块"},
            {"坐了100次火车", "坐了一百次火车"},
            {"*ST康美", "星 ai si ti康美"},
            {"休息，3-5。", "休息三到五"},
        });
    }

    TEST_CASE(
        "a lap's thousandths before a rank, an annex's part, a typed square or cube, a currency pair, a "
        "ticker's triangle and a padded month and day are said as news and listings read them") {
        // The rows before the limits failed on main 4872926 (session 37, dev39 and session 36's leftovers):
        // 八百七十六, 二到三, the interjection m2 and m3, the slash unsaid, the triangles skipped,
        // 一二杠零六, 二百零二万六千一百四十.
        check_cases({
            {"他以1分29秒876排在第2位", "他以一分二十九秒八七六排在第二位"},
            {"9秒83排名第一", "九秒八三排名第一"},
            {"详见附件2-3", "详见附件二杠三"},
            {"房屋面积120m2", "房屋面积一百二十平方米"},
            {"PM2.5浓度为115μg/m3", "pi ai mu二点五浓度为一百一十五微克每立方米"},
            {"美元/人民币报7.1234", "美元兑人民币报七点一二三四"},
            {"欧元/美元跌破1.05", "欧元兑美元跌破一点零五"},
            {"USD/CNY报7.12", "you ai si di兑 xi en wai报七点一二"},
            {"沪指 3088.53 ▲0.82%", "沪指三千零八十八点五三涨百分之零点八二"},
            {"恒指 19876.40 ▼1.20%", "恒指一万九千八百七十六点四零跌百分之一点二零"},
            {"更新于12-06 20:15", "更新于十二月六日二十点十五分"},
            {"发布于03-15", "发布于三月十五日"},
            {"双色球第2026140期开奖", "双色球第二零二六一四零期开奖"},
            // The limits: a row's count, money supply's M2, a price per a unit, a score, a code's dashed
            // digits, a figure's place, a count of issues.
            {"他排在第2排", "他排在第二排"},
            {"M2余额同比增长7%", "ai mu二余额同比增长百分之七"},
            {"3.5美元/公斤", "三点五美元每公斤"},
            {"比分12-10", "比分十二比十"},
            {"取件码A12-06", "取件码 ei一二杠零六"},
            {"如图3-2所示", "如图三杠二所示"},
            {"本刊第10000期", "本刊第一万期"},
        });
    }

    TEST_CASE("a caption's bullet opening its line is not said and not warned of") {
        // Main 4872926 read the same syllables but warned of each mark (session 37, dev39).
        for (const auto* line : {"▲图为救援人员在现场搜救。", "● 国内油价将调整。", "■要点"}) {
            const auto timeline = read_transcript(line);
            CHECK(timeline.warnings.empty());
        }
        // Inside a line a shape no legend explains is still a mark without a reading.
        CHECK_FALSE(read_transcript("今日▲要闻。").warnings.empty());
    }

    TEST_CASE("a shape a legend explains is said by its name") {
        // Each row but the limits fails on main 18103f3 (session 37's leftover, session 38): the shape was
        // skipped with a warning.
        check_cases({
            {"说明：▲表示上涨，▼表示下跌。", "说明三角表示上涨倒三角表示下跌"},
            {"图中●为观测站", "图中圆点为观测站"},
            {"重点内容用■标出", "重点内容用方块标出"},
            {"▲表示上涨", "三角表示上涨"},
            {"▲{实心三角}表示上涨", "实心三角表示上涨"},
            // The limits: a bullet opening its line stays unsaid; a ticker's triangle is 涨.
            {"▲为您推荐", "为您推荐"},
            {"沪指▲0.82%", "沪指涨百分之零点八二"},
        });
    }

    TEST_CASE("an English consonant before a liquid is a syllable of its own and a glide is a medial") {
        // Each row failed on main 029c10d: ti, pei, jin, si ti te, pou, qi ke, ku te.
        check_cases({
            {"tree", "te li"},
            {"play", "pu lei"},
            {"green", "ge lin"},
            {"street", "si te li te"},
            {"iPhone 16 Pro", "ai feng十六 pu lou"},
            {"quick", "kui ke"},
            {"好cute", "好 qiu te"},
        });
    }

    TEST_CASE("a lesson's, a game's, a chat's and a shop's forms are said as their readers say them") {
        // Each row but the limits fails on main 21994c7 (session 39, dev41's kinds of text): 长宽 with a
        // warning, 公斤, ai ke si di, ai qi, the weekday's character alone, letters for AM and PM.
        check_cases({
            {"三角形面积=底×高÷2", "三角形面积等于底乘高除以二"},
            {"质量为2.5kg的木块", "质量为二点五千克的木块"},
            {"笑死我了XD", "笑死我了"},
            {"XDDD 太好笑了", "太好笑了"},
            {"48H发货", "四十八小时发货"},
            {"7×24H在线客服", "七乘二十四小时在线客服"},
            {"1/1(日)照常營業", "一月一日星期日照常營業"},
            {"12月31日（五）晚上", "十二月三十一日星期五晚上"},
            {"9am-6pm", "上午九点到晚上六点"},
            {"11:30PM截止", "晚上十一点三十分截止"},
            {"12PM开门", "中午十二点开门"},
            // The limits: Taiwan's mass, a pencil's grade, a half year and a bracket after a word.
            {"質量為2.5kg", "質量為二點五公斤"},
            {"2H铅笔", "二 ai qi铅笔"},
            {"2024H1营收", "二零二四 ai qi一营收"},
            {"方案(三)", "方案三"},
        });
        // A collaboration's × is no formula's: unsaid, warned of as before.
        CHECK(said("李宁×故宫") == "李宁故宫");
    }

    TEST_CASE(
        "a unit in characters with a small prefix takes 两, and a number right after a dialling verb is "
        "dialled") {
        // Each row but the limits fails on main 21994c7 (session 38's leftovers, dev40's held out): 二奈米,
        // 二毫米, a number counted before 臺 of 臺北.
        check_cases({
            {"台積電2奈米製程", "台積電兩奈米製程"},
            {"直径2毫米", "直径两毫米"},
            {"长约2厘米", "长约两厘米"},
            {"請撥打1999臺北市民當家熱線", "請撥打一九九九臺北市民當家熱線"},
            {"请拨打12345热线", "请拨打幺二三四五热线"},
            // The limits: 第 keeps 二, and a count after 打 alone is a count.
            {"第2毫米", "第二毫米"},
            {"打1999元", "打一千九百九十九元"},
        });
    }

    TEST_CASE(
        "an exercise sheet's blanks, a listing's dimensions, a chat's +1 and a show's chapters are said") {
        // Each row but the limits fails on main f5434ff (session 40, dev42's tuning misses): the = before a
        // blank unsaid, × before a bracket and between a size's dimensions unsaid with a warning, 正一, and a
        // chapter's time as a time of day (三点十五分).
        check_cases({
            {"36×25=______", "三十六乘二十五等于"},
            {"(−4)×(−5)=？", "负四乘负五等于"},
            {"3×(4+5)=27", "三乘四加五等于二十七"},
            {"8+7=（  ）", "八加七等于"},
            {"長45公分×寬30公分", "長四十五公分乘寬三十公分"},
            {"尺寸：长20cm×宽15cm×高10cm", "尺寸长二十厘米乘宽十五厘米乘高十厘米"},
            {"收到+1，我也要", "收到加一我也要"},
            {"同意+1", "同意加一"},
            {"本期播客\n03:15 为什么要做播客", "本期播客三分十五秒为什么要做播客"},
            {"本集节目\n1:02:30 听众提问", "本集节目一小时零二分三十秒听众提问"},
            // The limits: a schedule's line in other text is a time of day, a value's +1 keeps its sign, a
            // question's ? after words is no blank, and a collaboration's × stays unsaid.
            {"今日安排\n09:00 开幕式", "今日安排九点开幕式"},
            {"化合价为+1，", "化合价为正一"},
            {"x=5吗？", "ai ke si等于五吗"},
        });
        CHECK(said("李宁×故宫") == "李宁故宫");
    }

    TEST_CASE(
        "a team's roles are counted, a service and a meeting place are named by their numbers, and a "
        "shop's threshold counts as 块 does") {
        // Each row but the limits fails on main f5434ff (session 39's leftovers, dev41's held out): 二補,
        // 一百 一十, 一百零一, 二百, ba si, 厘米 and 米 in Taiwan's text.
        check_cases({
            {"缺1坦2補", "缺一坦两補"},
            {"来2奶3射", "来两奶三射"},
            {"您好，这里是110吗", "您好这里是幺幺零吗"},
            {"下午3點半在101見", "下午三點半在一零一見"},
            {"我们在305碰面", "我们在三零五碰面"},
            {"满200减30", "满两百减三十"},
            {"打BOSS", "打 bo si"},
            {"小明身高152cm，體重45kg。", "小明身高一百五十二公分體重四十五公斤"},
            {"這間房25m²，離車站500m。", "這間房二十五平方公尺離車站五百公尺"},
            // The limits: a role alone, a room's number elsewhere, a notice's 元, a year, Hong Kong's
            // Cantonese text and Simplified text keep their readings.
            {"第2法", "第二法"},
            {"这里有110人", "这里有一百一十人"},
            {"满200元减30元", "满二百元减三十元"},
            {"在2025见", "在两千零二十五见"},
            {"佢身高152cm", "佢身高一百五十二厘米"},
            {"身高152cm", "身高一百五十二厘米"},
        });
    }

    TEST_CASE(
        "a score set off by spaces between names, a listing's year before its new model and a +1 "
        "before 的 are said") {
        // Each row but the limits fails on main 5b4d5b7 (session 40's leftovers, dev42's held out): 二到二,
        // 两千零二十四新款, 正一.
        check_cases({
            {"英超第15轮：曼城 2-2 利物浦", "英超第十五轮曼城二比二利物浦"},
            {"阿森纳 1-0 切尔西。", "阿森纳一比零切尔西"},
            {"【官方正品】2024新款羽绒服", "官方正品二零二四新款羽绒服"},
            {"2024秋冬新款", "二零二四秋冬新款"},
            {"2025新赛季", "二零二五新赛季"},
            {"有人要團購嗎？+1的請留言", "有人要團購嗎加一的請留言"},
            {"+1的私我", "加一的私我"},
            // The limits: a rising pair is a range, spaced or not, a number before 多 counts, and a value's
            // or a lesson's +1 keeps its sign.
            {"气温 12-18 度", "气温十二到十八度"},
            {"2000多款", "两千多款"},
            {"电荷为+1的离子", "电荷为正一的离子"},
            {"+1的相反数是-1", "正一的相反数是负一"},
        });
    }

    TEST_CASE(
        "an item's upgrade level is said as a bonus where the item or the upgrade is named apart from it") {
        // Each row but the limits fails on main b8e0682 (dev44's one tuning miss): 正十五, 正十二.
        check_cases({
            {"我号已经60级了，装备全是+15的。", "我号已经六十级了装备全是加十五的"},
            {"强化到+12了", "强化到加十二了"},
            {"一把+12的武器", "一把加十二的武器"},
            {"這把武器已經精煉到+10", "這把武器已經精煉到加十"},
            // The limits: a value's and a lesson's signs, and a change in percent, keep their readings.
            {"电荷为+1的离子", "电荷为正一的离子"},
            {"温差+12", "温差正十二"},
            {"装备价格+15%", "装备价格涨百分之十五"},
            {"一把+12的椅子", "一把正十二的椅子"},
        });
    }

    TEST_CASE("2 before 出, a play's or an inning's outs, is 两") {
        // Each row but the limits fails on main f5421d4 (dev45, session 44): 二出局, 二出戏.
        check_cases({
            {"第9局下半2出局滿壘", "第九局下半两出局滿壘"},
            {"演了2出戏", "演了两出戏"},
            // The limits: an ordinal, and a 2 inside a number.
            {"第2出", "第二出"},
            {"12出局", "十二出局"},
        });
    }

    TEST_CASE("a money word written after a currency sign's amount is said once") {
        // Each row but the limits fails on main 2d7215e (text18's probe of dev44's kinds): 二十三点五元元.
        check_cases({
            {"只要¥23.5元", "只要二十三点五元"},
            {"NT$150元", "新台币一百五十元"},
            {"HK$20港元", "二十港元"},
            {"$5美元", "五美元"},
            {"花了¥100块钱", "花了一百块钱"},
            {"¥100万元", "一百万元"},
            // The limits: the sign alone says its money's word, after a magnitude too.
            {"¥30", "三十元"},
            {"$5万", "五万美元"},
            {"¥2", "两元"},
        });
    }

    TEST_CASE(
        "a currency's name written after the sign's amount is said there alone, a space between or none") {
        // Each row but the limits fails on main 6db43b6: 新台币一百五十新台币, 五美元美元.
        check_cases({
            {"售价NT$150新台币", "售价一百五十新台币"},
            {"NT$3万新台币", "三万新台币"},
            {"只要$5 美元", "只要五美元"},
            {"US$20 美金", "二十美金"},
            {"价格¥100 元", "价格一百元"},
            // The limits: a plain money word keeps the sign's name before the amount, and no word after
            // the amount leaves the sign's.
            {"NT$150元", "新台币一百五十元"},
            {"NT$150", "新台币一百五十元"},
        });
    }

    TEST_CASE("an error code in brackets is said digit by digit, its minus kept") {
        // Each row but the limits fails on main 6db43b6: 负一千零九, 四百零四, 五百零二.
        check_cases({
            {"网络不可用(-1009)", "网络不可用负一零零九"},
            {"页面报错(404)", "页面报错四零四"},
            {"提示错误（502）", "提示错误五零二"},
            {"HTTP 404", "ai qi ti ti pi四零四"},
            // The limits: a bracketed amount with its unit or magnitude counts, a short signed number too.
            {"海拔(-1200米)", "海拔负一千二百米"},
            {"净利润(-1500万)", "净利润负一千五百万"},
            {"出现错误（-2）", "出现错误负二"},
        });
    }

    TEST_CASE(
        "a Traditional transcript reads a game's record, a World Cup's year and 釐米² as a Simplified one "
        "does") {
        // Each row but the limits fails on main c1e3848: 十二年三月五日 (a date of the Republic), 兩千零三十,
        // 三點五釐米 (the sign skipped).
        check_cases({
            {"我KDA 12/3/5，這都能輸？", "我 kei di ei十二槓三槓五這都能輸"},
            {"2030世界盃將在六國舉辦", "二零三零世界盃將在六國舉辦"},
            {"傷口面積約為3.5釐米²", "傷口面積約為三點五平方釐米"},
            {"體積為20釐米³", "體積為二十立方釐米"},
            // The limits: Taiwan's date keeps its year of the Republic.
            {"繳費期限：99/12/31前", "繳費期限九十九年十二月三十一日前"},
        });
    }

    TEST_CASE("a list of chapters that opens at 00:00 reads its times as places in the recording") {
        // Each row but the limits fails on main 53fa8cc: 十二点四十分, 四十五比十 (a score).
        check_cases({
            {"00:00 开场\n12:40 聊聊AI\n45:10 总结", "零分开场十二分四十秒聊聊 ei ai四十五分十秒总结"},
            {"0:00 片头\n3:15 正片", "零分片头三分十五秒正片"},
            // The limits: a schedule that opens at another hour keeps its times of day, and 00:00 inside a
            // line opens no list.
            {"09:00 开幕式\n12:40 午餐", "九点开幕式十二点四十分午餐"},
            {"倒计时到00:00结束\n12:40 午餐", "倒计时到零分结束十二点四十分午餐"},
        });
    }

    TEST_CASE("buildings counted by 栋 or 幢 before a building's noun are 两, as news counts them") {
        // Each row but the limits fails on main 1e20c3d (readings_dev3, session 45): 二栋, 二幢, 二棟.
        check_cases({
            {"这场大火烧毁了2栋民房", "这场大火烧毁了两栋民房"},
            {"新建2幢住宅楼", "新建两幢住宅楼"},
            {"2棟大樓受損", "兩棟大樓受損"},
            // The limits: a block's name, alone or before 楼 and a room, and an ordinal.
            {"住在2栋301", "住在二栋三零一"},
            {"2栋楼下", "二栋楼下"},
            {"第2栋民房", "第二栋民房"},
        });
    }

    TEST_CASE("a number after a score's 比 is said bare, 二 before 平 too") {
        // Each row but the limits fails on main bea23b7 (session 45's readings_dev3): 两.
        check_cases({
            {"比分2比2平", "比分二比二平"},
            {"最终2比2平", "最终二比二平"},
            {"比賽以2比2平手收場", "比賽以二比二平手收場"},
            // The limits: 平 of square metres after a number alone, and a score's number before 比.
            {"这套房子2平", "这套房子两平"},
            {"他们以2比1获胜", "他们以二比一获胜"},
        });
    }

    TEST_CASE("rounds and shots counted by 发 are 两, as a game's lines count them") {
        // Each row but the limits fails on main bea23b7 (readings_dev4, session 46): 二发, 二發.
        check_cases({
            {"就剩2发子弹了", "就剩两发子弹了"},
            {"連開2發", "連開兩發"},
            // The limits: an ordinal, and a number inside a larger one.
            {"第2发子弹", "第二发子弹"},
            {"打了12发", "打了十二发"},
        });
    }
}
