#!/usr/bin/python3
"""Generates src/text/data/english.cpp: English words as Mandarin-like syllables, so that an English
word in a Mandarin transcript (iPhone, Wi-Fi, email) gets syllables the aligner can time and the lips
can shape (issue 13). Run with Debian 12's /usr/bin/python3 after `apt-get install festlex-cmu`.

Source: the CMU pronouncing dictionary 0.4 as Festival ships it (festlex-cmu,
/usr/share/festival/dicts/cmu/cmudict-0.4.out): ~106k words, each already cut into syllables with
a stress mark. Each English syllable becomes one Mandarin syllable, its onset and vowel mapped to
the nearest pinyin initial and final; an s before another consonant (street, spin) and each
consonant after a vowel but n and ng, which Mandarin ends syllables with (and an n after ai, ei or
oi, which no final holds: 莱恩 line), become syllables of their own with a short vowel, as Mandarin
speakers say them and its loans write them (迈克 mai ke, 麦克斯 ma ke si, 艾克赛尔 yi ke sai er, 汤姆
mu, 比尔 er, 粉丝 fans); a liquid after a consonant opens a syllable of its own, l, the consonants
before it each a syllable (tree te li, play pu lei, Brown bu lang, street si te li te: 特里, 布朗, 斯特里特),
and a glide after one is the final's medial where Mandarin has the syllable (quick kui ke, Twitter tui te,
cute qiu te: 奎克, 推特, 丘特). Every result is a syllable of the library's own table
(the one make_readings.py writes, which the aligner and the lips accept); when the plain mapping
is not (fi, gi), the nearest one in it is taken (fa, ji). Stressed syllables get tone 1, the rest tone 5: tones do not move the
lips, and espeak-ng speaks them either way.

Why a committed table and not the dictionary read at run time: the library must run with no data
package installed and give the same syllables on every machine (SPEC "Transcript to syllables"),
like the Unihan tables; the mapping is done once, here, where it can be checked whole. The
dictionary's licence (a BSD-style permission from the University of Edinburgh and CMU) allows
this with its notice kept: docs/data-licences.md.
"""

import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from embed_text import write_cpp  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DICTIONARY = "/usr/share/festival/dicts/cmu/cmudict-0.4.out"
OUTPUT = os.path.join(ROOT, "src", "text", "data", "english.cpp")
READINGS = os.path.join(ROOT, "src", "text", "data", "readings.cpp")


def library_syllables():
    """The toneless syllables the library accepts (and the lips shape): the syllable table that
    make_readings.py wrote, which is narrower than pinyin_rules' grammar (no gi, no fai)."""
    with open(READINGS, encoding="utf-8") as source:
        text = source.read()
    table = text[text.index("kSyllablesText[] = {"):]
    table = table[:table.index("};")]
    return set(re.findall(r'"([a-z]+)\\n"', table))


LEGAL = library_syllables()


def is_legal_toneless(syllable):
    return syllable in LEGAL

VOWELS = {"aa": "a", "ae": "a", "ah": "a", "ao": "o", "aw": "ao", "ax": "e", "ay": "ai", "eh": "ai",
          "er": "er", "ey": "ei", "ih": "i", "iy": "i", "ow": "ou", "oy": "ao", "uh": "u", "uw": "u"}
INITIALS = {"p": "p", "b": "b", "t": "t", "d": "d", "k": "k", "g": "g", "f": "f", "v": "w", "th": "s",
            "dh": "d", "s": "s", "z": "z", "sh": "sh", "zh": "r", "ch": "ch", "jh": "zh", "m": "m",
            "n": "n", "l": "l", "r": "r", "w": "w", "y": "y", "hh": "h", "ng": "n"}
# A consonant said as a syllable of its own (the s of street, the k of Mike).
CONSONANT_SYLLABLES = {"p": "pu", "b": "bu", "t": "te", "d": "de", "k": "ke", "g": "ge", "f": "fu",
                       "v": "fu", "th": "si", "dh": "de", "s": "si", "z": "zi", "sh": "shi",
                       "zh": "shi", "ch": "qi", "jh": "zhi", "l": "le", "hh": "he"}
