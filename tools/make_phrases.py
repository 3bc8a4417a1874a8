#!/usr/bin/python3
"""Generates src/text/data/phrases.cpp: the words of a phrase list with how often each is used,
in Simplified and Traditional characters, and the reading of each word that settles a polyphonic
character (首都 shou3 du1, 都是 dou1 shi4). The transcript reader cuts a run of characters into
its likeliest words by these costs (src/text/word_segmentation.cpp), then reads each word.

Sources (licences in docs/data-licences.md):
  /usr/share/pyzy/db/android.db  Debian libpyzy-1.0-0v5; the Android Open Source Project's
                                  Pinyin IME phrase list, Apache 2.0. Simplified, toneless.
  opencc (command, s2t, s2tw, t2s) Debian opencc, Apache 2.0: Traditional forms of those phrases.
  Unihan readings                 via make_readings.py: decoding the ids and choosing tones.
  tools/phrase_additions.tsv      words the list lacks or reads wrong, with their readings: among
                                  them the words with a light tone (喜欢 xi3 huan5), which a
                                  toneless list cannot tell.
Run: /usr/bin/python3 tools/make_phrases.py
"""

import collections
import math
import os
import sqlite3
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import embed_text  # noqa: E402
import make_readings  # noqa: E402
import pinyin_rules  # noqa: E402

ANDROID_DB = "/usr/share/pyzy/db/android.db"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(ROOT, "src", "text", "data", "phrases.cpp")
ADDITIONS = os.path.join(ROOT, "tools", "phrase_additions.tsv")


def read_android_db():
    """[(phrase, freq, [(initial_id, final_id), ...])] for every row of every py_phrase_N table,
    most frequent first (ties in table order)."""
    rows = []
    with sqlite3.connect(f"file:{ANDROID_DB}?mode=ro", uri=True) as db:
        tables = [name for (name,) in db.execute(
            "SELECT name FROM sqlite_master WHERE type = 'table' AND name LIKE 'py_phrase_%'")]
        for table in sorted(tables, key=lambda name: int(name.rsplit("_", 1)[1])):
            length = int(table.rsplit("_", 1)[1]) + 1
            columns = ", ".join(f"s{i}, y{i}" for i in range(length))
            for row in db.execute(f"SELECT phrase, freq, {columns} FROM {table} ORDER BY rowid"):
                phrase, freq, ids = row[0], row[1], row[2:]
                if len(phrase) == length:
                    rows.append((phrase, freq, list(zip(ids[0::2], ids[1::2]))))
    rows.sort(key=lambda row: -row[1])
    return rows


def word_costs(rows):
    """{phrase: cost}, the cost -ln P(word) in hundredths. android.db's freq is not a count:
    pyzy's create_db.py replaced the Android list's frequencies by their dense rank (1 for the
    rarest value, 7,680 for the commonest), which keeps only their order. Zipf's law gives the
    probability back from the order: a row's share of running text is 1 / (r H_N), r its place
    in the list (rows of one freq share the first place among them), N the rows, H_N the N-th
    harmonic number. A word read in several ways (参 can, shen, cen) adds its rows' shares."""
    first_place = {}
    for place, (_, freq, _) in enumerate(rows, start=1):
        first_place.setdefault(freq, place)
    harmonic = sum(1.0 / place for place in range(1, len(rows) + 1))
    shares = collections.defaultdict(float)
    for phrase, freq, _ in rows:
        shares[phrase] += 1.0 / (first_place[freq] * harmonic)
    return {phrase: round(-100 * math.log(share)) for phrase, share in shares.items()}


def decode_ids(rows, unihan):
    """Majority vote against Unihan: pyzy stores pinyin as ids of its own initial and final
    tables. Each one-character row votes, for its (initial id, final id) pair and for each id
    alone, with every toneless reading Unihan gives that character; the true spelling is the
    one nearly every character agrees on, a polyphone's other readings scatter."""
    pair_votes = collections.defaultdict(collections.Counter)
    initial_votes = collections.defaultdict(collections.Counter)
    final_votes = collections.defaultdict(collections.Counter)
    for phrase, _, ids in rows:
        if len(phrase) != 1 or phrase not in unihan:
            continue
        (initial_id, final_id), = ids
        for toneless in make_readings.modern_toneless(unihan[phrase]):
            initial, final = pinyin_rules.split_syllable(toneless)
            pair_votes[(initial_id, final_id)][toneless] += 1
            initial_votes[initial_id][initial] += 1
            final_votes[final_id][final] += 1

    pairs = {pair: votes.most_common(1)[0][0] for pair, votes in pair_votes.items()}
    initials = {key: votes.most_common(1)[0][0] for key, votes in initial_votes.items()}
    finals = {key: votes.most_common(1)[0][0] for key, votes in final_votes.items()}

    def decode(pair):
        if pair in pairs:
            return pairs[pair]
        syllable = initials.get(pair[0], "?") + finals.get(pair[1], "?")
        # pyzy keeps u-umlaut as one final id whatever the initial; j q x y spell it u.
        if syllable[:1] in "jqxy" and "v" in syllable:
            syllable = syllable.replace("v", "u")
        return syllable

    return decode, initials, finals


