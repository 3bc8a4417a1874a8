"""Transcripts and timelines in Python: read_transcript, load_transcript, is_valid_pinyin,
syllable_mouth_shapes, and the timeline JSON (timeline_from_json / timeline_to_json, the library's
codec, the same bytes as the command and C)."""
import pytest

import talkface


def spoken_timeline():
    """你好，世界。 spoken from 0.5 s, one syllable every 0.25 s, 2 s of audio."""
    timeline = talkface.read_transcript("你好，世界。")
    syllables = timeline.syllables
    for index, syllable in enumerate(syllables):
        syllable.start_s = 0.5 + 0.25 * index
        syllable.end_s = syllable.start_s + 0.25
    syllables[0].final_start_s = 0.58
    syllables[1].confidence = 0.75
    timeline.syllables = syllables
    sentences = timeline.sentences
    sentences[0].start_s, sentences[0].end_s = 0.5, 1.5
    timeline.sentences = sentences
    timeline.duration_s = 2.0
    return timeline


def test_read_transcript_gives_sentences_syllables_and_warnings():
    timeline = talkface.read_transcript("長期下來，傷害不斷累積。\n銀行{hang2}很好 ★", source_name="story.txt")
    assert [s.text for s in timeline.sentences] == ["長期下來，傷害不斷累積。", "銀行很好 ★"]
    assert "".join(s.text for s in timeline.syllables) == "長期下來傷害不斷累積銀行很好"
    assert timeline.syllables[11].pinyin == "hang2"
    assert timeline.syllables[11].sentence == 1
    assert timeline.syllables[3].pause_after
    assert len(timeline.warnings) == 1
    assert timeline.warnings[0].startswith('story.txt:2:13: "★"')
    assert all(s.start_s == 0.0 and s.final_start_s is None for s in timeline.syllables)


def test_emoji_and_faces_are_unsaid_without_a_warning():
    # Session 31: on main d388cc3 each emoji and each sign of the face was warned of, and the ω said.
    timeline = talkface.read_transcript("谢谢🚀晚安(｡･ω･｡)ﾉ", source_name="chat.txt")
    assert "".join(s.text for s in timeline.syllables) == "谢谢晚安"
    assert timeline.warnings == []
    assert [s.text for s in timeline.sentences] == ["谢谢🚀晚安(｡･ω･｡)ﾉ"]
    assert len(talkface.read_transcript("价格＆").warnings) == 1


def test_a_blank_line_starts_a_paragraph():
    timeline = talkface.read_transcript("春曉\n\n春眠不覺曉。處處聞啼鳥。\n夜來風雨聲，花落知多少？")
    assert [s.text for s in timeline.sentences] == ["春曉", "春眠不覺曉。", "處處聞啼鳥。", "夜來風雨聲，花落知多少？"]
    assert [s.starts_paragraph for s in timeline.sentences] == [False, True, False, False]
    assert '"paragraph":true' in talkface.timeline_to_json(timeline).replace(" ", "")
    assert [s.starts_paragraph for s in talkface.timeline_from_json(talkface.timeline_to_json(timeline)).sentences] == \
        [False, True, False, False]
    sentence = talkface.Sentence("好。", 0.5, 1.0, starts_paragraph=True)
    assert sentence.starts_paragraph
    assert sentence != talkface.Sentence("好。", 0.5, 1.0)


def test_pinyin_input_can_be_turned_off():
    assert [s.pinyin for s in talkface.read_transcript("ni3 hao3").syllables] == ["ni3", "hao3"]
    off = talkface.read_transcript("ni3 hao3", read_pinyin=False)
    # Read as Latin instead: "ni" is a word no table reads, generic speech (a warning names it), 3 a number.
    assert [s.pinyin for s in off.syllables][:2] == [talkface.kGenericSpeechPinyin, "san1"]
    assert off.syllables[0].generic_speech
    assert 'not in the English pronouncing dictionary' in off.warnings[0]