# Two consonants after a vowel said as one syllable, as the loans write them (瓦茨 Watts, 爱德华兹 Edwards).
CODA_PAIRS = {("t", "s"): "ci", ("d", "z"): "zi"}
# Vowels after which an l is no syllable: a schwa's (apple, model: 爱坡, 毛豆) and the back ones, which take
# the l into themselves (call, cool, goal, Ultra, Hulk: 扣, 酷, 奥特曼, 浩克). After the others it is 尔
# (Excel 艾克赛尔, Bill 比尔, golf 高尔夫, mail 伊妹儿).
L_WITHOUT_SYLLABLE = {"ax", "ah", "ao", "ow", "uw", "uh"}
# Vowels that keep their glide before an n, which is then a syllable of its own: Mandarin has no final of a
# diphthong and n, and its loans keep the diphthong and write the n 恩 (莱恩 Lane, Ryan; 凯恩 Kane; 韦恩 Wayne;
# 佩恩 Payne; 博伊恩 Boyne), where taking the n into the vowel made line lan and Wayne wen. Where the syllable
# loses the glide anyway (fai is none: find fa), the n stays in the final (fan de), the nearer.
GLIDE_BEFORE_N = {"ay", "ey", "oy"}
# Pinyin initials (English ch, j, sh) before which an e (eh) is ie, with the palatal initial, as the loans
# write it (切尔西 Chelsea, 切斯特 Chester, 杰夫 Jeff, 杰瑞 Jerry, 杰西卡 Jessica, 谢菲尔德 Sheffield) and Mandarin
# speakers say check (qie ke), where it was chai, zhai, shai; before its nasal it is left to NASAL (詹金斯 Jenkins).
IE_AFTER = {"ch", "zh", "sh"}
NASAL = {("a", "n"): "an", ("a", "ng"): "ang", ("e", "n"): "en", ("e", "ng"): "eng", ("i", "n"): "in",
         ("i", "ng"): "ing", ("u", "n"): "un", ("u", "ng"): "ong", ("ai", "n"): "an", ("ai", "ng"): "ang",
         ("ei", "n"): "en", ("ei", "ng"): "eng", ("ao", "n"): "ang", ("ao", "ng"): "ang", ("ou", "n"): "ong",
         ("ou", "ng"): "ong", ("o", "n"): "ong", ("o", "ng"): "ong", ("er", "n"): "en", ("er", "ng"): "eng"}
# An aw before n is ang, as the loans write it (布朗 Brown, 克朗 crown, 唐宁 Downing, 蒙巴顿 Mountbatten) and
# Mandarin speakers say down (当) and town: session 26, it was an (brown ban, town tan, down dan), which no loan
# writes for it.
# Nearest finals to try, in order, when initial + final is not a Mandarin syllable.
NEAREST = {"i": ["ei", "ai"], "in": ["en"], "ing": ["eng"], "ei": ["ai", "i"], "ai": ["a", "ei"],
           "ou": ["o", "u", "ao"], "o": ["ou", "uo", "ao", "a"], "ao": ["ou", "a"], "u": ["ou", "o"],
           "un": ["en", "ong"], "ong": ["eng", "ang"], "er": ["e", "a"], "e": ["a", "ei"], "an": ["en", "ang"],
           "en": ["an", "eng"], "ang": ["eng", "an"], "eng": ["ang", "en"], "a": ["e"]}
PALATAL = {"g": "j", "k": "q", "h": "x", "z": "j", "c": "q", "s": "x", "zh": "j", "ch": "q", "sh": "x"}
# A final with no initial, as pinyin spells it.
BARE = {"i": "yi", "in": "yin", "ing": "ying", "u": "wu", "un": "wen", "ong": "weng"}


def legal_syllable(initial, final):
    """The nearest legal toneless syllable to initial + final."""
    finals = [final] + NEAREST.get(final, [])
    initials = [initial] + ([PALATAL[initial]] if initial in PALATAL else [])
    for candidate_final in finals:
        for candidate_initial in initials:
            if candidate_initial:
                syllable = candidate_initial + candidate_final
                if is_legal_toneless(syllable):
                    return syllable
    for candidate_final in finals:
        syllable = BARE.get(candidate_final, candidate_final)
        if is_legal_toneless(syllable):
            return syllable
    return "a"


