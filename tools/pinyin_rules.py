"""Pinyin spelling shared by the talkface data generators (make_readings.py, make_phrases.py).

Numbered pinyin is what talkface stores and prints: tone 1-5 after the letters (5 = neutral),
u-umlaut written v ("lv4"). The legality check is the Mandarin syllable grammar, independent of
any dictionary, so that a generator can tell a bad table entry from a rare but real syllable.
"""

import unicodedata

# Combining marks left by NFD: tone marks become digits; the diaeresis is the u-umlaut, the
# circumflex the e of "ê" (a syllable talkface does not keep: see make_readings.py).
TONE_MARKS = {"\u0304": "1", "\u0301": "2", "\u030c": "3", "\u0300": "4"}

INITIALS = ["zh", "ch", "sh", "b", "p", "m", "f", "d", "t", "n", "l", "g", "k", "h", "j", "q", "x",
            "r", "z", "c", "s", "y", "w"]

# The finals as written after each kind of initial (spelling rules folded in: y/w spellings,
# "iu" "ui" "un" contractions, ju = jv). Sets are deliberately generous only where Mandarin
# dictionaries attest syllables (dei, den, nou, kei, rua, shei, zhei, tei, cei, ...).
_AFTER_LABIAL = {"a", "o", "ai", "ei", "ao", "an", "en", "ang", "eng", "i", "ie", "iao", "ian",
                 "in", "ing", "u", "ou", "iu", "iang"}
_FINALS = {
    "b": _AFTER_LABIAL - {"ou", "iu"},  # biang: 𰻞 (biangbiang noodles)
    "p": _AFTER_LABIAL - {"iu", "iang"},
    "m": (_AFTER_LABIAL | {"e"}) - {"iang"},
    "f": {"a", "o", "ei", "an", "en", "ang", "eng", "u", "ou", "iao"},
    "d": {"a", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "i", "ia", "ie", "iao",
          "iu", "ian", "ing", "u", "uo", "ui", "uan", "un", "iang", "in"},
    "t": {"a", "e", "ai", "ei", "ao", "ou", "an", "ang", "eng", "ong", "i", "ie", "iao", "ian",
          "ing", "u", "uo", "ui", "uan", "un"},
    "n": {"a", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "i", "ie", "iao", "iu",
          "ian", "in", "iang", "ing", "u", "uo", "uan", "un", "v", "ve", "ia", "g", ""},
    "l": {"a", "e", "o", "ai", "ei", "ao", "ou", "an", "ang", "eng", "ong", "i", "ia", "ie", "iao",
          "iu", "ian", "in", "iang", "ing", "u", "uo", "uan", "un", "v", "ve", "en", "ui"},
    "g": {"a", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "u", "ua", "uo", "uai",
          "ui", "uan", "un", "uang", "i"},
    "k": {"a", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "u", "ua", "uo", "uai",
          "ui", "uan", "un", "uang"},
    "h": {"a", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "u", "ua", "uo", "uai",
          "ui", "uan", "un", "uang", "m", "ng", "o"},
    "j": {"i", "ia", "ie", "iao", "iu", "ian", "in", "iang", "ing", "iong", "u", "ue", "uan", "un"},
    "zh": {"a", "e", "i", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "u", "ua", "uo",
           "uai", "ui", "uan", "un", "uang"},
    "r": {"e", "i", "ao", "ou", "an", "en", "ang", "eng", "ong", "u", "ua", "uo", "ui", "uan",
          "un"},
    "z": {"a", "e", "i", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "u", "uo", "ui",
          "uan", "un"},
    "y": {"a", "o", "e", "ai", "ao", "ou", "an", "ang", "i", "in", "ing", "ong", "u", "ue", "uan",
          "un"},
    "w": {"a", "o", "ai", "ei", "an", "en", "ang", "eng", "u", "ong"},
}
_FINALS["q"] = _FINALS["x"] = _FINALS["j"]
_FINALS["ch"] = _FINALS["zh"] - {"ei"} | {"uai"}
_FINALS["sh"] = _FINALS["zh"] - {"ong"}
_FINALS["c"] = _FINALS["z"]
_FINALS["s"] = _FINALS["z"]
# Syllables with no initial: vowels, and the nasal interjections hm hng m n ng.
_BARE = {"a", "o", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "er", "m", "n", "ng",
         "hm", "hng"}


def is_legal_toneless(syllable: str) -> bool:
    """True if `syllable` (toneless, v for u-umlaut) is spelled as a Mandarin syllable can be."""
    if syllable in _BARE:
        return True
    for initial in INITIALS:
        if syllable.startswith(initial):
            return syllable[len(initial):] in _FINALS.get(initial, set())
    return False


def to_numbered(marked: str):
    """'zhǎng' -> 'zhang3', 'lǘ' -> 'lv2', 'ḿ' -> 'm2', 'de' -> 'de5'; None for 'ê' readings."""
    letters = []
    tone = "5"
    for ch in unicodedata.normalize("NFD", marked.strip().lower()):
        if ch in TONE_MARKS:
            tone = TONE_MARKS[ch]
        elif ch == "\u0308":
            if not letters or letters[-1] != "u":
                raise ValueError(f"diaeresis not on u in {marked!r}")
            letters[-1] = "v"
        elif ch == "\u0302":
            return None
        elif "a" <= ch <= "z":
            letters.append(ch)
        else:
            raise ValueError(f"unexpected character {ch!r} in reading {marked!r}")
    if not letters:
        raise ValueError(f"empty reading {marked!r}")
    return "".join(letters) + tone


def split_syllable(syllable: str):
    """Toneless syllable -> (initial, final) as spelled: 'zhang' -> ('zh', 'ang'), 'an' -> ('', 'an')."""
    for initial in INITIALS:
        if syllable.startswith(initial) and len(syllable) > len(initial):
            return initial, syllable[len(initial):]
    return "", syllable