def test_written_forms_are_read_aloud_and_kept_beside_their_syllables():
    timeline = talkface.read_transcript("今天是2026年12月1日，我用iPhone打电话。")
    assert timeline.sentences[0].text == "今天是2026年12月1日，我用iPhone打电话。"
    forms = timeline.written_forms
    assert [f.text for f in forms] == ["2026年", "12", "1", "iPhone"]
    year = forms[0]
    said = timeline.syllables[year.first_syllable:year.first_syllable + year.syllable_count]
    assert "".join(s.text for s in said) == "二零二六年"
    assert [s.pinyin for s in said] == ["er4", "ling2", "er4", "liu4", "nian2"]
    assert forms[3] == talkface.WrittenForm("iPhone", first_syllable=15, syllable_count=2)
    assert timeline.warnings == []


def test_news_forms_read_as_newsreaders_say_them():
    # Session 15: the exchange's suffix unsaid, a floor nF, a jump's centimetres, -2.5度 of weather.
    timeline = talkface.read_transcript("台積電（2330.TW）在5F，他跳出8米22，氣溫-2.5度。")
    assert [f.text for f in timeline.written_forms] == ["2330.TW", "5F", "8", "22", "-2.5"]
    assert "".join(s.text for s in timeline.syllables) == "台積電二三三零在五樓他跳出八米二二氣溫零下二點五度"
    assert timeline.warnings == []


def test_game_records_ratings_dates_of_the_republic_and_versions():
    # Session 16: a game's record with 杠, an IP rating digit by digit, Taiwan's 113.10.15, a version after 版本.
    timeline = talkface.read_transcript("戰績0-10。防水等級IP68。113.10.15公告。新版本13.24。")
    assert [f.text for f in timeline.written_forms] == ["0-10", "IP", "68", "113.10.15", "13.24"]
    assert "".join(s.text for s in timeline.syllables) == "戰績零杠十防水等級aipi六八一百一十三年十月十五日公告新版本十三点二十四"
    assert timeline.warnings == []
    cue = talkface.read_transcript("00:01:23,450 --> 00:01:25,900 你终于来了")
    assert [s.text for s in cue.syllables] == ["你", "终", "于", "来", "了"]
    assert cue.sentences[0].text.startswith("00:01:23,450 -->")


def test_full_width_letters_are_read_as_their_ascii_forms():
    timeline = talkface.read_transcript("公司的ＣＥＯ说，ＧＤＰ增长５．３％。")
    assert [f.text for f in timeline.written_forms] == ["ＣＥＯ", "ＧＤＰ", "５．３％"]
    assert [s.pinyin for s in timeline.syllables[3:6]] == ["xi1", "yi4", "ou1"]
    assert timeline.warnings == []


def test_a_written_form_is_fixed_in_place_and_a_bad_fix_names_where():
    fixed = talkface.read_transcript("2026{两千零二十六}年")
    assert "".join(s.text for s in fixed.syllables) == "两千零二十六年"
    assert fixed.written_forms[0].syllable_count == 6
    with pytest.raises(talkface.ParseError, match=r"<transcript>:1:3: reading fix"):
        talkface.read_transcript("5%{★}")


def test_a_number_too_long_is_read_digit_by_digit_with_a_warning():
    timeline = talkface.read_transcript("1" * 20)
    assert len(timeline.syllables) == 20
    assert "more than 16 digits" in timeline.warnings[0]


def test_written_forms_go_through_the_timeline_json():
    timeline = talkface.read_transcript("请拨打110。")
    json = talkface.timeline_to_json(timeline, with_times=False)
    assert '"written_forms":[\n{"text":"110","first_syllable":3,"syllable_count":3}\n]' in json
    back = talkface.timeline_from_json(json)
    assert back.written_forms == timeline.written_forms


