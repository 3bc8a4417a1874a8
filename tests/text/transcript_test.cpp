#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"
#include "text/reading_tables.hpp"
#include "text/unread_transcript.hpp"

using namespace talkface;

namespace {

// The toneless readings of all syllables, space-separated: tones do not move the lips, so this
// is what must be right (SPEC "Transcript to syllables").
std::string toneless(const Timeline& timeline) {
    std::string text;
    for (const auto& syllable : timeline.syllables) {
        if (!text.empty()) text += ' ';
        text += syllable.pinyin.substr(0, syllable.pinyin.size() - 1);
    }
    return text;
}

std::string toneless(const std::string& transcript) {
    return toneless(read_transcript(transcript));
}

// The numbered readings of all syllables, space-separated, where a tone is what is checked.
std::string pinyin(const std::string& transcript) {
    std::string text;
    for (const auto& syllable : read_transcript(transcript).syllables)
        text += (text.empty() ? "" : " ") + syllable.pinyin;
    return text;
}

}  // namespace

TEST_SUITE("transcript") {
    TEST_CASE("a polyphonic character is read by the word it stands in") {
        CHECK(toneless("首都") == "shou du");
        CHECK(toneless("都是") == "dou shi");
        CHECK(toneless("朝代") == "chao dai");
        CHECK(toneless("朝氣") == "zhao qi");
        CHECK(toneless("朝气") == "zhao qi");
        CHECK(toneless("曾經") == "ceng jing");
        CHECK(toneless("曾经") == "ceng jing");
        CHECK(toneless("銀行") == "yin hang");
        CHECK(toneless("行走") == "xing zou");
        CHECK(toneless("長期") == "chang qi");
        CHECK(toneless("長大") == "zhang da");
        CHECK(toneless("长大") == "zhang da");
        CHECK(toneless("下來") == "xia lai");
        CHECK(toneless("我們都是首都人") == "wo men dou shi shou du ren");
    }

    TEST_CASE("a run is cut into its likeliest words, not the longest word at each place") {
        // The longest match took 人参 (ren2 shen1), 生长 (sheng1 zhang3), 司长 (si1 zhang3),
        // 会计 (kuai4 ji4), 还原 (huan2 yuan2) here: the word to its left was not a phrase.
        CHECK(toneless("全国有一亿人参加了比赛") == "quan guo you yi yi ren can jia le bi sai");
        CHECK(toneless("很多老人参加了活动") == "hen duo lao ren can jia le huo dong");
        CHECK(toneless("学生长期住在学校") == "xue sheng chang qi zhu zai xue xiao");
        CHECK(toneless("公司长期亏损") == "gong si chang qi kui sun");
        CHECK(toneless("他们会计划好") == "ta men hui ji hua hao");
        CHECK(toneless("他还原谅了我") == "ta hai yuan liang le wo");
        // Matching from the end would take 都是 (dou1 shi4) here.
        CHECK(toneless("首都是北京") == "shou du shi bei jing");
        CHECK(toneless("人参是一种药材") == "ren shen shi yi zhong yao cai");
        CHECK(toneless("這家銀行長期支持小企業") == "zhe jia yin hang chang qi zhi chi xiao qi ye");
    }

    TEST_CASE("the particle 了 after a verb decides the cut and the reading of 还") {
        // 还 before the particle is the verb "return", huan2; before 了解 or in 还了得 the adverb.
        CHECK(toneless("他还了我一本书") == "ta huan le wo yi ben shu");
        CHECK(toneless("书他还了没有") == "shu ta huan le mei you");
        CHECK(toneless("他還了三本書") == "ta huan le san ben shu");
        CHECK(toneless("他还了解这个情况") == "ta hai liao jie zhe ge qing kuang");
        CHECK(toneless("这还了得") == "zhe hai liao de");
        // After a verb that takes 了, 了 is the particle where 解 starts a word with what follows.
        CHECK(toneless("我看了解说才明白") == "wo kan le jie shuo cai ming bai");
        CHECK(toneless("听了解释以后") == "ting le jie shi yi hou");
        CHECK(toneless("他寫了解決方案") == "ta xie le jie jue fang an");
        CHECK(toneless("我们去了解情况") == "wo men qu liao jie qing kuang");
        CHECK(toneless("我想了解说话的技巧") == "wo xiang liao jie shuo hua de ji qiao");
        CHECK(toneless("他很了解我") == "ta hen liao jie wo");
    }

    TEST_CASE("还 is the verb huan2 where the adverb hai2 cannot stand") {
        // Nothing after it in its clause: the adverb always modifies what follows.
        CHECK(toneless("借了东西要按时还。") == "jie le dong xi yao an shi huan");
        CHECK(toneless("「書要記得還」") == "shu yao ji de huan");
        // Before a person given something back, or a debt; asked as 还不还.
        CHECK(toneless("你什么时候还我钱") == "ni shen me shi hou huan wo qian");
        CHECK(toneless("他每个月都要还房贷") == "ta mei ge yue dou yao huan fang dai");
        CHECK(toneless("你到底还不还？") == "ni dao di huan bu huan");
        CHECK(toneless("你还不还钱") == "ni huan bu huan qian");
        // The adverb keeps hai2: before a verb or an adjective, and before a number, which is not
        // the clause's end (还500元 is cut before the number, not at a pause).
        CHECK(toneless("他还想再去一次") == "ta hai xiang zai qu yi ci");
        CHECK(toneless("他比我还高") == "ta bi wo hai gao");
        CHECK(toneless("他还不快走") == "ta hai bu kuai zou");
        CHECK(toneless("还有三天") == "hai you san tian");
        CHECK(toneless("这个月还500元") == "zhe ge yue hai wu bai yuan");
        CHECK(toneless("他还欠我钱") == "ta hai qian wo qian");
    }

    TEST_CASE("还得 is hai2 dei3, still have to, and 还得起 the verb with its complement") {
        CHECK(toneless("下班以后我还得去超市") == "xia ban yi hou wo hai dei qu chao shi");
        CHECK(toneless("我还得起床") == "wo hai dei qi chuang");
        CHECK(toneless("这么多钱你还得起吗") == "zhe me duo qian ni huan de qi ma");
        CHECK(toneless("他还不起") == "ta huan bu qi");
        CHECK(toneless("他还不起床") == "ta hai bu qi chuang");
        CHECK(toneless("我明天去机场还车") == "wo ming tian qu ji chang huan che");
    }

    TEST_CASE("还得了 and 还了得 are the idiom of outrage only where they end a clause") {
        // 得了 déliǎo, 了得 liǎo·de: 这还得了 "how can this be tolerated".
        CHECK(toneless("这还得了！") == "zhe hai de liao");
        CHECK(toneless("這還得了！") == "zhe hai de liao");
        CHECK(toneless("那还得了吗？") == "na hai de liao ma");
        CHECK(toneless("這還了得！") == "zhe hai liao de");
        // Elsewhere 了 is the particle: 得 "get" takes it (得 "must" never does), 还了 is returned.
        CHECK(toneless("他还得了第一名。") == "ta hai de le di yi ming");
        CHECK(toneless("他还了得到的钱。") == "ta huan le de dao de qian");
        CHECK(toneless("他還了得到的錢。") == "ta huan le de dao de qian");
    }

    TEST_CASE("得 before the particle 了 is the verb de2, and 得了 in 还得了 and 受得了 keeps liao") {
        // The particle de5 never takes 了: 得 is "get" (dé) or "enough" (得了 dé·le).
        CHECK(pinyin("他还得了第一名。") == "ta1 hai2 de2 le5 di4 yi1 ming2");
        CHECK(pinyin("他得了感冒") == "ta1 de2 le5 gan3 mao4");
        CHECK(pinyin("得了，别说了。") == "de2 le5 bie2 shuo1 le5");
        CHECK(pinyin("这还得了！") == "zhe4 hai2 de2 liao3");
        // 又得 也得 都得 are words of "must" (dei) in the phrase list; before 了 they are not (session 13).
        CHECK(pinyin("他又得了第一名。") == "ta1 you4 de2 le5 di4 yi1 ming2");
        CHECK(pinyin("他也得了奖。") == "ta1 ye3 de2 le5 jiang3");
        CHECK(pinyin("我们都得了感冒。") == "wo3 men5 dou1 de2 le5 gan3 mao4");
        // Elsewhere they are 得 "must", dei3 (tools/phrase_additions.tsv), and 得到 stays whole.
        CHECK(pinyin("明天我也得去。") == "ming2 tian1 wo3 ye3 dei3 qu4");
        CHECK(pinyin("下周他又得出差。") == "xia4 zhou1 ta1 you4 dei3 chu1 chai1");
        CHECK(toneless("孩子们又得到了新玩具。") == "hai zi men you de dao le xin wan ju");
        CHECK(pinyin("我受得了") == "wo3 shou4 de5 liao3");
        CHECK(pinyin("这个问题还得再讨论") == "zhe4 ge4 wen4 ti2 hai2 dei3 zai4 tao3 lun4");
    }

    TEST_CASE("得了 after a one-character verb is the potential complement de5 liao3") {
        CHECK(pinyin("你吃得了吗？") == "ni3 chi1 de5 liao3 ma5");
        CHECK(pinyin("我还走得了。") == "wo3 hai2 zou3 de5 liao3");
        CHECK(pinyin("你搬得了吗") == "ni3 ban1 de5 liao3 ma5");
        CHECK(pinyin("明天你来得了吗") == "ming2 tian1 ni3 lai2 de5 liao3 ma5");
        CHECK(pinyin("他管得了这么多") == "ta1 guan3 de5 liao3 zhe4 me5 duo1");
        // Not after an adverb or a subject, nor in a word of gain: 了 the particle there.
        CHECK(pinyin("他得了第一名") == "ta1 de2 le5 di4 yi1 ming2");
        CHECK(pinyin("他赢得了冠军").rfind("ta1 ying2 de2 le5", 0) == 0);  // 赢得 yíngdé, a word of gain
        CHECK(pinyin("我记得了") == "wo3 ji4 de5 le5");
        CHECK(pinyin("吃得{de2}了{le5}") == "chi1 de2 le5");
    }

    TEST_CASE("还 before a debt or with a complement closing its clause is the verb") {
        CHECK(toneless("我每个月都要还贷款。") == "wo mei ge yue dou yao huan dai kuan");
        CHECK(toneless("记得还信用卡") == "ji de huan xin yong ka");
        CHECK(toneless("他终于把钱还上了") == "ta zhong yu ba qian huan shang le");
        CHECK(toneless("早点还完吧，") == "zao dian huan wan ba");
        CHECK(toneless("早点还完了吗") == "zao dian huan wan le ma");
        // The adverb: the complement starts a word with what follows, or does not close the clause.
        CHECK(toneless("他还上学") == "ta hai shang xue");
        CHECK(toneless("还完成了任务") == "hai wan cheng le ren wu");
    }

    TEST_CASE("words the phrase list lacks or misreads come from tools/phrase_additions.tsv") {
        CHECK(toneless("他还没有还书") == "ta hai mei you huan shu");
        CHECK(toneless("他還沒有還書") == "ta hai mei you huan shu");
        CHECK(toneless("天气暖和了") == "tian qi nuan huo le");
        CHECK(toneless("天氣很暖和") == "tian qi hen nuan huo");
        CHECK(toneless("妈妈在和面") == "ma ma zai huo mian");
        CHECK(toneless("他衣锦还乡") == "ta yi jin huan xiang");
        // The words around them are cut as before.
        CHECK(toneless("我和面包店的老板很熟") == "wo he mian bao dian de lao ban hen shu");
    }

    TEST_CASE("a light tone is said in the words that have it, the full tone elsewhere (issue 13)") {
        CHECK(pinyin("欢迎") == "huan1 ying2");
        CHECK(pinyin("喜欢") == "xi3 huan5");
        CHECK(pinyin("歡迎光臨") == "huan1 ying2 guang1 lin2");
        CHECK(pinyin("我很喜歡") == "wo3 hen3 xi3 huan5");
        CHECK(pinyin("信息") == "xin4 xi1");
        CHECK(pinyin("消息") == "xiao1 xi5");
        CHECK(pinyin("服务") == "fu2 wu4");
        CHECK(pinyin("西安") == "xi1 an1");
        CHECK(pinyin("买东西") == "mai3 dong1 xi5");
        CHECK(pinyin("东西方") == "dong1 xi1 fang1");
        CHECK(pinyin("训练") == "xun4 lian4");
        CHECK(pinyin("识别") == "shi2 bie2");
        CHECK(pinyin("认识") == "ren4 shi5");
        // A compound says a word of tools/phrase_additions.tsv as the word is said alone.
        CHECK(pinyin("好朋友") == "hao3 peng2 you5");
        CHECK(pinyin("知识分子") == "zhi1 shi5 fen4 zi3");
    }

    TEST_CASE("news' words for adding up, adjusting and recording a figure take the tone they mean") {
        CHECK(pinyin("今年累计上涨") == "jin1 nian2 lei3 ji4 shang4 zhang3");
        CHECK(pinyin("累積雨量") == "lei3 ji1 yu3 liang4");
        CHECK(pinyin("经验的积累") == "jing1 yan4 de5 ji1 lei3");
        CHECK(pinyin("央行调降利率") == "yang1 hang2 tiao2 jiang4 li4 lv4");
        CHECK(pinyin("月薪調升至") == "yue4 xin1 tiao2 sheng1 zhi4");
        CHECK(pinyin("天文台錄得") == "tian1 wen2 tai2 lu4 de2");
        // The character alone keeps its common reading: tired, a tune, the light 得.
        CHECK(pinyin("我很累") == "wo3 hen3 lei4");
        CHECK(pinyin("升调") == "sheng1 diao4");
        CHECK(pinyin("记得") == "ji4 de5");
    }

    TEST_CASE("a diamond, a drill and a backpack take the tone of the noun, not of the verb's") {
        CHECK(pinyin("这颗钻石很贵") == "zhe4 ke1 zuan4 shi2 hen3 gui4");
        CHECK(pinyin("鑽戒") == "zuan4 jie4");
        CHECK(pinyin("换个钻头") == "huan4 ge4 zuan4 tou2");
        CHECK(pinyin("一把電鑽") == "yi1 ba3 dian4 zuan4");
        CHECK(pinyin("我的背包呢") == "wo3 de5 bei1 bao1 ne5");
        // The verbs keep theirs: to drill, to memorise, the back.
        CHECK(pinyin("钻研") == "zuan1 yan2");
        CHECK(pinyin("背书") == "bei4 shu1");
        CHECK(pinyin("后背") == "hou4 bei4");
    }

    TEST_CASE(
        "particles are light, and a suffix is light after a word's first character, full at its start") {
        CHECK(pinyin("我们的") == "wo3 men5 de5");
        CHECK(pinyin("好了吗") == "hao3 le5 ma5");
        CHECK(pinyin("孩子") == "hai2 zi5");
        CHECK(pinyin("子女") == "zi3 nv3");
        CHECK(pinyin("电子") == "dian4 zi3");
        CHECK(pinyin("儿童") == "er2 tong2");
        CHECK(pinyin("女儿") == "nv3 er2");
        CHECK(pinyin("觉得") == "jue2 de5");
        CHECK(pinyin("得到") == "de2 dao4");
        CHECK(pinyin("获得") == "huo4 de2");
        CHECK(pinyin("好得多") == "hao3 de5 duo1");
        CHECK(pinyin("公園裡") == "gong1 yuan2 li5");
        CHECK(pinyin("裡面") == "li3 mian4");
    }

    TEST_CASE("a character's first reading is a full tone unless it is a particle or a suffix") {
        // tools/make_readings.py's LIGHT_FIRST: the characters whose light tone is a grammatical
        // word or a suffix. Before issue 13, 130 characters led with a light tone (欢 息 识 务 西 ...).
        const std::string light_first =
            "的地了着著吗嗎呢吧啊呀啦嘛呗唄喽嘍哇哩咧呐吶嘞么麼嚜噷子儿兒们們得裡";
        const auto& tables = detail::reading_tables();
        for (const auto line : tables.character_lines().lines()) {
            const auto character = detail::SortedLines::key_of(line);
            const auto readings = tables.readings(character);
            const bool has_full = std::any_of(readings.begin(), readings.end(),
                                              [](std::string_view reading) { return reading.back() != '5'; });
            if (!has_full || light_first.find(character) != std::string::npos) continue;
            CAPTURE(character);
            CHECK(readings.front().back() != '5');
        }
    }

    TEST_CASE("a tone the 2013 standard dictionary gives alone is the first reading") {
        CHECK(pinyin("成绩") == "cheng2 ji4");
        CHECK(pinyin("事迹") == "shi4 ji4");
        CHECK(pinyin("甚至") == "shen4 zhi4");
    }

    TEST_CASE("长 where no word covers it is chang2, the adjective, and the verb zhang3 comes in words") {
        // Session 21 (tools/make_readings.py FIRST_BY_USAGE): 友谊长存 was zhang3, kHanyuPinlu's first
        // reading.
        CHECK(pinyin("友谊长存") == "you3 yi4 chang2 cun2");
        CHECK(pinyin("這條路長約三公里") == "zhe4 tiao2 lu4 chang2 yue1 san1 gong1 li3");
        CHECK(toneless("他长得很高") == "ta zhang de hen gao");
        CHECK(toneless("孩子长大了") == "hai zi zhang da le");
        CHECK(toneless("校长和家长") == "xiao zhang he jia zhang");
        CHECK(toneless("她是家里的长女") == "ta shi jia li de zhang nv");
    }

    TEST_CASE("长 right after a place or a body it heads is zhang3, where the cut leaves it alone") {
        // Failed on main 6db43b6: the list's 台北市 and 广东省 cut the title 市长 省长 in two.
        CHECK(pinyin("台北市长") == "tai2 bei3 shi4 zhang3");
        CHECK(pinyin("臺北市長今日宣布") == "tai2 bei3 shi4 zhang3 jin1 ri4 xuan1 bu4");
        CHECK(pinyin("广东省长视察") == "guang3 dong1 sheng3 zhang3 shi4 cha2");
        CHECK(toneless("派出所长来了") == "pai chu suo zhang lai le");
        // A word 长 starts keeps its own reading, and a length keeps chang2.
        CHECK(toneless("北京市长安街") == "bei jing shi chang an jie");
        CHECK(toneless("这座城市长年下雨") == "zhe zuo cheng shi chang nian xia yu");
        CHECK(toneless("我在城市长大") == "wo zai cheng shi zhang da");
        CHECK(toneless("这条路长约三公里") == "zhe tiao lu chang yue san gong li");
    }

    TEST_CASE("a Traditional character reads in the sense its Simplified form took over") {
        // Failed on main 6db43b6: Unihan's Simplified fields list 徵 乾 鉻 in their rarer sense alone (the
        // note zhi3, the qian2 of 乾隆, luo4), and the Traditional forms of common single characters
        // cost as much as their rare entries in the Simplified list (於 1147 where 于 is 731).
        CHECK(pinyin("加徵關稅") == "jia1 zheng1 guan1 shui4");
        CHECK(pinyin("加入乾酵母") == "jia1 ru4 gan1 jiao4 mu3");
        CHECK(pinyin("鍍鉻") == "du4 ge4");
        CHECK(pinyin("隔閡") == "ge2 he2");
        CHECK(pinyin("我很瞭解他") == "wo3 hen3 liao3 jie3 ta1");
        CHECK(toneless("請家長於週五前繳費") == toneless("请家长于周五前缴费"));
        CHECK(toneless("請家長於週五前繳費") == "qing jia zhang yu zhou wu qian jiao fei");
        // The rarer sense stays where a word spells it, and where the character is Simplified's own.
        CHECK(pinyin("乾隆") == "qian2 long2");
        CHECK(pinyin("瞭望") == "liao4 wang4");
        CHECK(pinyin("哪吒") == "ne2 zha1");
        // 仆 is pu2 (仆人, 公仆) but in 前仆后继.
        CHECK(pinyin("他是我的仆人") == "ta1 shi4 wo3 de5 pu2 ren2");
        CHECK(pinyin("前仆后继") == "qian2 pu1 hou4 ji4");
    }

    TEST_CASE("长 of a length's noun and after 这么 or 那么 is chang2 before 的") {
        // Every row but the limits failed on main 7a33214 (session 32, dev29): the phrase list's 长的
        // zhang3 de5 ("grown") took the 长, its noun or adverb left out of the list.
        CHECK(toneless("正方形的面积等于边长的平方") ==
              "zheng fang xing de mian ji deng yu bian chang de ping fang");
        CHECK(toneless("正方形的面積等於邊長的平方") ==
              "zheng fang xing de mian ji deng yu bian chang de ping fang");
        CHECK(toneless("身长的一半") == "shen chang de yi ban");
        CHECK(toneless("那么长的时间") == "na me chang de shi jian");
        CHECK(toneless("這麼長的頭髮") == "zhe me chang de tou fa");
        // The limits: the verb "grown", and a head's 长.
        CHECK(toneless("新长的叶子") == "xin zhang de ye zi");
        CHECK(toneless("校长的话") == "xiao zhang de hua");
    }

    TEST_CASE("得 alone after a person is dei3, must, unless what follows makes it the verb get") {
        // Each row but the limits failed on main f5421d4 (dev45, session 44): de5, the particle.
        CHECK(toneless("我们得赶紧去给他庆祝") == "wo men dei gan jin qu gei ta qing zhu");
        CHECK(toneless("你得重新写一遍") == "ni dei chong xin xie yi bian");
        CHECK(pinyin("大家得注意安全") == "da4 jia1 dei3 zhu4 yi4 an1 quan2");
        CHECK(pinyin("我得去医院") == "wo3 dei3 qu4 yi1 yuan4");
        // The limits: 得 that gets (before 了 过 的 到 or a count), the particle after a verb, and words.
        CHECK(pinyin("我们得了第一名") == "wo3 men5 de2 le5 di4 yi1 ming2");
        CHECK(toneless("她得过三次奖") == "ta de guo san ci jiang");
        CHECK(toneless("我得的是感冒") == "wo de de shi gan mao");
        CHECK(toneless("你得到了吗") == "ni de dao le ma");
        CHECK(toneless("他得一百分") == "ta de yi bai fen");
        CHECK(toneless("他跑得快") == "ta pao de kuai");
        CHECK(toneless("我得知这个消息") == "wo de zhi zhe ge xiao xi");
    }

    TEST_CASE("背 carrying on the back is bei1 in 背着 and 背起, and the back keeps bei4") {
        // Each row but the limits failed on main f5421d4 (dev45, session 44): bei4.
        CHECK(pinyin("他背着书包") == "ta1 bei1 zhe5 shu1 bao1");
        CHECK(pinyin("他背著吉他") == "ta1 bei1 zhe5 ji2 ta1");
        CHECK(pinyin("背起行囊") == "bei1 qi3 xing2 nang2");
        // The limits: the back, and hands clasped behind it.
        CHECK(pinyin("站在我背后") == "zhan4 zai4 wo3 bei4 hou4");
        CHECK(pinyin("照片的背景") == "zhao4 pian4 de5 bei4 jing3");
        CHECK(pinyin("他背着手") == "ta1 bei4 zhe5 shou3");
    }

    TEST_CASE(
        "数 counting is shu3 before a particle and in the words that count, and the number keeps shu4") {
        // Each row but the limits failed on main f5421d4 (dev45, session 44): shu4.
        CHECK(pinyin("我數了三遍") == "wo3 shu3 le5 san1 bian4");
        CHECK(pinyin("你数一数") == "ni3 shu3 yi1 shu3");
        CHECK(pinyin("数不清") == "shu3 bu4 qing1");
        CHECK(pinyin("数落他") == "shu3 luo5 ta1");
        // The limits: the noun.
        CHECK(pinyin("数学") == "shu4 xue2");
        CHECK(pinyin("錢的數目") == "qian2 de5 shu4 mu4");
    }

    TEST_CASE("行 of a bank's clerk is hang2, and a pilot's keeps xing2") {
        // The first row failed on main f5421d4 (dev45, session 44): xing2.
        CHECK(toneless("銀行的行員說") == "yin hang de hang yuan shuo");
        CHECK(toneless("飞行员") == "fei xing yuan");
    }

    TEST_CASE(
        "a word whose character differs from its commonest reading in the tone alone takes the word's tone") {
        // Each row but the limits failed on main 2167fb4 (readings_dev2, session 44): shao3, wei4, jia3,
        // zhao2, geng4, kong1, guan1, dao4, cheng1.
        CHECK(pinyin("青少年的爱好") == "qing1 shao4 nian2 de5 ai4 hao4");
        CHECK(pinyin("他认为这是化学反应") == "ta1 ren4 wei2 zhe4 shi4 hua4 xue2 fan3 ying4");
        CHECK(pinyin("暑假期间") == "shu3 jia4 qi1 jian1");
        CHECK(pinyin("飞机着陆") == "fei1 ji1 zhuo2 lu4");
        CHECK(pinyin("系统变更") == "xi4 tong3 bian4 geng1");
        CHECK(pinyin("周末有空吗") == "zhou1 mo4 you3 kong4 ma5");
        CHECK(pinyin("世界冠軍") == "shi4 jie4 guan4 jun1");
        CHECK(pinyin("他摔倒了") == "ta1 shuai1 dao3 le5");
        CHECK(pinyin("难不倒他") == "nan2 bu4 dao3 ta1");
        CHECK(pinyin("称心如意") == "chen4 xin1 ru2 yi4");
        // The limits: the words of the commonest reading.
        CHECK(pinyin("因为") == "yin1 wei4");
        CHECK(pinyin("应该") == "ying1 gai1");
        CHECK(pinyin("真假") == "zhen1 jia3");
        CHECK(pinyin("更加") == "geng4 jia1");
        CHECK(pinyin("空气") == "kong1 qi4");
        CHECK(pinyin("倒水") == "dao4 shui3");
        CHECK(pinyin("只有") == "zhi3 you3");
    }

    TEST_CASE("the list's words of a polyphone's other tone, from a pass over every word holding it") {
        // Each row but the limits failed on main cf76347: wei4 twice, geng4 twice, nan2, ying1 twice,
        // jia3, hao3, kong1, shao3, dao4, zhong3, zhi3, zhao2.
        CHECK(pinyin("他被评为先进") == "ta1 bei4 ping2 wei2 xian1 jin4");
        CHECK(pinyin("温度约为二十度") == "wen1 du4 yue1 wei2 er4 shi2 du4");
        CHECK(pinyin("软件更新") == "ruan3 jian4 geng1 xin1");
        CHECK(pinyin("三更半夜") == "san1 geng1 ban4 ye4");
        CHECK(pinyin("这场灾难") == "zhe4 chang3 zai1 nan4");
        CHECK(pinyin("这是化学感应") == "zhe4 shi4 hua4 xue2 gan3 ying4");
        CHECK(pinyin("应付考试") == "ying4 fu5 kao3 shi4");
        CHECK(pinyin("国庆放假") == "guo2 qing4 fang4 jia4");
        CHECK(pinyin("好强的孩子") == "hao4 qiang2 de5 hai2 zi5");
        CHECK(pinyin("按空格键") == "an4 kong4 ge2 jian4");
        CHECK(pinyin("少林寺") == "shao4 lin2 si4");
        CHECK(pinyin("大楼倒塌") == "da4 lou2 dao3 ta1");
        CHECK(pinyin("种下一棵树") == "zhong4 xia4 yi1 ke1 shu4");
        CHECK(pinyin("只身一人") == "zhi1 shen1 yi1 ren2");
        CHECK(pinyin("要替对方着想") == "yao4 ti4 dui4 fang1 zhuo2 xiang3");
        // The limit: an adverb before 为 keeps the character's commonest reading, wèi "for" (曾为公司 工作),
        // the pass left those words out, wéi "to be" as often (曾为教师).
        CHECK(pinyin("他曾为公司工作") == "ta1 ceng2 wei4 gong1 si1 gong1 zuo4");
    }

    TEST_CASE("the list's words of the rarer tone of 要 中 当 差 发 分 相 与 将 散 看 强 正 冲") {
        // Each row but the limit failed on main cf76347: yao4, zhong1, dang1, cha4, fa1, fen1, xiang1, yu3,
        // jiang1, san4, kan4, qiang2, zheng4, chong1.
        CHECK(pinyin("这是总体要求") == "zhe4 shi4 zong3 ti3 yao1 qiu2");
        CHECK(pinyin("我中奖了") == "wo3 zhong4 jiang3 le5");
        CHECK(pinyin("把我当作朋友") == "ba3 wo3 dang4 zuo4 peng2 you5");
        CHECK(pinyin("两组差异很大") == "liang3 zu3 cha1 yi4 hen3 da4");
        CHECK(pinyin("他去理发了") == "ta1 qu4 li3 fa4 le5");
        CHECK(pinyin("主要成分") == "zhu3 yao4 cheng2 fen4");
        CHECK(pinyin("这台相机") == "zhe4 tai2 xiang4 ji1");
        CHECK(pinyin("选民参与投票") == "xuan3 min2 can1 yu4 tou2 piao4");
        CHECK(pinyin("一位将领") == "yi1 wei4 jiang4 ling3");
        CHECK(pinyin("散文集") == "san3 wen2 ji2");
        CHECK(pinyin("看守大门") == "kan1 shou3 da4 men2");
        CHECK(pinyin("勉强同意") == "mian3 qiang3 tong2 yi4");
        CHECK(pinyin("正月十五") == "zheng1 yue4 shi2 wu3");
        CHECK(pinyin("冲着我笑") == "chong4 zhe5 wo3 xiao4");
        // The limit: 名将 is left out, a cut takes it from 三名 before 将 "will".
        CHECK(pinyin("前三名将获得奖品") == "qian2 san1 ming2 jiang1 huo4 de2 jiang3 pin3");
    }

    TEST_CASE("种 and 只 after a count are measure words, 种 elsewhere and 教 alone are verbs") {
        // Each row but the limits failed on main 2167fb4 (readings_dev2, session 44): zhong3, zhi3, jiao4.
        CHECK(pinyin("老师教我们唱歌") == "lao3 shi1 jiao1 wo3 men5 chang4 ge1");
        CHECK(pinyin("妈妈教孩子画画") == "ma1 ma5 jiao1 hai2 zi5 hua4 hua4");
        CHECK(pinyin("他去年种了几棵树") == "ta1 qu4 nian2 zhong4 le5 ji3 ke1 shu4");
        CHECK(pinyin("八只羊") == "ba1 zhi1 yang2");
        CHECK(pinyin("三只鸡") == "san1 zhi1 ji1");
        // The limits: the words of 教 and 种, a measure word, and 只 the adverb.
        CHECK(pinyin("教育") == "jiao4 yu4");
        CHECK(pinyin("请教") == "qing3 jiao4");
        CHECK(pinyin("种子") == "zhong3 zi5");
        CHECK(pinyin("有三种颜色") == "you3 san1 zhong3 yan2 se4");
        CHECK(pinyin("这只是开始") == "zhe4 zhi3 shi4 kai1 shi3");
        // 种 counted by a written number, or by 多少, stays the measure word.
        CHECK(pinyin("第3种情况") == "di4 san1 zhong3 qing2 kuang4");
        CHECK(pinyin("有10多种") == "you3 shi2 duo1 zhong3");
        CHECK(pinyin("有多少种") == "you3 duo1 shao3 zhong3");
    }

    TEST_CASE("news read aloud: 只 counted by a written number, 为 between a quantity and its value") {
        // Each row but the limits failed on main 1e20c3d (readings_dev3, session 45): zhi3 twice, wei4 three
        // times.
        CHECK(pinyin("动物园有2只猫") == "dong4 wu4 yuan2 you3 liang3 zhi1 mao1");
        CHECK(pinyin("科创50成分股中有32只股票上涨") ==
              "ke1 chuang4 wu3 shi2 cheng2 fen4 gu3 zhong1 you3 san1 shi2 er4 zhi1 gu3 piao4 shang4 zhang3");
        CHECK(pinyin("失业率为3.9%") == "shi1 ye4 lv4 wei2 bai3 fen1 zhi1 san1 dian3 jiu3");
        CHECK(pinyin("PM2.5浓度为每立方米35微克") ==
              "pi1 ai2 mu5 er4 dian3 wu3 nong2 du4 wei2 mei3 li4 fang1 mi3 san1 shi2 wu3 wei1 ke4");
        CHECK(pinyin("今年7月平均气温为23.3℃") ==
              "jin1 nian2 qi1 yue4 ping2 jun1 qi4 wen1 wei2 er4 shi2 san1 dian3 san1 she4 shi4 du4");
        // The limits: 只 the adverb after a percentage or a time, 为 "for" after a title or a noun no value
        // follows.
        CHECK(pinyin("涨幅30%只是开始") == "zhang3 fu2 bai3 fen1 zhi1 san1 shi2 zhi3 shi4 kai1 shi3");
        CHECK(pinyin("下午3:00只剩两人") == "xia4 wu3 san1 dian3 zhi3 sheng4 liang3 ren2");
        CHECK(pinyin("部长为此道歉") == "bu4 zhang3 wei4 ci3 dao4 qian4");
        CHECK(pinyin("制度为经济发展服务") == "zhi4 du4 wei4 jing1 ji4 fa1 zhan3 fu2 wu4");
    }

    TEST_CASE("为 after 以 and what it takes is wéi, \"as\"") {
        // Each row but the limits failed on main 7e809fa (session 45): wei4.
        CHECK(pinyin("一切以安全为重") == "yi1 qie4 yi3 an1 quan2 wei2 zhong4");
        CHECK(pinyin("我们以他为榜样") == "wo3 men5 yi3 ta1 wei2 bang3 yang4");
        CHECK(pinyin("以经济建设为中心") == "yi3 jing1 ji4 jian4 she4 wei2 zhong1 xin1");
        // The limits: 以 inside a word (可以 以前), and 为了 "for".
        CHECK(pinyin("可以为你做饭") == "ke3 yi3 wei4 ni3 zuo4 fan4");
        CHECK(pinyin("以前为了省钱") == "yi3 qian2 wei4 le5 sheng3 qian2");
    }

    TEST_CASE("地 after a demonstrative or a measure word of land is the noun, 假 after a span the leave") {
        // Each row but the limits failed on main 1e20c3d: de5 twice, jia3.
        CHECK(pinyin("该地发生地震") == "gai1 di4 fa1 sheng1 di4 zhen4");
        CHECK(pinyin("这块地种满了玉米") == "zhe4 kuai4 di4 zhong4 man3 le5 yu4 mi3");
        CHECK(pinyin("我请了三天假") == "wo3 qing3 le5 san1 tian1 jia4");
        // The limits: the adverb's 地, after a word said twice too, and 假 "false".
        CHECK(pinyin("她慢慢地走") == "ta1 man4 man4 de5 zou3");
        CHECK(pinyin("一片片地倒下") == "yi1 pian4 pian4 de5 dao3 xia4");
        CHECK(pinyin("这是假的") == "zhe4 shi4 jia3 de5");
    }

    TEST_CASE("中 after a count of shots taken and a count made is zhòng, as a box score writes it") {
        // Each row but the limits failed on main bea23b7 (readings_dev4, session 46): zhong1.
        CHECK(pinyin("他三分球12投7中") == "ta1 san1 fen1 qiu2 shi2 er4 tou2 qi1 zhong4");
        CHECK(pinyin("全场6罚5中") == "quan2 chang3 liu4 fa2 wu3 zhong4");
        CHECK(pinyin("三分球５投０中") == "san1 fen1 qiu2 wu3 tou2 ling2 zhong4");
        // The limits: a school's number, and a number before 中 with no attempts before it.
        CHECK(pinyin("他在7中读书") == "ta1 zai4 qi1 zhong1 du2 shu1");
        CHECK(pinyin("投3中的学生") == "tou2 san1 zhong1 de5 xue2 sheng1");
    }

    TEST_CASE("切 alone is cut, qiē, and 撒 before what a cook strews is sǎ") {
        // Each row but the limits failed on main bea23b7 (readings_dev4, session 46): qie4 twice, sa1 three
        // times, zhong1.
        CHECK(pinyin("土豆去皮切薄片") == "tu3 dou4 qu4 pi2 qie1 bao2 pian4");
        CHECK(pinyin("把肉切好") == "ba3 rou4 qie1 hao3");
        CHECK(pinyin("出锅前撒葱花") == "chu1 guo1 qian2 sa3 cong1 hua1");
        CHECK(pinyin("撒点盐") == "sa3 dian3 yan2");
        CHECK(pinyin("盐撒在地上") == "yan2 sa3 zai4 di4 shang4");
        CHECK(pinyin("切中要害") == "qie4 zhong4 yao4 hai4");
        // The limits: 切 qiè in its words, the adverb and names, 撒 sā cast or let go and in names.
        CHECK(pinyin("一切都好") == "yi1 qie4 dou1 hao3");
        CHECK(pinyin("切不可大意") == "qie4 bu4 ke3 da4 yi4");
        CHECK(pinyin("切尔西队") == "qie4 er3 xi1 dui4");
        CHECK(pinyin("撒切尔夫人") == "sa1 qie4 er3 fu1 ren2");
        CHECK(pinyin("撒网捕鱼") == "sa1 wang3 bu3 yu2");
        CHECK(pinyin("撒手不管") == "sa1 shou3 bu4 guan3");
        CHECK(pinyin("撒哈拉沙漠") == "sa1 ha1 la1 sha1 mo4");
    }

    TEST_CASE("觉 alone after 睡 and what is said of the sleep is the sleep, jiào") {
        // Each row but the limits failed on main bea23b7 (readings_dev4, session 46): jue2.
        CHECK(pinyin("一直睡不着觉") == "yi1 zhi2 shui4 bu4 zhao2 jiao4");
        CHECK(pinyin("中午睡了个觉") == "zhong1 wu3 shui4 le5 ge4 jiao4");
        CHECK(pinyin("周末睡大觉") == "zhou1 mo4 shui4 da4 jiao4");
        // The limits: the feeling's 觉, alone or in its words.
        CHECK(pinyin("不知不觉") == "bu4 zhi1 bu4 jue2");
        CHECK(pinyin("我觉不出") == "wo3 jue2 bu4 chu1");
        CHECK(pinyin("睡醒后只觉得累") == "shui4 xing3 hou4 zhi3 jue2 de5 lei4");
    }

    TEST_CASE("得 after a person before a prize or a count is dé, before a verb děi") {
        // Each row but the limit failed on main 1e20c3d: dei3 twice, de5.
        CHECK(pinyin("她得冠军了") == "ta1 de2 guan4 jun1 le5");
        CHECK(pinyin("他得金牌了") == "ta1 de2 jin1 pai2 le5");
        CHECK(pinyin("他得一百分") == "ta1 de2 yi1 bai3 fen1");
        // The limit: 得 "must".
        CHECK(pinyin("我们得赶紧走") == "wo3 men5 dei3 gan3 jin3 zou3");
    }

    TEST_CASE(
        "the list's words of 兴 xīng, 冠 guàn and 鲜 xiǎn, 押解 and 执行长, and 儿 or 子 beginning a noun") {
        // Each row but the limits failed on main 1e20c3d: xing4 three times, guan1 twice, xian1, jie3,
        // chang2, er5, zi5.
        CHECK(pinyin("他很兴奋") == "ta1 hen3 xing1 fen4");
        CHECK(pinyin("民族复兴") == "min2 zu2 fu4 xing1");
        CHECK(pinyin("兴建学校") == "xing1 jian4 xue2 xiao4");
        CHECK(pinyin("中国队夺冠") == "zhong1 guo2 dui4 duo2 guan4");
        CHECK(pinyin("欧冠决赛") == "ou1 guan4 jue2 sai4");
        CHECK(pinyin("朝鲜半岛") == "chao2 xian3 ban4 dao3");
        CHECK(pinyin("嫌犯被押解回国") == "xian2 fan4 bei4 ya1 jie4 hui2 guo2");
        CHECK(pinyin("公司执行长") == "gong1 si1 zhi2 xing2 zhang3");
        CHECK(pinyin("少年儿童") == "shao4 nian2 er2 tong2");
        CHECK(pinyin("炎黄子孙") == "yan2 huang2 zi3 sun1");
        // The limits: 兴 xìng, 冠 guān, 鲜 xiān, and the suffixes and complements that stay light.
        CHECK(pinyin("他对音乐感兴趣") == "ta1 dui4 yin1 yue4 gan3 xing4 qu4");
        CHECK(pinyin("很高兴") == "hen3 gao1 xing4");
        CHECK(pinyin("皇冠") == "huang2 guan1");
        CHECK(pinyin("新冠疫情") == "xin1 guan1 yi4 qing2");
        CHECK(pinyin("新鲜水果") == "xin1 xian1 shui3 guo3");
        CHECK(pinyin("孩子们") == "hai2 zi5 men5");
        CHECK(pinyin("看得到") == "kan4 de5 dao4");
    }

    TEST_CASE("the list's words of 供 gòng and 量 liáng") {
        // Each row but the limits failed on main 1e20c3d: liang4 four times, gong1.
        CHECK(pinyin("用仪器测量") == "yong4 yi2 qi4 ce4 liang2");
        CHECK(pinyin("如何衡量") == "ru2 he2 heng2 liang2");
        CHECK(pinyin("他上下打量着我") == "ta1 shang4 xia4 da3 liang5 zhe5 wo3");
        CHECK(pinyin("供奉祖先") == "gong4 feng4 zu3 xian1");
        CHECK(pinyin("量身定做") == "liang2 shen1 ding4 zuo4");
        // The limits: 量 liàng, an amount, and 供 gōng, supply.
        CHECK(pinyin("质量很好") == "zhi4 liang4 hen3 hao3");
        CHECK(pinyin("提供服务") == "ti2 gong1 fu2 wu4");
    }

    TEST_CASE("为 after a verb of choosing or naming is wéi, \"as\"") {
        // Each row but the limits fails on main bea23b7 (session 45's readings_dev3): wei4.
        CHECK(pinyin("他当选为主席") == "ta1 dang1 xuan3 wei2 zhu3 xi2");
        CHECK(pinyin("她被评选为优秀教师") == "ta1 bei4 ping2 xuan3 wei2 you1 xiu4 jiao4 shi1");
        CHECK(pinyin("他被任命为校长") == "ta1 bei4 ren4 ming4 wei2 xiao4 zhang3");
        CHECK(pinyin("他當選為立法委員") == "ta1 dang1 xuan3 wei2 li4 fa3 wei3 yuan2");
        // The limits: 为 "for" after a word whose last character makes a wéi word of the list with it.
        CHECK(pinyin("银行为客户提供贷款") == "yin2 hang2 wei4 ke4 hu4 ti2 gong1 dai4 kuan3");
        CHECK(pinyin("本人为此负责") == "ben3 ren2 wei4 ci3 fu4 ze2");
    }

    TEST_CASE("兴 xīng in words the list lacked") {
        // Each row but the limit fails on main bea23b7 (session 45): xing4.
        CHECK(pinyin("国家兴亡") == "guo2 jia1 xing1 wang2");
        CHECK(pinyin("百废待兴") == "bai3 fei4 dai4 xing1");
        CHECK(pinyin("兴修水利") == "xing1 xiu1 shui3 li4");
        CHECK(pinyin("興師動眾") == "xing1 shi1 dong4 zhong4");
        // The limit: 兴 xìng, mood.
        CHECK(pinyin("他很高兴") == "ta1 hen3 gao1 xing4");
    }

    TEST_CASE(
        "倒数 counts down or from the end, dào shǔ, and is the reciprocal, dàoshù, where a noun stands") {
        // Each row but the limits fails on main bea23b7 (session 45's readings_dev3): shu4.
        CHECK(pinyin("倒数第二名") == "dao4 shu3 di4 er4 ming2");
        CHECK(pinyin("我们一起倒数三秒") == "wo3 men5 yi1 qi3 dao4 shu3 san1 miao3");
        CHECK(pinyin("他的排名倒數第一") == "ta1 de5 pai2 ming2 dao4 shu3 di4 yi1");
        // The limits: the reciprocal after 的 and in 互为倒数.
        CHECK(pinyin("二的倒数是二分之一") == "er4 de5 dao4 shu4 shi4 er4 fen1 zhi1 yi1");
        CHECK(pinyin("这两个数互为倒数") == "zhe4 liang3 ge4 shu4 hu4 wei2 dao4 shu4");
    }

    TEST_CASE("为 before a share that closes its clause, or after a count's noun, is wéi") {
        // Each row but the limits fails on main bea23b7 (session 45's readings_dev3): wei4.
        CHECK(pinyin("对手为45.1%") == "dui4 shou3 wei2 bai3 fen1 zhi1 si4 shi2 wu3 dian3 yi1");
        CHECK(pinyin("男性为52%，女性为48%") ==
              "nan2 xing4 wei2 bai3 fen1 zhi1 wu3 shi2 er4 nv3 xing4 wei2 bai3 fen1 zhi1 si4 shi2 ba1");
        CHECK(pinyin("得票数为1200票") == "de2 piao4 shu4 wei2 yi1 qian1 er4 bai3 piao4");
        // The limits: a share that counts whom 为 is for, and 为 before no value.
        CHECK(pinyin("为50%的家庭提供补贴") ==
              "wei4 bai3 fen1 zhi1 wu3 shi2 de5 jia1 ting2 ti2 gong1 bu3 tie1");
        CHECK(pinyin("无数为国牺牲的英雄") == "wu2 shu4 wei4 guo2 xi1 sheng1 de5 ying1 xiong2");
    }

    TEST_CASE("得 before a written count is dé, before a time or a little more of a verb děi") {
        // Each row but the limits fails on main bea23b7 (session 45's readings_dev3): de5.
        CHECK(pinyin("他得100分") == "ta1 de2 yi1 bai3 fen1");
        CHECK(pinyin("我得5点起床") == "wo3 dei3 wu3 dian3 qi3 chuang2");
        CHECK(pinyin("这道菜得多放点盐") == "zhe4 dao4 cai4 dei3 duo1 fang4 dian3 yan2");
        CHECK(pinyin("天冷了，得少出点门") == "tian1 leng3 le5 dei3 shao3 chu1 dian3 men2");
        CHECK(pinyin("這道菜得多放點鹽") == "zhe4 dao4 cai4 dei3 duo1 fang4 dian3 yan2");
        // The limits: 得 the particle before 多 of degree and an adjective, the comparison's 得多, and a
        // verb's complement, 多 and 了 before 些.
        CHECK(pinyin("她长得多漂亮") == "ta1 zhang3 de5 duo1 piao4 liang5");
        CHECK(pinyin("这个比那个好得多") == "zhe4 ge4 bi3 na4 ge4 hao3 de5 duo1");
        CHECK(pinyin("盐放得多了些") == "yan2 fang4 de5 duo1 le5 xie1");
    }

    TEST_CASE("sports, markets, weather, health and recipes: the list's words of 将 jiàng, 切 qiē, 间 jiàn") {
        // Each row but the limits failed on main bea23b7 (readings_dev4, session 46): jiang1 twice, qie4
        // twice, jian1 twice, men4, e4 xin1, hai4.
        CHECK(pinyin("老将梅西主罚角球") == "lao3 jiang4 mei2 xi1 zhu3 fa2 jiao3 qiu2");
        CHECK(pinyin("门将扑救") == "men2 jiang4 pu1 jiu4");
        CHECK(pinyin("土豆切成薄片") == "tu3 dou4 qie1 cheng2 bao2 pian4");
        CHECK(pinyin("先切菜") == "xian1 qie1 cai4");
        CHECK(pinyin("间隔二十一天") == "jian4 ge2 er4 shi2 yi1 tian1");
        CHECK(pinyin("间接影响") == "jian4 jie1 ying3 xiang3");
        CHECK(pinyin("天气闷热") == "tian1 qi4 men1 re4");
        CHECK(pinyin("头晕恶心") == "tou2 yun1 e3 xin5");
        CHECK(pinyin("咳嗽得厉害") == "ke2 sou5 de5 li4 hai5");
        // The limits: 将 jiāng, 切 qiè, 间 jiān and 闷 mèn in their own words.
        CHECK(pinyin("比赛即将开始") == "bi3 sai4 ji2 jiang1 kai1 shi3");
        CHECK(pinyin("一切顺利") == "yi1 qie4 shun4 li4");
        CHECK(pinyin("密切合作") == "mi4 qie4 he2 zuo4");
        CHECK(pinyin("时间不多") == "shi2 jian1 bu4 duo1");
        CHECK(pinyin("心情郁闷") == "xin1 qing2 yu4 men4");
    }

    TEST_CASE("为 between a report's sum or count and its value is wéi, and 量 measured is liáng") {
        // Each row but the limits failed on main bea23b7 (readings_dev4, session 46): wei4 three times,
        // liang4 twice.
        CHECK(pinyin("净利润为15.8亿元") == "jing4 li4 run4 wei2 shi2 wu3 dian3 ba1 yi4 yuan2");
        CHECK(pinyin("参会人数为300人") == "can1 hui4 ren2 shu4 wei2 san1 bai3 ren2");
        CHECK(pinyin("昼夜温差为15度") == "zhou4 ye4 wen1 cha1 wei2 shi2 wu3 du4");
        CHECK(pinyin("每天早晚各量一次血压") == "mei3 tian1 zao3 wan3 ge4 liang2 yi1 ci4 xue4 ya1");
        CHECK(pinyin("医生给他量了体温") == "yi1 sheng1 gei3 ta1 liang2 le5 ti3 wen1");
        // The limits: 为 "for" where no value follows, and the amount's 量.
        CHECK(pinyin("收入为他赢得尊重") == "shou1 ru4 wei4 ta1 ying2 de2 zun1 zhong4");
        CHECK(pinyin("数量很大") == "shu4 liang4 hen3 da4");
        CHECK(pinyin("销量一直很好") == "xiao1 liang4 yi1 zhi2 hen3 hao3");
        CHECK(pinyin("这批货的量一共多少") == "zhe4 pi1 huo4 de5 liang4 yi1 gong4 duo1 shao3");
    }

    TEST_CASE("syllables carry the character, numbered pinyin and their sentence") {
        const auto timeline = read_transcript("銀行。女兒");
        REQUIRE(timeline.syllables.size() == 4);
        CHECK(timeline.syllables[0].text == "銀");
        CHECK(timeline.syllables[0].pinyin == "yin2");
        CHECK(timeline.syllables[1].pinyin == "hang2");
        CHECK(timeline.syllables[2].pinyin == "nv3");  // u-umlaut written v
        CHECK(timeline.syllables[3].sentence == 1);
        for (const auto& syllable : timeline.syllables) {
            CAPTURE(syllable.text);
            CHECK(is_valid_pinyin(syllable.pinyin));
            CHECK(syllable.start_s == 0.0);
            CHECK(syllable.end_s == 0.0);
        }
        CHECK(timeline.warnings.empty());
    }

    TEST_CASE("the thesis's transcripts are read right") {
        // thesis Figure 3.7 and 3.9
        const auto first = read_transcript("或許你已聽過，多補充抗氧化劑可以延緩老化。但真相為何？");
        CHECK(toneless(first) ==
              "huo xu ni yi ting guo duo bu chong kang yang hua ji ke yi yan huan lao hua dan zhen xiang wei "
              "he");
        REQUIRE(first.sentences.size() == 2);
        CHECK(first.sentences[0].text == "或許你已聽過，多補充抗氧化劑可以延緩老化。");
        CHECK(first.sentences[1].text == "但真相為何？");
        CHECK(first.syllables[5].text == "過");
        CHECK(first.syllables[5].pause_after);

        const auto second = read_transcript("長期下來，傷害不斷累積，就可能造就出一個較老、較脆弱的身體。");
        CHECK(toneless(second) ==
              "chang qi xia lai shang hai bu duan lei ji jiu ke neng zao jiu chu yi ge jiao lao jiao cui ruo "
              "de "
              "shen ti");
        CHECK(second.sentences.size() == 1);
        std::vector<std::string> paused;
        for (const auto& syllable : second.syllables) {
            if (syllable.pause_after) paused.push_back(syllable.text);
        }
        CHECK(paused == std::vector<std::string>{"來", "積", "老"});
    }

    TEST_CASE("sentences end at end marks, and the last one needs none") {
        const auto timeline = read_transcript("你好！他走了；真的嗎?好. 我來了… 再見");
        REQUIRE(timeline.sentences.size() == 6);
        CHECK(timeline.sentences[0].text == "你好！");
        CHECK(timeline.sentences[1].text == "他走了；");
        CHECK(timeline.sentences[2].text == "真的嗎?");
        CHECK(timeline.sentences[3].text == "好.");
        CHECK(timeline.sentences[4].text == "我來了…");
        CHECK(timeline.sentences[5].text == "再見");
        CHECK(timeline.syllables.back().sentence == 5);
    }

    TEST_CASE("spaces and the break of a line wrapped at its paragraph's width do not end a sentence") {
        // A line of 20 characters or more as wide as its paragraph's widest fills it: wrapped there.
        const auto timeline = read_transcript("\n  今天天氣很好我們一起去公園散步然後再去吃一頓\n午飯。 \n");
        REQUIRE(timeline.sentences.size() == 1);
        CHECK(timeline.sentences[0].text == "今天天氣很好我們一起去公園散步然後再去吃一頓午飯。");
        CHECK_FALSE(timeline.sentences[0].starts_paragraph);
        CHECK(timeline.syllables.size() == 24);
        // Running text, a sentence ending inside a line: its lines were wrapped, the short one too.
        const auto running = read_transcript("今天天氣很好。我們一起去\n公園散步。");
        REQUIRE(running.sentences.size() == 2);
        CHECK(running.sentences[1].text == "我們一起去公園散步。");
    }

    TEST_CASE("a line written as a sentence of its own ends it, as a script or a subtitle's lines are") {
        // Each fails on main 18103f3 (session 38): the lines were joined into one sentence.
        const auto script = read_transcript("大家好\n我是小明\n今天聊聊天氣\n");
        REQUIRE(script.sentences.size() == 3);
        CHECK(script.sentences[0].text == "大家好");
        CHECK(script.sentences[1].text == "我是小明");
        CHECK(script.sentences[2].text == "今天聊聊天氣");
        CHECK(script.syllables[2].sentence == 0);
        CHECK(script.syllables[3].sentence == 1);
        const auto quoted = read_transcript("他說「好」\n我們走吧");
        CHECK(quoted.sentences.size() == 2);
        const auto lyric = read_transcript("[00:12.50]我們一起走\n[00:15.00]走過春夏秋冬");
        CHECK(lyric.sentences.size() == 2);
        CHECK(read_transcript("1.買菜\n2.做飯").sentences.size() == 2);  // a list, an item a line
        CHECK(read_transcript("Hello everyone\nMy name is Tom").sentences.size() == 2);
        // The limits: a line ending in a pause mark or a dash runs on; a blank line still starts a
        // paragraph; a line with its end mark ends as it did.
        CHECK(read_transcript("今天天氣很好，\n我們去公園").sentences.size() == 1);
        CHECK(read_transcript("他說——\n我們去公園").sentences.size() == 1);
        const auto paragraphs = read_transcript("第一章\n\n天亮了\n他醒了");
        REQUIRE(paragraphs.sentences.size() == 3);
        CHECK(paragraphs.sentences[1].starts_paragraph);
        CHECK_FALSE(paragraphs.sentences[2].starts_paragraph);
        CHECK(read_transcript("你好。\n我是小明。").sentences.size() == 2);
    }

    TEST_CASE("a blank line starts a paragraph, and ends a sentence left open") {
        const auto timeline =
            read_transcript("\n\n春曉\n \r\n春眠不覺曉。處處聞啼鳥。\n夜來風雨聲，\n\n花落知多少？");
        REQUIRE(timeline.sentences.size() == 5);
        CHECK(timeline.sentences[0].text == "春曉");
        CHECK(timeline.sentences[1].text == "春眠不覺曉。");
        CHECK(timeline.sentences[2].text == "處處聞啼鳥。");
        CHECK(timeline.sentences[3].text == "夜來風雨聲，");
        CHECK(timeline.sentences[4].text == "花落知多少？");
        const std::vector<bool> starts = {false, true, false, false, true};
        for (std::size_t k = 0; k < starts.size(); ++k) {
            CAPTURE(k);
            CHECK(timeline.sentences[k].starts_paragraph == starts[k]);
        }
        const auto poem = read_transcript("春眠不覺曉。處處聞啼鳥。\n夜來風雨聲，\n\n花落知多少？");
        REQUIRE(poem.sentences.size() == 4);
        CHECK(poem.sentences[3].text == "花落知多少？");
        CHECK(poem.sentences[3].starts_paragraph);
        CHECK_FALSE(poem.sentences[2].starts_paragraph);
    }

    TEST_CASE("closing quotes stay with the sentence they end") {
        const auto timeline = read_transcript("他說：「你好。」她笑了。");
        REQUIRE(timeline.sentences.size() == 2);
        CHECK(timeline.sentences[0].text == "他說：「你好。」");
        CHECK(timeline.syllables[1].pause_after);  // 說：
        CHECK(timeline.warnings.empty());          // quotes are punctuation, not skipped text
    }

    TEST_CASE("pause marks set pause_after on the syllable before them") {
        const auto timeline = read_transcript("一，二、三：四, 五: 六。");
        REQUIRE(timeline.syllables.size() == 6);
        for (std::size_t i = 0; i < 5; ++i) {
            CAPTURE(i);
            CHECK(timeline.syllables[i].pause_after);
        }
        CHECK_FALSE(timeline.syllables[5].pause_after);
        CHECK(timeline.sentences.size() == 1);
    }

    TEST_CASE("a reading fix overrides phrase and character readings") {
        const auto timeline = read_transcript("行{hang2}走，銀行{xing2}，了{liao3}，綠{lu:4}");
        CHECK(toneless(timeline) == "hang zou yin xing liao lv");
        CHECK(timeline.syllables[0].pinyin == "hang2");
        CHECK(timeline.syllables[0].text == "行");
        CHECK(timeline.sentences[0].text == "行走，銀行，了，綠");
        CHECK(read_transcript("了{liao}").syllables[0].pinyin == "liao5");
    }

    TEST_CASE("an invalid reading fix is an error naming it and where it stands") {
        CHECK_THROWS_WITH_AS(read_transcript("你好\n銀行{hxng2}", {}, "news.txt"),
                             doctest::Contains("news.txt:2:3: reading fix \"{hxng2}\" for \"行\""),
                             ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("行{hang7}"), doctest::Contains("hang7"), ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("{hang2}"), doctest::Contains("must directly follow"),
                             ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("行{hang2"), doctest::Contains("no closing"), ParseError);
    }

    TEST_CASE("numbered pinyin is read per token, with or without spaces and tones") {
        const auto timeline = read_transcript("ni3 hao3. Ni3hao3 ma, xi'an lü4 nv3 zhong");
        CHECK(toneless(timeline) == "ni hao ni hao ma xi an lv nv zhong");
        REQUIRE(timeline.syllables.size() == 10);
        CHECK(timeline.syllables[0].text == "ni3");
        CHECK(timeline.syllables[0].pinyin == "ni3");
        CHECK(timeline.syllables[2].text == "Ni3");
        CHECK(timeline.syllables[4].pinyin == "ma5");  // no tone: neutral
        CHECK(timeline.syllables[4].pause_after);
        CHECK(timeline.syllables[7].pinyin == "lv4");
        CHECK(timeline.sentences.size() == 2);
        CHECK(timeline.warnings.empty());
        CHECK(toneless("xian") == "xian");  // one syllable, as pinyin spells it
        CHECK(toneless("我們 wo3men5") == "wo men wo men");
    }

    TEST_CASE("with read_pinyin off, Latin letters are read as letters or English, not as pinyin") {
        TranscriptOptions options;
        options.read_pinyin = false;
        const auto timeline = read_transcript("ni3 好", options);
        // "ni" is no English word: generic speech of one syllable, then 3
        CHECK(toneless(timeline) == "de san hao");
        CHECK(timeline.syllables.at(0).generic_speech);
        REQUIRE(timeline.warnings.size() == 1);
        CHECK(timeline.warnings[0].find("\"ni\" is not in the English pronouncing dictionary") !=
              std::string::npos);
    }

    TEST_CASE("characters without a reading are reported with line and column, not dropped silently") {
        const auto timeline = read_transcript("@# 你好，\n★你", {}, "t.txt");
        CHECK(toneless(timeline) == "ni hao ni");
        REQUIRE(timeline.warnings.size() == 3);
        CHECK(timeline.warnings[0] == "t.txt:1:1: \"@\" (U+0040) has no Mandarin reading; skipped");
        CHECK(timeline.warnings[1].find("t.txt:1:2: \"#\"") == 0);
        CHECK(timeline.warnings[2].find("t.txt:2:1: \"\u2605\"") == 0);  // columns count characters
        CHECK(timeline.sentences.size() == 1);
        // A line break between wide characters is layout; the line runs on past its comma.
        CHECK(timeline.sentences[0].text == "@# 你好，★你");
    }

    TEST_CASE("a sentence with nothing to say is left out, its characters still reported") {
        const auto timeline = read_transcript("★. 好。");
        CHECK(timeline.sentences.size() == 1);
        CHECK(timeline.syllables[0].sentence == 0);
        CHECK(timeline.warnings.size() == 1);
    }

    TEST_CASE("invalid UTF-8 is an error naming the byte offset and its line and column") {
        CHECK_THROWS_WITH_AS(read_transcript("ab\n你\xff好", {}, "bad.txt"),
                             doctest::Contains("bad.txt:2:2: byte offset 6: invalid UTF-8"), ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("\xe4\xbd"), doctest::Contains("byte offset 0"), ParseError);
        CHECK_THROWS_WITH_AS(read_transcript("\xc0\xaf"), doctest::Contains("byte offset 0"),
                             ParseError);  // overlong
        CHECK_THROWS_WITH_AS(read_transcript("\xed\xa0\x80"), doctest::Contains("0xED"),
                             ParseError);            // surrogate
        CHECK(toneless("\xEF\xBB\xBF好") == "hao");  // a byte order mark is not text
    }

    TEST_CASE("load_transcript reads a file and names it") {
        const auto path = test::output_path("transcript_test.txt");
        std::ofstream(path) << "銀行{hang2}。";
        CHECK(toneless(load_transcript(path)) == "yin hang");
        CHECK_THROWS_AS(load_transcript(test::output_path("no-such-transcript.txt")), FileError);
    }

    TEST_CASE("is_valid_pinyin accepts legal syllables with a tone") {
        for (const char* good : {"hang2", "lv4", "ma5", "zhuang1", "ng2", "m2", "hm5", "er2"}) {
            CAPTURE(good);
            CHECK(is_valid_pinyin(good));
        }
        for (const char* bad : {"hxng2", "hang", "hang6", "lü4", "Hang2", "", "2", "jv3"}) {
            CAPTURE(bad);
            CHECK_FALSE(is_valid_pinyin(bad));
        }
    }

    TEST_CASE("every reading in the built-in tables is a legal syllable") {
        const auto& tables = detail::reading_tables();
        // Standard Mandarin has about 410 toneless syllables; Unihan adds a few rare ones.
        CHECK(tables.syllable_lines().lines().size() > 400);
        CHECK(tables.syllable_lines().lines().size() < 430);
        CHECK(tables.character_lines().lines().size() > 40000);
        CHECK(tables.word_lines().lines().size() > 90000);
        CHECK(tables.syllable_lines().keys_ascend());
        CHECK(tables.character_lines().keys_ascend());
        CHECK(tables.word_lines().keys_ascend());
        for (const auto line : tables.character_lines().lines()) {
            const auto character = detail::SortedLines::key_of(line);
            CAPTURE(character);
            CHECK_FALSE(tables.readings(character).empty());
            for (const auto reading : tables.readings(character)) CHECK(is_valid_pinyin(reading));
        }
        for (const auto line : tables.word_lines().lines()) {
            const auto phrase = detail::SortedLines::key_of(line);
            CAPTURE(phrase);
            const auto word = tables.word(phrase);
            REQUIRE(word);
            for (const auto reading : word->readings) CHECK(is_valid_pinyin(reading));
        }
    }

    TEST_CASE("held-out news sentences are read right") {
        // tests/data/transcripts/heldout.tsv: 20 sentences, readings checked by hand. Before any
        // tuning the reader got 309 of 310 syllables: 还得多喝水 read 得 de, as the phrase source
        // reads 还得; tools/phrase_additions.tsv now gives it hai2 dei3 (issue 13).
        std::ifstream file(test::source_path("tests/data/transcripts/heldout.tsv"));
        REQUIRE(file);
        std::string line;
        int sentence_count = 0;
        int syllable_count = 0;
        int wrong_count = 0;
        while (std::getline(file, line)) {
            if (line.empty() || line[0] == '#') continue;
            const auto tab = line.find('\t');
            REQUIRE(tab != std::string::npos);
            const auto text = line.substr(0, tab);
            const auto expected = line.substr(tab + 1);
            const auto got = toneless(text);
            ++sentence_count;
            std::istringstream expected_words(expected);
            std::istringstream got_words(got);
            std::string expected_word;
            std::string got_word;
            while (expected_words >> expected_word) {
                ++syllable_count;
                if (!(got_words >> got_word) || got_word != expected_word) ++wrong_count;
            }
            CAPTURE(text);
            const bool has_extra_syllable = static_cast<bool>(got_words >> got_word);
            CHECK_FALSE(has_extra_syllable);
            if (got != expected) MESSAGE(text << ": expected " << expected << ", got " << got);
        }
        CHECK(sentence_count == 20);
        CHECK(syllable_count == 310);
        CHECK(wrong_count == 0);
    }

    TEST_CASE("a transcript with nothing to read is described with its counts in the singular or plural") {
        Timeline transcript;
        CHECK(detail::describe_unread_transcript(transcript) == "0 sentences, none with a Mandarin reading");
        transcript.sentences.resize(1);
        transcript.warnings = {"t.txt:1:1: \"★\" (U+2605) has no Mandarin reading; skipped"};
        CHECK(detail::describe_unread_transcript(transcript) ==
              "1 sentence, with no Mandarin reading; t.txt:1:1: \"★\" (U+2605) has no Mandarin reading; "
              "skipped");
        transcript.sentences.resize(2);
        transcript.warnings.push_back("t.txt:1:2: second");
        CHECK(detail::describe_unread_transcript(transcript) ==
              "2 sentences, none with a Mandarin reading; t.txt:1:1: \"★\" (U+2605) has no Mandarin reading; "
              "skipped (and 1 more warning)");
        transcript.warnings.push_back("t.txt:1:3: third");
        CHECK(doctest::String(detail::describe_unread_transcript(transcript).c_str()) ==
              doctest::Contains("skipped (and 2 more warnings)"));
    }

    TEST_CASE(
        "an audio book's words: 的确 几乎 挣扎 挨打 曾祖母 and their kind, 那只, light tones, AA verbs") {
        // Each row but the limits fails on main a33e7ae (session 46's readings_dev5): di4, ji3 twice, zha1,
        // zheng1, ai1, ceng2, meng2, yun1, sheng3, zhi3, ye5 ye2, yi4, suan5 pan2, lu1, zhi3, shui3, and kan4
        // xiang3 liao2 shi4 for the light second syllable.
        CHECK(pinyin("他的确来过") == "ta1 di2 que4 lai2 guo4");
        CHECK(pinyin("几乎所有人") == "ji1 hu1 suo3 you3 ren2");
        CHECK(pinyin("一张茶几") == "yi1 zhang1 cha2 ji1");
        CHECK(pinyin("他拼命挣扎") == "ta1 pin1 ming4 zheng1 zha2");
        CHECK(pinyin("挣钱养家") == "zheng4 qian2 yang3 jia1");
        CHECK(pinyin("他又挨打了") == "ta1 you4 ai2 da3 le5");
        CHECK(pinyin("我的曾祖母") == "wo3 de5 zeng1 zu3 mu3");
        CHECK(pinyin("被人蒙骗") == "bei4 ren2 meng1 pian4");
        CHECK(pinyin("她晕车") == "ta1 yun4 che1");
        CHECK(pinyin("醉得不省人事") == "zui4 de5 bu4 xing3 ren2 shi4");
        CHECK(pinyin("那只小鸟受伤了") == "na4 zhi1 xiao3 niao3 shou4 shang1 le5");
        CHECK(pinyin("老爷爷") == "lao3 ye2 ye5");
        CHECK(pinyin("好主意") == "hao3 zhu3 yi5");
        CHECK(pinyin("打算盘") == "da3 suan4 pan5");
        CHECK(pinyin("打呼噜") == "da3 hu1 lu5");
        CHECK(pinyin("金戒指") == "jin1 jie4 zhi5");
        CHECK(pinyin("草叶上的露水") == "cao3 ye4 shang4 de5 lu4 shui5");
        CHECK(pinyin("你来看看") == "ni3 lai2 kan4 kan5");
        CHECK(pinyin("让我想想") == "rang4 wo3 xiang3 xiang5");
        CHECK(pinyin("我们聊聊天") == "wo3 men5 liao2 liao5 tian1");
        CHECK(pinyin("試試看") == "shi4 shi5 kan4");
        // The limits: Traditional 隻, never the adverb, 只是 after a demonstrative, 等等 "and so on",
        // 偷偷摸摸, words whose second character is its own, and 晕 yūn where one faints.
        CHECK(pinyin("這隻貓和那隻狗") == "zhe4 zhi1 mao1 he2 na4 zhi1 gou3");
        CHECK(pinyin("这只是开始") == "zhe4 zhi3 shi4 kai1 shi3");
        CHECK(pinyin("那只能这样了") == "na4 zhi3 neng2 zhe4 yang4 le5");
        CHECK(pinyin("苹果、香蕉等等") == "ping2 guo3 xiang1 jiao1 deng3 deng3");
        CHECK(pinyin("偷偷摸摸") == "tou1 tou1 mo1 mo1");
        CHECK(pinyin("考试试题") == "kao3 shi4 shi4 ti2");
        CHECK(pinyin("花露水") == "hua1 lu4 shui3");
        CHECK(pinyin("他晕倒了") == "ta1 yun1 dao3 le5");
        CHECK(pinyin("目的") == "mu4 di4");
    }

    TEST_CASE("冲 graded by a degree adverb is chòng, strong or blunt") {
        // Each row but the limits fails on main a33e7ae (session 46's readings_dev5): chong1.
        CHECK(pinyin("这酒很冲") == "zhe4 jiu3 hen3 chong4");
        CHECK(pinyin("他太冲了吧") == "ta1 tai4 chong4 le5 ba5");
        CHECK(pinyin("味道有点冲") == "wei4 dao4 you3 dian3 chong4");
        CHECK(pinyin("他說話那麼衝") == "ta1 shuo1 hua4 na4 me5 chong4");
        // The limits: the verb, going somewhere after it, and 冲动.
        CHECK(pinyin("他就那么冲过去了") == "ta1 jiu4 na4 me5 chong1 guo4 qu4 le5");
        CHECK(pinyin("他很冲动") == "ta1 hen3 chong1 dong4");
        CHECK(pinyin("冲了个澡") == "chong1 le5 ge4 zao3");
    }

    TEST_CASE("挣 alone earns, zhèng, and 泊 alone moors, bó") {
        // Each row but the limits fails on main 3d33409 (session 46's readings_dev5): zheng1, po1.
        CHECK(pinyin("他挣了不少钱") == "ta1 zheng4 le5 bu4 shao3 qian2");
        CHECK(pinyin("一个月挣五千") == "yi1 ge4 yue4 zheng4 wu3 qian1");
        CHECK(pinyin("掙了錢") == "zheng4 le5 qian2");
        CHECK(pinyin("船泊在岸边") == "chuan2 bo2 zai4 an4 bian1");
        // The limits: the words of zhēng and pō.
        CHECK(pinyin("他在挣扎") == "ta1 zai4 zheng1 zha2");
        CHECK(pinyin("湖泊很美") == "hu2 po1 hen3 mei3");
        CHECK(pinyin("躺在血泊中") == "tang3 zai4 xue4 po1 zhong1");
        CHECK(pinyin("梁山泊") == "liang2 shan1 po1");
    }
}
