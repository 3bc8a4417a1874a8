// Pinyin syllables -> mouth shapes (SPEC "Mouth shapes", thesis 5.2.2).
#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"

using namespace talkface;

namespace {

// Every syllable with the shapes worked out by hand from SPEC's table and rules (not by calling the
// library): initial class (b p m: m; f: f; d t n l j q x: h'; g k h: h; zh ch sh r: r; z c s: z),
// medial (i; u and ü: u) in bopomofo terms (in = i + en, ing = i + eng, iong = ü + eng, un = u + en,
// ün = ü + en, iu = i + ou, ui = u + ei), then the rime (a; o; e: h; ê: e; er: h; ai: a i; ei: e i;
// ao: a u; ou: o u; an: a n; en: h n; ang: a h; eng: h; ong: u h), with an -> e n after i / ü,
// o -> u o after m, en -> n after i / ü (in, ün), and h' / h dropped before i u e o.
const char* const kTable = R"(
a a
ai a i
an a n
ang a h
ao a u
ba m a
bai m a i
ban m a n
bang m a h
bao m a u
bei m e i
ben m h n
beng m h
bi m i
bian m i e n
biang m i a h
biao m i a u
bie m i e
bin m i n
bing m i h
bo m u o
bu m u
ca z a
cai z a i
can z a n
cang z a h
cao z a u
ce z h
cei z e i
cen z h n
ceng z h
cha r a
chai r a i
chan r a n
chang r a h
chao r a u
che r h
chen r h n
cheng r h
chi r i
chong r u h
chou r o u
chu r u
chua r u a
chuai r u a i
chuan r u a n
chuang r u a h
chui r u e i
chun r u h n
chuo r u o
ci z i
cong z u h
cou z o u
cu z u
cuan z u a n
cui z u e i
cun z u h n
cuo z u o
da h' a
dai h' a i
dan h' a n
dang h' a h
dao h' a u
de h' h
dei e i
den h' h n
deng h' h
di i
dia i a
dian i e n
diao i a u
die i e
din i n
ding i h
diu i o u
dong u h
dou o u
du u
duan u a n
dui u e i
dun u h n
duo u o
e h
ei e i
en h n
eng h
er h
fa f a
fan f a n
fang f a h
fei f e i
fen f h n
feng f h
fiao f i a u
fo f o
fou f o u
fu f u
ga h a
gai h a i
gan h a n
gang h a h
gao h a u
ge h h
gei e i
gen h h n
geng h h
gong u h
gou o u
gu u
gua u a
guai u a i
guan u a n
guang u a h
gui u e i
gun u h n
guo u o
ha h a
hai h a i
han h a n
hang h a h
hao h a u
he h h
hei e i
hen h h n
heng h h
hm m
hng h
hong u h
hou o u
hu u
hua u a
huai u a i
huan u a n
huang u a h
hui u e i
hun u h n
huo u o
ji i
jia i a
jian i e n
jiang i a h
jiao i a u
jie i e
jin i n
jing i h
jiong u h
jiu i o u
ju u
juan u e n
jue u e
jun u n
ka h a
kai h a i
kan h a n
kang h a h
kao h a u
ke h h
kei e i
ken h h n
keng h h
kong u h
kou o u
ku u
kua u a
kuai u a i
kuan u a n
kuang u a h
kui u e i
kun u h n
kuo u o
la h' a
lai h' a i
lan h' a n
lang h' a h
lao h' a u
le h' h
lei e i
len h' h n
leng h' h
li i
lia i a
lian i e n
liang i a h
liao i a u
lie i e
lin i n
ling i h
liu i o u
lo o
long u h
lou o u
lu u
luan u a n
lun u h n
luo u o
lv u
lve u e
m m
ma m a
mai m a i
man m a n
mang m a h
mao m a u
me m h
mei m e i
men m h n
meng m h
mi m i
mian m i e n
miao m i a u
mie m i e
min m i n
ming m i h
miu m i o u
mo m u o
mou m o u
mu m u
n n
na h' a
nai h' a i
nan h' a n
nang h' a h
nao h' a u
ne h' h
nei e i
nen h' h n
neng h' h
ng h
ni i
nia i a
nian i e n
niang i a h
niao i a u
nie i e
nin i n
ning i h
niu i o u
nong u h
nou o u
nu u
nuan u a n
nun u h n
nuo u o
nv u
nve u e
o o
ou o u
pa m a
pai m a i
pan m a n
pang m a h
pao m a u
pei m e i
pen m h n
peng m h
pi m i
pian m i e n
piao m i a u
pie m i e
pin m i n
ping m i h
po m u o
pou m o u
pu m u
qi i
qia i a
qian i e n
qiang i a h
qiao i a u
qie i e
qin i n
qing i h
qiong u h
qiu i o u
qu u
quan u e n
que u e
qun u n
r h
ran r a n
rang r a h
rao r a u
re r h
ren r h n
reng r h
ri r i
rong r u h
rou r o u
ru r u
rua r u a
ruan r u a n
rui r u e i
run r u h n
ruo r u o
sa z a
sai z a i
san z a n
sang z a h
sao z a u
se z h
sen z h n
seng z h
sha r a
shai r a i
shan r a n
shang r a h
shao r a u
she r h
shei r e i
shen r h n
sheng r h
shi r i
shou r o u
shu r u
shua r u a
shuai r u a i
shuan r u a n
shuang r u a h
shui r u e i
shun r u h n
shuo r u o
si z i
song z u h
sou z o u
su z u
suan z u a n
sui z u e i
sun z u h n
suo z u o
ta h' a
tai h' a i
tan h' a n
tang h' a h
tao h' a u
te h' h
tei e i
teng h' h
ti i
tian i e n
tiao i a u
tie i e
ting i h
tong u h
tou o u
tu u
tuan u a n
tui u e i
tun u h n
tuo u o
wa u a
wai u a i
wan u a n
wang u a h
wei u e i
wen u h n
weng u h
wo u o
wong u h
wu u
xi i
xia i a
xian i e n
xiang i a h
xiao i a u
xie i e
xin i n
xing i h
xiong u h
xiu i o u
xu u
xuan u e n
xue u e
xun u n
ya i a
yan i e n
yang i a h
yao i a u
ye i e
yi i
yin i n
ying i h
yo i o
yong u h
you i o u
yu u
yuan u e n
yue u e
yun u n
za z a
zai z a i
zan z a n
zang z a h
zao z a u
ze z h
zei z e i
zen z h n
zeng z h
zha r a
zhai r a i
zhan r a n
zhang r a h
zhao r a u
zhe r h
zhei r e i
zhen r h n
zheng r h
zhi r i
zhong r u h
zhou r o u
zhu r u
zhua r u a
zhuai r u a i
zhuan r u a n
zhuang r u a h
zhui r u e i
zhun r u h n
zhuo r u o
zi z i
zong z u h
zou z o u
zu z u
zuan z u a n
zui z u e i
zun z u h n
zuo z u o
ê e
)";