def test_a_word_no_table_reads_is_generic_speech():
    timeline = talkface.read_transcript("我用Zorblax打电话", source_name="t.txt")
    word = timeline.syllables[2:4]
    assert [s.text for s in word] == ["Zor", "blax"]
    assert all(s.generic_speech and s.pinyin == talkface.kGenericSpeechPinyin for s in word)
    assert not timeline.syllables[1].generic_speech
    assert "aligned as generic speech of about 2 syllables" in timeline.warnings[0]
    back = talkface.timeline_from_json(talkface.timeline_to_json(timeline, with_times=False))
    assert back.syllables == timeline.syllables
    syllable = talkface.Syllable("Zor", "de5", generic_speech=True)
    assert syllable.generic_speech
    assert "generic_speech=True" in repr(syllable)


def test_timeline_keeps_written_forms_it_is_given():
    timeline = talkface.Timeline(
        [talkface.Sentence("OK。")],
        [talkface.Syllable("ou", "ou1"), talkface.Syllable("kei", "kei4")],
        written_forms=[talkface.WrittenForm("OK", 0, 2)])
    assert timeline.written_forms[0].text == "OK"
    assert repr(timeline.written_forms[0]) == "talkface.WrittenForm('OK', first_syllable=0, syllable_count=2)"


def test_bad_reading_fix_is_a_parse_error_naming_where():
    with pytest.raises(talkface.ParseError, match=r"<transcript>:1:") as caught:
        talkface.read_transcript("銀行{hxng2}")
    assert caught.value.line == 1


def test_load_transcript_reads_a_file_and_names_a_missing_one(tmp_path):
    path = tmp_path / "story.txt"
    path.write_text("你好。", encoding="utf-8")
    assert [s.pinyin for s in talkface.load_transcript(path).syllables] == ["ni3", "hao3"]
    with pytest.raises(talkface.FileError, match="missing.txt") as caught:
        talkface.load_transcript(tmp_path / "missing.txt")
    assert isinstance(caught.value, OSError)
    assert caught.value.filename == str(tmp_path / "missing.txt")


def test_load_transcript_reads_a_named_encoding_and_refuses_a_guess(tmp_path):
    path = tmp_path / "big5.txt"
    path.write_bytes("銀行很好。".encode("big5"))
    with pytest.raises(talkface.ParseError, match="it reads as big5"):
        talkface.load_transcript(path)
    assert "".join(s.text for s in talkface.load_transcript(path, encoding="big5").syllables) == "銀行很好"
    with pytest.raises(talkface.InvalidArgument, match="encoding"):
        talkface.load_transcript(path, encoding="klingon")


def test_subtitles_and_directions(tmp_path):
    path = tmp_path / "subs.srt"
    path.write_text("1\n00:00:01,000 --> 00:00:02,000\n大家好（笑）\n\n2\n00:00:02,500 --> 00:00:03,000\n再见\n",
                    encoding="utf-8")
    timeline = talkface.load_transcript(path)
    assert [s.text for s in timeline.sentences] == ["大家好", "再见"]
    assert "stage direction" in timeline.warnings[0]
    kept = talkface.load_transcript(path, keep_directions=True)
    assert "".join(s.text for s in kept.syllables) == "大家好笑再见"
    assert len(talkface.read_transcript("A：你好\nB：你好\n", keep_directions=True).syllables) == 6


def test_is_valid_pinyin_and_syllable_mouth_shapes():
    assert talkface.is_valid_pinyin("hang2")
    assert not talkface.is_valid_pinyin("hxng2")
    names = [talkface.mouth_shape_name(s) for s in talkface.syllable_mouth_shapes("bo1")]
    assert names == ["m", "u", "o"]
    assert [talkface.mouth_shape_name(s) for s in talkface.syllable_mouth_shapes("hao")] == ["h", "a", "u"]
    assert "zhuang" in talkface.mandarin_syllables()
    with pytest.raises(talkface.InvalidArgument, match="xx"):
        talkface.syllable_mouth_shapes("xx")


def test_timeline_json_round_trips_every_field():
    timeline = spoken_timeline()
    text = talkface.timeline_to_json(timeline)
    back = talkface.timeline_from_json(text)
    assert back.sentences == timeline.sentences
    assert back.syllables == timeline.syllables
    assert back.warnings == timeline.warnings
    assert back.duration_s == 2.0
    assert back.syllables[0].final_start_s == 0.58
    assert back.syllables[1].pause_after


