#!/usr/bin/python3
"""Generates src/text/data/readings.cpp: every Han character's Mandarin readings, most frequent
first, in numbered pinyin, plus the set of legal toneless syllables, from Unihan.

Source: /usr/share/unicode/Unihan_Readings.txt.bz2 (Debian package unicode-data; the Unicode
License for data files, see docs/data-licences.md). Run from anywhere: /usr/bin/python3 tools/make_readings.py

Reading order per character: kHanyuPinlu by its corpus frequency (the only field with counts),
then kMandarin (first value: zh-Hans; second: zh-Hant), then the dictionaries kTGHZ2013,
kXHC1983, kHanyuPinyin in the order they list readings; a light tone (5) after the full ones,
except for the particles and suffixes below. The first reading is what a character gets when no
phrase covers it. A Traditional character whose Simplified form (OpenCC t2s, Debian opencc, Apache
2.0) is another character leads with a reading it shares with that form (see reading_orders).
"""

import bz2
import collections
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pinyin_rules  # noqa: E402
import embed_text  # noqa: E402

UNIHAN = "/usr/share/unicode/Unihan_Readings.txt.bz2"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(ROOT, "src", "text", "data", "readings.cpp")

# Fields from modern dictionaries and corpora: a character with more than one toneless reading
# here is polyphonic for make_phrases.py. kHanyuPinyin (a historical dictionary) lists many
# archaic readings, so it only breaks ties and fills characters nothing else covers.
MODERN_FIELDS = ("kHanyuPinlu", "kMandarin", "kTGHZ2013", "kXHC1983")
ALL_FIELDS = MODERN_FIELDS + ("kHanyuPinyin",)

# Characters whose light tone is a grammatical word of its own or a suffix, said light nearly
# wherever it stands: their light reading stays first. kHanyuPinlu counts readings in running
# text, so 130 characters led with a light tone they take only inside a few words (欢 in 喜欢, 息
# in 消息, 识 in 认识, 友 in 朋友, 西 in 东西): read alone, or in 欢迎 信息 识别 友谊 西安, they take
# their full tone, and those words carry their light tone themselves (make_phrases.py and
# phrase_additions.tsv).
LIGHT_PARTICLES = {
    # Structural and aspect particles: 的 地 (得 is among the suffixes), 了 着 (著 in Traditional text).
    "的", "地", "了", "着", "著",
    # Sentence-final and modal particles.
    "吗", "嗎", "呢", "吧", "啊", "呀", "啦", "嘛", "呗", "唄", "喽", "嘍", "哇", "哩", "咧", "呐", "吶",
    "嘞", "么", "麼", "嚜", "噷",
}
# Suffixes, 得 after a verb (觉得, 说得) and the locative 裡 (Traditional; 屋裡, 這裡, 哪裡): light after
# a word's first character (桌子, 我们, 一会儿), full where they begin one (子女, 儿童, 得到, 裡面);
# make_phrases.py reads them so, the words where they are full after the first (电子, 女儿, 获得)
# listed in phrase_additions.tsv. Alone they are the suffix of a word the list lacks. (The
# Simplified 里 is also the unit li3 of 公里, so it is not among them.)
LIGHT_SUFFIXES = {"子", "儿", "兒", "们", "們", "得", "裡"}
LIGHT_FIRST = LIGHT_PARTICLES | LIGHT_SUFFIXES

# Characters whose reading where no word covers them is not the one kHanyuPinlu counts first, decided
# by usage (session 21). 长: zhǎng (1879) leads cháng (1179) through 部长 校长 家长 长大 成长 增长, words
# the phrase list reads themselves, as it reads the verb's common forms (长了 长得 长出 长满 长高 长着);
# what is left uncovered is mostly the adjective (友谊长存, 这条路长约, 长袖), and the 2013 standard
# dictionary (kTGHZ2013) lists cháng first. The list's words keep their readings either way.
# 仆: pú (仆人 公仆 女仆 奴仆 风尘仆仆) leads pū, which is 前仆后继 (phrase_additions.tsv) and 仆倒. 瞭: liǎo (瞭解
# 明瞭 一目瞭然, Traditional text's) leads the liào that kTGHZ2013 gives alone, Simplified text keeping 瞭 only
# for 瞭望 (phrase_additions.tsv) and writing the others 了.
# 挣: zhèng, earn (挣了不少钱, 一个月挣五千) where it stands alone; zhēng is 挣扎 挣揣, words the list reads
# (session 46, readings_dev5: 挣了钱 zheng1). 泊: bó, moor or stay (船泊在岸边, 停泊 漂泊 淡泊); pō is 湖泊 血泊
# 梁山泊, words the list reads (session 46: 船泊在 po1).
FIRST_BY_USAGE = {"长": "chang2", "長": "chang2", "仆": "pu2", "瞭": "liao3", "挣": "zheng4", "掙": "zheng4",
                  "泊": "bo2"}


def _field_readings(field, value):
    """Marked readings of one Unihan field, in the field's order."""
    if field == "kHanyuPinlu":
        pairs = re.findall(r"([^\s(]+)\((\d+)\)", value)
        pairs.sort(key=lambda pair: -int(pair[1]))  # stable: ties keep Unihan's order
        return [reading for reading, _ in pairs]
    if field == "kMandarin":
        return value.split()
    readings = []
    for entry in value.split():
        readings.extend(entry.split(":", 1)[1].split(","))
    return readings