# A final with a glide's medial before it: a w's u (kui, tui, kua, shuo) and a y's i (qiu, miu, xia).
W_MEDIAL = {"i": "ui", "ei": "ui", "ai": "uai", "a": "ua", "e": "uo", "o": "uo", "ou": "uo", "an": "uan",
            "en": "un", "in": "un", "ang": "uang", "eng": "ong", "ing": "ong", "er": "uo"}
Y_MEDIAL = {"u": "iu", "ou": "iu", "a": "ia", "ai": "ie", "e": "ie", "ao": "iao", "an": "ian", "ang": "iang",
            "un": "iong", "ong": "iong"}


def with_medial(initial, final, glide):
    """The syllable initial + final says, with the glide's medial where Mandarin has that syllable (the
    initial or its palatal: k + iu is qiu); without the glide, the nearest legal syllable."""
    medial = {"w": W_MEDIAL, "y": Y_MEDIAL}.get(glide, {}).get(final)
    if medial:
        for candidate in [initial] + ([PALATAL[initial]] if initial in PALATAL else []):
            if is_legal_toneless(candidate + medial):
                return candidate + medial
    return legal_syllable(initial, final)


def coda_syllables(vowel, coda, next_phone, glide_kept, s_spelled):
    """The nasal a syllable's final takes from its coda (or None), and the syllables its other consonants
    become; next_phone opens the word's next syllable (None at its end); glide_kept tells whether the
    syllable says its vowel's glide (GLIDE_BEFORE_N); s_spelled, whether a z ending the coda is written s,
    when it is si as the loans write it (粉丝 fans, 琼斯 Jones, 威廉斯 Williams, 罗斯 Rose; 兹 is a z's: 莉兹
    Liz, 迪亚兹 Diaz). Session 25: only the last consonant of a word was a syllable, so fix was fei si (said
    fei ke si), Excel yi sai, Zoom zun (m taken for n) and team yin (tin is no syllable); line was lan (its n
    taken in) and fans fan zi."""
    nasal = None
    syllables = []
    index = 0
    while index < len(coda):
        phone = coda[index]
        following = coda[index + 1] if index + 1 < len(coda) else next_phone
        if phone == "n" and glide_kept:
            syllables.append("en")
        elif phone in ("n", "ng") or (phone == "m" and following in ("p", "b")):
            # An m before a labial stop is said n, as the loans write it (坎普 camp, 奥林匹克 Olympic).
            nasal = nasal or ("n" if phone == "m" else phone)
        elif phone == "m":
            syllables.append("mu")
        elif phone == "l":
            if vowel not in L_WITHOUT_SYLLABLE:
                syllables.append("er")
        elif index + 1 < len(coda) and (phone, following) in CODA_PAIRS:
            syllables.append(CODA_PAIRS[(phone, following)])
            index += 1
        elif phone == "z" and s_spelled and index + 1 == len(coda):
            syllables.append("si")
        elif phone in CONSONANT_SYLLABLES:
            syllables.append(CONSONANT_SYLLABLES[phone])
        index += 1
    return nasal, syllables