def test_timeline_json_has_the_align_contract_shape():
    import json

    document = json.loads(talkface.timeline_to_json(spoken_timeline()))
    assert list(document) == ["version", "sentences", "syllables", "duration", "warnings"]
    assert document["version"] == talkface.TIMELINE_JSON_VERSION == 1
    assert document["sentences"] == [{"text": "你好，世界。", "start": 0.5, "end": 1.5}]
    first = document["syllables"][0]
    assert list(first)[:5] == ["text", "pinyin", "start", "end", "sentence"]
    assert first["final_start"] == 0.58
    assert "final_start" not in document["syllables"][1]


def test_timeline_json_reads_the_syllables_contract_without_times():
    text = '{"sentences":[{"text":"你好。"}], "syllables":[{"text":"你","pinyin":"ni3","sentence":0}]}'
    timeline = talkface.timeline_from_json(text)
    assert timeline.syllables[0].pinyin == "ni3"
    assert timeline.syllables[0].end_s == 0.0


def test_timeline_json_without_times_keeps_the_pause_marks():
    import json

    document = json.loads(talkface.timeline_to_json(spoken_timeline(), with_times=False))
    assert "duration" not in document
    assert document["syllables"][1] == {"text": "好", "pinyin": "hao3", "sentence": 0, "pause_after": True}


def test_timeline_json_file_round_trip_and_a_newer_version_refused(tmp_path):
    path = tmp_path / "aligned.json"
    talkface.save_timeline_json(path, spoken_timeline())
    assert talkface.load_timeline_json(path).syllables == spoken_timeline().syllables
    assert talkface.timeline_to_json(talkface.load_timeline_json(path)) == path.read_text(encoding="utf-8")
    with pytest.raises(talkface.ParseError, match=r"version 7 is newer than this talkface reads \(version 1\)"):
        talkface.timeline_from_json('{"version": 7, "sentences": [], "syllables": []}')
    with pytest.raises(talkface.FileError):
        talkface.load_timeline_json(tmp_path / "missing.json")


@pytest.mark.parametrize(
    "text, match, item",
    [
        ('{"sentences": [}', r"aligned\.json:1:16: ", ""),
        ('{"sentences": []}', r'"syllables" is missing', "document"),
        ('{"sentences":[{"text":"a"}],"syllables":[{"text":"a","pinyin":"a1","sentence":0,"start":"x"}]}',
         r'1:89: syllables\[0\]\.start: expected a number', "syllables[0].start"),
        ('{"sentences":[{"text":"a"}],"syllables":[{"text":"a","pinyin":"a1","sentence":1}]}',
         r"syllables\[0\]\.sentence: expected a sentence index 0\.\.0, found 1", "syllables[0].sentence"),
        ('{"sentences":[{"start":0}],"syllables":[]}', r'sentences\[0\]: "text" is missing', "sentences[0]"),
    ],
)
def test_timeline_json_errors_name_where(text, match, item):
    with pytest.raises(talkface.ParseError, match=match) as caught:
        talkface.timeline_from_json(text, "aligned.json")
    assert caught.value.path == "aligned.json"
    assert caught.value.item == item


def test_addresses_calling_codes_and_no_1_are_read_aloud():
    timeline = talkface.read_transcript("请发邮件到zhangwei@163.com，或致电+86 10 6512 3456。他是No.1。")
    assert [f.text for f in timeline.written_forms] == ["zhangwei@163.com", "+86 10 6512 3456", "No.1"]
    address = timeline.written_forms[0]
    said = timeline.syllables[address.first_syllable:address.first_syllable + address.syllable_count]
    assert [s.text for s in said][2:4] == ["艾", "特"]
    assert "".join(s.text for s in said[4:]) == "一六三点kamu"
    code = timeline.written_forms[1]
    assert "".join(s.text for s in timeline.syllables[code.first_syllable:code.first_syllable + 3]) == "加八六"
    assert len(timeline.sentences) == 2
    assert timeline.warnings == []