def read_additions():
    """{word: [numbered readings]} from tools/phrase_additions.tsv: words the list lacks or reads
    wrong (that file says why, word by word)."""
    additions = {}
    with open(ADDITIONS, encoding="utf-8") as lines:
        for number, line in enumerate(lines, start=1):
            if line.startswith("#") or not line.strip():
                continue
            word, readings, _ = line.rstrip("\n").split("\t")
            readings = readings.split()
            if len(readings) != len(word) or not all(
                    pinyin_rules.is_legal_toneless(r[:-1]) and r[-1] in "12345" for r in readings):
                sys.exit(f"make_phrases: {ADDITIONS}:{number}: {word} needs one numbered reading a character")
            additions[word] = readings
    return additions


def add_words(simplified, costs, additions):
    """Puts the additions into the list: a new word at the median cost of the list's words of its
    length (a word as common as a typical one: it wins over its characters read apart, and loses
    to a commoner word that overlaps it), a word the list has with its reading replaced."""
    by_length = collections.defaultdict(list)
    for phrase in simplified:
        by_length[len(phrase)].append(costs[phrase])
    for word, readings in additions.items():
        if word not in costs:
            costs[word] = sorted(by_length[len(word)])[len(by_length[len(word)]) // 2]
        simplified[word] = [reading[:-1] for reading in readings]


def numbered_reading(character, toneless, orders, fallback_character, after_first):
    """The character's most frequent full reading with this toneless spelling; its light one if
    it has no full one, if it is a particle (make_readings.LIGHT_PARTICLES: 好吧, 是吗, 除了; 酒吧
    and 干吗 are in phrase_additions.tsv), or if it is a suffix (make_readings.LIGHT_SUFFIXES)
    after the word's first character (桌子, 我们, 觉得; 子女 and 得到 keep the full tone). A
    Traditional form without readings borrows its Simplified form's."""
    for source in (character, fallback_character):
        if source in orders:
            spelled = [reading for reading in orders[source] if reading[:-1] == toneless]
            full = [reading for reading in spelled if not reading.endswith("5")]
            light = [reading for reading in spelled if reading.endswith("5")]
            if light and (not full or source in make_readings.LIGHT_PARTICLES or
                          (after_first and source in make_readings.LIGHT_SUFFIXES)):
                return light[0]
            if full:
                return full[0]
    return None


def begins_noun(word, k, simplified):
    """儿 or 子 at word[k] begins a noun of the list with the character after it (少年儿童: 儿童 ér;
    中华儿女, 炎黄子孙: 儿女 子孙), so it is no suffix there. 得 and 裡 are left to the suffix rule: the
    words they begin (得到 得过 裡去) follow a verb as its complement, light (看得到 过得去 哪裡去)."""
    return word[k] in ("儿", "兒", "子") and k + 1 < len(word) and word[k:k + 2] in simplified


def with_known_words(word, readings, additions):
    """The readings of a word with those of the additions inside it laid over them, the longest
    first: a compound says a word the way the word is said alone (好朋友 and 朋友们 as 朋友 peng2
    you5, 知识分子 as 知识 zhi1 shi5 and 分子 fen4 zi3)."""
    readings = list(readings)
    settled = [False] * len(word)
    for length in range(len(word) - 1, 1, -1):
        for start in range(len(word) - length + 1):
            known = additions.get(word[start:start + length])
            if known and not any(settled[start:start + length]):
                readings[start:start + length] = known
                settled[start:start + length] = [True] * length
    return readings


def main():
    unihan = make_readings.load_unihan()
    orders = make_readings.reading_orders(unihan)
    rows = read_android_db()
    decode, initials, finals = decode_ids(rows, unihan)
    print(f"make_phrases: decoded {len(initials)} initial ids, {len(finals)} final ids")
    costs = word_costs(rows)

    # A word read in several ways takes the reading of its most frequent row (rows come most
    # frequent first): 都是 dou shi, not du shi.
    simplified = {}
    for phrase, _, ids in rows:
        if phrase not in simplified:
            simplified[phrase] = [decode(pair) for pair in ids]
    additions = read_additions()
    add_words(simplified, costs, additions)
    bad = [p for p, syllables in simplified.items()
           if len(p) > 1 and not all(pinyin_rules.is_legal_toneless(s) for s in syllables)]
    if bad:
        sys.exit(f"make_phrases: {len(bad)} phrases decode to illegal syllables, e.g. {bad[:5]}")

    # Commonest first, so that a Traditional form two Simplified words share (a rare clash of
    # OpenCC's conversion) takes the commoner word's reading and cost.
    words = sorted(simplified, key=lambda phrase: (costs[phrase], phrase))
    forms = [(word, word) for word in words]
    for config in ("s2t.json", "s2tw.json"):
        forms.extend(zip(make_readings.opencc_convert(words, config), words))

    def first_reading(character):
        return orders[character][0] if character in orders else None

    # A Traditional character the Simplified list also holds, as a rare entry of its own (於 1147, 長
    # 1332), is written as often as its Simplified form (于 731, 长 876): it takes that form's cost,
    # or Traditional text is cut as if its commonest characters were rare (請家長於 read 家 長於). A form
    # Simplified text writes too (著, 瞭) keeps its own.
    converted = sorted({form for form, source in forms if form != source and len(form) == len(source)})
    simplified_forms = make_readings.opencc_convert(converted, "t2s.json")
    traditional_only = {form for form, back in zip(converted, simplified_forms) if back != form}
    simplified_form_cost = {}
    for form, source in forms:
        if form in traditional_only and form != source:
            simplified_form_cost[form] = min(costs[source], simplified_form_cost.get(form, costs[source]))

    table = {}
    unreadable = 0
    for form, source in forms:
        if form in table or len(form) != len(source):
            continue
        syllables = simplified[source]
        # A word whose characters all take their first reading, tones included, needs no readings
        # of its own: it is there for its cost, which decides how the words around it are cut. One
        # that settles a polyphonic character, or a tone, carries its readings.
        polyphonic = len(form) > 1 and any(
            c in unihan and (len(make_readings.modern_toneless(unihan[c])) > 1 or first_reading(c)[:-1] != s)
            for c, s in zip(form, syllables))
        if source in additions:
            readings = additions[source]
        else:
            readings = [numbered_reading(c, s, orders, f, k > 0 and not begins_noun(source, k, simplified))
                        for k, (c, s, f) in enumerate(zip(form, syllables, source))]
            if None in readings and polyphonic:
                unreadable += 1  # pyzy reads a character in a way no Unihan field knows: not trusted
                continue
            if None not in readings:
                readings = with_known_words(source, readings, additions)
        as_characters = not polyphonic and readings == [first_reading(c) for c in form]
        if len(form) == 1 or None in readings or as_characters:
            readings = []
        table[form] = (min(costs[source], simplified_form_cost.get(form, costs[source])), readings)
    lines = [f"{form}\t{cost}" + (f"\t{' '.join(readings)}" if readings else "")
             for form, (cost, readings) in sorted(table.items())]
    embed_text.write_cpp(
        OUTPUT, "tools/make_phrases.py",
        ["Modified data derived from the Android Open Source Project's Pinyin IME phrase list as",
         "shipped in Debian libpyzy-1.0-0v5 (android.db), Copyright 2008-2010 The Android Open",
         "Source Project, Apache License 2.0: frequency ranks turned into word costs, pinyin ids",
         "decoded and kept only where they settle a polyphonic character, Traditional forms added",
         "with OpenCC (Apache License 2.0), tones chosen from Unihan (Copyright (c) 1991-2022",
         "Unicode, Inc., Unicode License)."],
        {"phrases_text": lines})
    with_readings = sum(1 for _, readings in table.values() if readings)
    print(f"make_phrases: {len(simplified)} Simplified words, {len(lines)} with Traditional forms, "
          f"{with_readings} of them with readings, {unreadable} dropped (reading not in Unihan) "
          f"-> {os.path.relpath(OUTPUT, ROOT)}")


if __name__ == "__main__":
    main()