def map_word(syllables, spelling=""):
    """[(phones, stress), ...] from the dictionary -> numbered pinyin syllables."""
    result = []
    for index, (phones, stress) in enumerate(syllables):
        # A few syllables are a consonant alone (the m of "hmm"): said with the weak vowel.
        vowel_at = next((i for i, phone in enumerate(phones) if phone in VOWELS), len(phones))
        onset, coda = phones[:vowel_at], phones[vowel_at + 1:]
        vowel = phones[vowel_at] if vowel_at < len(phones) else "ax"
        tone = "1" if stress > 0 else "5"
        if len(onset) >= 2 and onset[0] in ("s", "sh"):
            result.append(CONSONANT_SYLLABLES[onset[0]] + "5")
            onset = onset[1:] if onset[1:] != ["r"] else ["l"]
        # A liquid after a consonant opens the syllable as l, as the loans write it (特里 tree, 布朗 Brown,
        # 克里斯 Chris, 普莱 play, 格林 green, 斯特里特 street), and each consonant before it is a syllable of
        # its own. Session 35: the liquid was dropped (tree ti, Brown bang, play pei), which no loan writes.
        # A glide after a consonant is the final's medial where Mandarin has that syllable (奎克 quick, 推特
        # Twitter, 丘特 cute, 缪斯 muse), else dropped (the first consonant of the cluster opens the syllable).
        glide = None
        if len(onset) >= 2 and onset[-1] in ("w", "y"):
            glide = onset[-1]
            onset = onset[:-1]
        if len(onset) >= 2 and onset[-1] in ("l", "r"):
            result.extend(CONSONANT_SYLLABLES.get(phone, "e") + "5" for phone in onset[:-1])
            onset = ["l"]
        initial = INITIALS[onset[0]] if onset else ""
        final = VOWELS[vowel]
        # A final unstressed schwa written a (NASA, pizza, data, Toyota) is said a, as Mandarin says
        # those words and writes their loans (纳萨, 比萨, 丰田 tuo you ta, 阿尔法): session 15, it was e.
        if index + 1 == len(syllables) > 1 and vowel == "ax" and not coda and spelling.endswith("a"):
            final = "a"
        next_phone = syllables[index + 1][0][0] if index + 1 < len(syllables) else None
        # A name's last -stein is 斯坦, si tan, as the loans write it whether English says it stine or steen
        # (爱因斯坦 Einstein, 伯恩斯坦 Bernstein, 爱泼斯坦 Epstein, 弗兰肯斯坦 Frankenstein, 戈德斯坦 Goldstein), by
        # the German ei's older convention: session 26, it was tai en (Einstein ai en si tai en).
        is_stein = next_phone is None and spelling.endswith("stein") and initial == "t" and coda == ["n"]
        if is_stein:
            final = "an"
        glide_kept = not is_stein and vowel in GLIDE_BEFORE_N and legal_syllable(initial, final).endswith(final)
        s_spelled = next_phone is None and spelling.removesuffix("e").endswith("s")
        nasal, consonants = coda_syllables(vowel, coda, next_phone, glide_kept, s_spelled)
        if nasal is not None:
            final = NASAL.get((final, nasal), final)
        elif vowel == "eh" and initial in IE_AFTER:
            final = "ie"
        result.append(with_medial(initial, final, glide) + tone)
        result.extend(syllable + "5" for syllable in consonants)
    return result


ENTRY = re.compile(r'^\("((?:[^"\\]|\\.)*)" \S+ \((.*)\)\)\s*$')
SYLLABLE = re.compile(r"\(\(([a-z ]+)\) (\d)\)")


def main():
    words = {}
    with open(DICTIONARY, encoding="latin-1") as source:
        for line in source:
            match = ENTRY.match(line)
            if not match:
                continue
            word = match.group(1).lower()
            # Letters and inner apostrophes only; the first entry of a homograph is its commonest.
            if not re.fullmatch(r"[a-z]+(?:'[a-z]+)?", word) or word in words:
                continue
            syllables = [(phones.split(), int(stress)) for phones, stress in SYLLABLE.findall(match.group(2))]
            if syllables:
                words[word] = map_word(syllables, word)
    for word, readings in words.items():
        for reading in readings:
            assert is_legal_toneless(reading[:-1]), (word, reading)
    lines = [f"{word}\t{' '.join(readings)}" for word, readings in sorted(words.items())]
    write_cpp(OUTPUT, "tools/make_english.py",
              ["The CMU pronouncing dictionary 0.4 (Debian festlex-cmu, cmudict-0.4.out), MODIFIED:",
               "each English syllable mapped onto a Mandarin syllable (see the script).",
               "Centre for Speech Technology Research, University of Edinburgh, UK.",
               "Copyright (c) 1996, 1997, 1998. All Rights Reserved. Distributed under the",
               "permission notice quoted whole in docs/data-licences.md, which must stay with it."],
              {"english_text": lines})
    print(f"{len(lines)} words -> {OUTPUT}")


if __name__ == "__main__":
    main()