struct Row {
    std::string syllable;
    std::string shapes;  // names joined by spaces
};

std::vector<Row> table_rows() {
    std::vector<Row> rows;
    std::istringstream in(kTable);
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        const auto space = line.find(' ');
        rows.push_back({line.substr(0, space), line.substr(space + 1)});
    }
    return rows;
}

std::string names(const std::vector<MouthShape>& shapes) {
    std::string text;
    for (const MouthShape shape : shapes)
        text += (text.empty() ? "" : " ") + std::string(mouth_shape_name(shape));
    return text;
}

}  // namespace

TEST_SUITE("syllable_mouth_shapes") {
    TEST_CASE("every Mandarin syllable gets the shapes worked out by hand") {
        const auto rows = table_rows();
        CHECK(rows.size() == 426);
        for (const Row& row : rows) {
            CAPTURE(row.syllable);
            CHECK(names(syllable_mouth_shapes(row.syllable)) == row.shapes);
        }
    }

    TEST_CASE("the hand-made table and the library's syllable list are the same set") {
        std::set<std::string> from_table;
        for (const Row& row : table_rows()) from_table.insert(row.syllable);
        const auto& known = mandarin_syllables();
        const std::set<std::string> from_library(known.begin(), known.end());
        CHECK(from_library.size() == known.size());
        for (const auto& syllable : from_library) {
            CAPTURE(syllable);
            CHECK(from_table.count(syllable) == 1);
        }
        for (const auto& syllable : from_table) {
            CAPTURE(syllable);
            CHECK(from_library.count(syllable) == 1);
        }
    }

    TEST_CASE("no syllable has more than 4 shapes and none is empty") {
        for (const auto& syllable : mandarin_syllables()) {
            CAPTURE(syllable);
            const auto shapes = syllable_mouth_shapes(syllable);
            CHECK(!shapes.empty());
            CHECK(shapes.size() <= 4);
        }
    }

    TEST_CASE("the rule examples of SPEC and thesis 5.2.2") {
        CHECK(names(syllable_mouth_shapes("bo")) == "m u o");    // o -> u o after m
        CHECK(names(syllable_mouth_shapes("xian")) == "i e n");  // an -> e n after i; h' dropped
        CHECK(names(syllable_mouth_shapes("guo")) == "u o");     // medial u first; h dropped
        CHECK(names(syllable_mouth_shapes("hao")) == "h a u");   // h kept before a
        CHECK(names(syllable_mouth_shapes("zhi")) == "r i");     // empty rime is i
        CHECK(names(syllable_mouth_shapes("xia")) == "i a");
        CHECK(names(syllable_mouth_shapes("xue")) == "u e");
        CHECK(names(syllable_mouth_shapes("de")) == "h' h");  // h'ㄜ = h' h (thesis 5.2.2)
    }

    TEST_CASE("the tone digit, case and the spellings of u-umlaut are ignored") {
        CHECK(names(syllable_mouth_shapes("ma3")) == "m a");
        CHECK(names(syllable_mouth_shapes("ma5")) == "m a");
        CHECK(names(syllable_mouth_shapes("ma0")) == "m a");
        CHECK(names(syllable_mouth_shapes("Zhuang1")) == "r u a h");
        CHECK(syllable_mouth_shapes("lv4") == syllable_mouth_shapes("lü4"));
        CHECK(syllable_mouth_shapes("lv4") == syllable_mouth_shapes("lu:4"));
        CHECK(syllable_mouth_shapes("nve4") == syllable_mouth_shapes("nue4"));
        CHECK(syllable_mouth_shapes("LV4") == syllable_mouth_shapes("lv"));
        CHECK(names(syllable_mouth_shapes("ê2")) == "e");
    }

    TEST_CASE("whether the first shape is the initial's") {
        CHECK(syllable_shapes("bo").has_initial_shape);
        CHECK(syllable_shapes("hao").has_initial_shape);
        CHECK(syllable_shapes("de").has_initial_shape);
        CHECK(syllable_shapes("shi").has_initial_shape);
        CHECK_FALSE(syllable_shapes("xian").has_initial_shape);
        CHECK_FALSE(syllable_shapes("dou").has_initial_shape);
        CHECK_FALSE(syllable_shapes("a").has_initial_shape);
        CHECK_FALSE(syllable_shapes("yun").has_initial_shape);
    }

    TEST_CASE("a syllable that is not Mandarin is refused and named") {
        for (const char* bad : {"bv", "fin", "xa", "", "ma6", "ma 3", "hello", "3", "zhv", "gi"}) {
            CAPTURE(bad);
            CHECK_THROWS_WITH_AS(syllable_mouth_shapes(bad),
                                 doctest::Contains(("syllable \"" + std::string(bad) + "\"").c_str()),
                                 InvalidArgument);
        }
    }
}