def load_unihan():
    """{character: {field: [numbered readings]}} for every character with a Mandarin reading."""
    table = collections.defaultdict(dict)
    with bz2.open(UNIHAN, "rt", encoding="utf-8") as lines:
        for line in lines:
            if line.startswith("#") or not line.strip():
                continue
            code, field, value = line.rstrip("\n").split("\t")
            if field not in ALL_FIELDS:
                continue
            character = chr(int(code[2:], 16))
            numbered = []
            for marked in _field_readings(field, value):
                reading = pinyin_rules.to_numbered(marked)
                # "ê" (欸, 誒) is dropped: those characters also read ei / ai, and numbered pinyin
                # has no agreed ASCII spelling for it.
                # kHanyuPinlu counts the erhua suffix 儿/兒 as "r"; spoken alone it is "er".
                if reading == "r5":
                    reading = "er5"
                if reading is not None and reading not in numbered:
                    numbered.append(reading)
            if numbered:
                table[character][field] = numbered
    return table


def ordered_readings(character, fields):
    """The character's readings, most frequent first, a light tone after the full ones unless
    the character is a particle or suffix (LIGHT_FIRST)."""
    readings = []
    for field in ALL_FIELDS:
        for reading in fields.get(field, []):
            if reading not in readings:
                readings.append(reading)
    # A reading the 2013 standard dictionary (kTGHZ2013) gives alone, with the first one's spelling
    # and another full tone, is the standard one now (迹 jì, 绩 jì, 甚 shèn, 框 kuàng, where
    # kHanyuPinlu's corpus of the 1980s and kMandarin keep jī, jī, shén, kuāng).
    standard = fields.get("kTGHZ2013", [])
    if (len(standard) == 1 and not standard[0].endswith("5") and readings[0][:-1] == standard[0][:-1]
            and readings[0] != standard[0] and not readings[0].endswith("5")):
        readings.remove(standard[0])
        readings.insert(0, standard[0])
    if character in FIRST_BY_USAGE:
        readings.remove(FIRST_BY_USAGE[character])
        readings.insert(0, FIRST_BY_USAGE[character])
    if character in LIGHT_FIRST:
        return readings
    full = [reading for reading in readings if not reading.endswith("5")]
    light = [reading for reading in readings if reading.endswith("5")]
    return full + light if full else readings


def opencc_convert(phrases, config):
    """OpenCC (config: s2t.json, s2tw.json, t2s.json) over the whole list at once, one phrase per line
    (phrase-level conversion)."""
    result = subprocess.run(["opencc", "-c", config], input="\n".join(phrases) + "\n",
                            capture_output=True, text=True, check=True)
    converted = result.stdout.split("\n")[:len(phrases)]
    if len(converted) != len(phrases):
        sys.exit(f"opencc {config} returned {len(converted)} lines for {len(phrases)}")
    return converted


def reading_orders(table):
    """{character: ordered_readings} for every character of the table. A Traditional character that
    Simplified text writes as another character (乾 干, 徵 征, 鉻 铬) and whose first reading that
    character never has leads with the first of its readings that it has: the first one is its own,
    rarer sense, which the Simplified fields (kMandarin's zh-Hans value, kTGHZ2013) list alone (乾 qián
    of 乾隆 before gān "dry", 徵 zhǐ the note before zhēng, 鉻 luò before the element's gè), while
    Traditional text writes it mostly in the sense the Simplified form took over. Not where the 2013
    standard dictionary gives that first reading and kMandarin none apart for Traditional text: the
    character is a Simplified one of its own in it, read so in both scripts (吒 zhā of 哪吒, 苧 níng)."""
    orders = {character: ordered_readings(character, fields) for character, fields in table.items()}
    several = sorted(character for character, readings in orders.items() if len(readings) > 1)
    for character, form in zip(several, opencc_convert(several, "t2s.json")):
        if form == character or form not in orders or character in LIGHT_FIRST:
            continue
        readings, shared = orders[character], orders[form]
        fields = table[character]
        standard = readings[0] in fields.get("kTGHZ2013", []) and len(fields.get("kMandarin", [])) < 2
        if readings[0] in shared or standard:
            continue
        lead = next((reading for reading in readings if reading in shared and not reading.endswith("5")), None)
        if lead is not None:
            readings.remove(lead)
            readings.insert(0, lead)
    return orders


def modern_toneless(fields):
    """The distinct toneless readings modern sources give; all sources if none does."""
    names = [field for field in MODERN_FIELDS if field in fields] or ["kHanyuPinyin"]
    toneless = []
    for field in names:
        for reading in fields[field]:
            if reading[:-1] not in toneless:
                toneless.append(reading[:-1])
    return toneless


def main():
    table = load_unihan()
    syllables = set()
    lines = []
    orders = reading_orders(table)
    for character in sorted(table):
        readings = orders[character]
        syllables.update(reading[:-1] for reading in readings)
        lines.append(f"{character}\t{' '.join(readings)}")
    illegal = sorted(s for s in syllables if not pinyin_rules.is_legal_toneless(s))
    if illegal:
        sys.exit(f"make_readings: Unihan readings outside the syllable grammar: {illegal}")
    # The toneless syllables every reading uses, checked against the grammar above: the run-time
    # check of reading fixes and pinyin input.
    syllable_lines = sorted(syllables)
    embed_text.write_cpp(
        OUTPUT, "tools/make_readings.py",
        ["Modified data derived from Unihan_Readings.txt (Debian unicode-data 15.0),",
         "Copyright (c) 1991-2022 Unicode, Inc., under the Unicode License: readings converted",
         "to numbered pinyin and reordered by frequency; other Unihan fields left out."],
        {"readings_text": lines, "syllables_text": syllable_lines})
    print(f"make_readings: {len(lines)} characters, {len(syllable_lines)} toneless syllables "
          f"-> {os.path.relpath(OUTPUT, ROOT)}")


if __name__ == "__main__":
    main()
