"""`talkface syllables`: the SPEC "Contracts" JSON (the timeline JSON without times, pause marks
included), the plain listing, and errors."""
import json
import os
import subprocess

CLI = os.environ["TALKFACE_CLI"]


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=60)


def write(tmp_path, text, name="transcript.txt"):
    path = tmp_path / name
    path.write_bytes(text.encode("utf-8") if isinstance(text, str) else text)
    return path


def test_json_has_exactly_the_contract_shape(tmp_path):
    path = write(tmp_path, "長期下來，傷害不斷累積。\n銀行{hang2}很好 ★")
    result = run("syllables", path, "--json")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    document = json.loads(result.stdout)
    assert list(document) == ["version", "sentences", "syllables", "warnings"]
    assert document["sentences"] == [{"text": "長期下來，傷害不斷累積。"}, {"text": "銀行很好 ★"}]
    syllables = document["syllables"]
    assert all(list(s) == ["text", "pinyin", "sentence", "pause_after"] for s in syllables)
    assert [s["text"] for s in syllables] == list("長期下來傷害不斷累積銀行很好")
    assert [s["pinyin"][:-1] for s in syllables[:4]] == ["chang", "qi", "xia", "lai"]
    assert syllables[11] == {"text": "行", "pinyin": "hang2", "sentence": 1, "pause_after": False}
    assert [s["text"] for s in syllables if s["pause_after"]] == ["來"]
    assert [s["sentence"] for s in syllables] == [0] * 10 + [1] * 4
    assert len(document["warnings"]) == 1
    assert document["warnings"][0].startswith(f'{path}:2:13: "★"')


def test_emoji_and_faces_are_unsaid_without_a_warning(tmp_path):
    # Session 31: on main d388cc3 each emoji and each sign of the face was a warning on stderr.
    path = write(tmp_path, "谢谢🚀晚安(｡･ω･｡)ﾉ\n价格＆")
    result = run("syllables", path, "--json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert [s["text"] for s in document["syllables"]] == list("谢谢晚安价格")
    assert len(document["warnings"]) == 1 and document["warnings"][0].startswith(f'{path}:2:3: "＆"')


def test_json_writes_u_umlaut_as_v(tmp_path):
    document = json.loads(run("syllables", write(tmp_path, "綠色 lü4"), "--json").stdout)
    assert [s["pinyin"] for s in document["syllables"]] == ["lv4", "se4", "lv4"]


def test_plain_output_lists_sentences_and_readings_and_warns_on_stderr(tmp_path):
    result = run("syllables", write(tmp_path, "首都。都是 ★"))
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "sentence 1: 首都。", "  首\tshou3", "  都\tdu1",
        "sentence 2: 都是 ★", "  都\tdou1", "  是\tshi4"]
    assert 'talkface: warning:' in result.stderr and '"★"' in result.stderr


def test_full_width_letters_are_read_as_ascii_and_shown_as_written(tmp_path):
    result = run("syllables", write(tmp_path, "我用ｉＰｈｏｎｅ问ＡＩ，打Ｗｉ－Ｆｉ电话。"), "--json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["sentences"] == [{"text": "我用ｉＰｈｏｎｅ问ＡＩ，打Ｗｉ－Ｆｉ电话。"}]
    assert [f["text"] for f in document["written_forms"]] == ["ｉＰｈｏｎｅ", "ＡＩ", "Ｗｉ－Ｆｉ"]
    assert [s["pinyin"] for s in document["syllables"][2:4]] == ["ai1", "feng5"]
    assert document["warnings"] == []
    plain = run("syllables", write(tmp_path, "ＡＩ"))
    assert "  ＡＩ -> ei ai\tei1 ai4" in plain.stdout.splitlines()


def test_plain_output_shows_each_written_form_and_what_it_became(tmp_path):
    result = run("syllables", write(tmp_path, "今天是2026年12月1日，我用iPhone。"))
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "  2026年 -> 二零二六年\ter4 ling2 er4 liu4 nian2" in lines
    assert "  1 -> 一\tyi1" in lines
    assert "  日\tri4\t(pause)" in lines
    assert "  iPhone -> ai feng\tai1 feng5" in lines
    assert result.stderr == ""


def test_a_word_no_table_reads_is_shown_as_generic_speech(tmp_path):
    result = run("syllables", write(tmp_path, "我用Zorblax打电话。"))
    assert result.returncode == 0, result.stderr
    assert "  Zorblax -> Zor blax\tde5 de5\t(unknown word: 2 syllables of generic speech)" in result.stdout.splitlines()
    assert "aligned as generic speech of about 2 syllables" in result.stderr
    document = json.loads(run("syllables", write(tmp_path, "我用Zorblax打电话。"), "--json").stdout)
    assert [s.get("generic_speech", False) for s in document["syllables"]] == [False, False, True, True, False, False,
                                                                              False]


def test_json_carries_the_written_text_of_each_syllable_group(tmp_path):
    document = json.loads(run("syllables", write(tmp_path, "打13812345678，GDP增长5%。"), "--json").stdout)
    assert list(document) == ["version", "sentences", "syllables", "written_forms", "warnings"]
    forms = document["written_forms"]
    assert [f["text"] for f in forms] == ["13812345678", "GDP", "5%"]
    phone = forms[0]
    said = document["syllables"][phone["first_syllable"]:phone["first_syllable"] + phone["syllable_count"]]
    assert "".join(s["text"] for s in said) == "幺三八幺二三四五六七八"
    assert document["sentences"] == [{"text": "打13812345678，GDP增长5%。"}]


def test_a_number_too_long_is_read_digit_by_digit_with_a_warning(tmp_path):
    result = run("syllables", write(tmp_path, "1" * 30))
    assert result.returncode == 0
    assert "more than 16 digits; read digit by digit" in result.stderr


def test_invalid_utf8_fails_naming_the_byte_offset(tmp_path):
    result = run("syllables", write(tmp_path, b"ab\n\xe4\xbd\xa0\xff"), "--json")
    assert result.returncode == 1
    assert result.stdout == ""
    assert "transcript.txt:2:2: byte offset 6: not UTF-8 (the byte 0xFF starts no character)" in result.stderr


def test_a_gbk_or_big5_file_is_refused_naming_its_encoding_and_read_when_named(tmp_path):
    for text, encoding in [("长期下来，伤害不断累积。", "gb18030"), ("長期下來，傷害不斷累積。", "big5")]:
        path = write(tmp_path, text.encode(encoding), f"{encoding}.txt")
        refused = run("syllables", path)
        assert refused.returncode == 1
        assert f"it reads as {encoding} (" in refused.stderr and f'"{text}"' in refused.stderr
        assert f"--transcript-encoding {encoding}" in refused.stderr
        read = run("syllables", path, "--transcript-encoding", encoding, "--json")
        assert read.returncode == 0, read.stderr
        assert json.loads(read.stdout)["sentences"] == [{"text": text}]
    assert "is not an encoding" in run("syllables", path, "--transcript-encoding", "klingon").stderr


def test_notepad_unicode_files_are_read(tmp_path):
    for codec in ["utf-16", "utf-16-be", "utf-32"]:
        data = "你好。".encode(codec)
        if codec == "utf-16-be":
            data = b"\xfe\xff" + data
        result = run("syllables", write(tmp_path, data, f"{codec}.txt"), "--json")
        assert result.returncode == 0, result.stderr
        assert json.loads(result.stdout)["sentences"] == [{"text": "你好。"}]


def test_subtitles_as_the_transcript_give_their_text_not_their_numbers_and_times(tmp_path):
    srt = "1\n00:00:01,000 --> 00:00:02,000\n<i>大家好</i>\n\n2\n00:00:02,500 --> 00:00:04,000\n{\\an8}欢迎收看\n"
    document = json.loads(run("syllables", write(tmp_path, srt, "subs.srt"), "--json").stdout)
    assert document["sentences"] == [{"text": "大家好"}, {"text": "欢迎收看"}]
    assert "".join(s["text"] for s in document["syllables"]) == "大家好欢迎收看"


def test_a_scripts_directions_and_labels_are_left_out_with_warnings_unless_kept(tmp_path):
    path = write(tmp_path, "主持人：大家好（笑）\n嘉宾：[掌声] 你好\n主持人：欢迎。\n")
    result = run("syllables", path, "--json")
    document = json.loads(result.stdout)
    assert "".join(s["text"] for s in document["syllables"]) == "大家好你好欢迎"
    assert len(document["sentences"]) == 3
    assert any('"主持人：" is a speaker\'s label (2 lines)' in w for w in document["warnings"])
    kept = json.loads(run("syllables", path, "--json", "--keep-directions").stdout)
    assert "".join(s["text"] for s in kept["syllables"]) == "主持人大家好笑嘉宾掌声你好主持人欢迎"


def test_an_invalid_reading_fix_fails_naming_it(tmp_path):
    result = run("syllables", write(tmp_path, "行{hxng2}"))
    assert result.returncode == 1
    assert '"{hxng2}"' in result.stderr


def test_a_missing_transcript_is_a_usage_error(tmp_path):
    assert run("syllables", tmp_path / "missing.txt").returncode == 2


def listing_and_document(tmp_path, text):
    """`talkface syllables` on a transcript of `text`: the plain listing and the --json document."""
    path = write(tmp_path, text)
    plain = run("syllables", path)
    assert plain.returncode == 0, plain.stderr
    return plain.stdout, json.loads(run("syllables", path, "--json").stdout)


def test_news_forms_show_what_they_became(tmp_path):
    # Session 15: a stock code's exchange suffix is not said, a floor written nF is n楼.
    plain, document = listing_and_document(tmp_path, "腾讯控股（00700.HK）的门店在2F。")
    assert "00700.HK -> 零零七零零\tling2 ling2 qi1 ling2 ling2" in plain
    assert "2F -> 二楼\ter4 lou2" in plain
    assert [f["text"] for f in document["written_forms"]] == ["00700.HK", "2F"]
    assert "".join(s["text"] for s in document["syllables"]) == "腾讯控股零零七零零的门店在二楼"


def test_subtitle_timings_video_places_scores_and_degrees(tmp_path):
    # Session 16: a lyric's time tag is not said, a place in a video is minutes and seconds, a falling
    # score between two teams is a score, 2度 of weather is 两度, and a short line of Taiwan's shows 樓.
    plain, document = listing_and_document(tmp_path, "[00:12.50]视频1:23处，曼城2-1阿森纳，气温只有2度。")
    assert "1:23 -> 一分二十三秒\tyi1 fen1 er4 shi2 san1 miao3" in plain
    assert "2-1 -> 二比一\ter4 bi3 yi1" in plain
    assert "2 -> 两\tliang3" in plain
    assert document["sentences"][0]["text"].startswith("[00:12.50]视频")
    assert [f["text"] for f in document["written_forms"]] == ["1:23", "2-1", "2"]
    assert document["syllables"][0]["text"] == "视"
    taiwan, _ = listing_and_document(tmp_path, "台北101大樓89F觀景台，113/12/31截止。")
    assert "89F -> 八十九樓\tba1 shi2 jiu3 lou2" in taiwan
    assert "113/12/31 -> 一百一十三年十二月三十一日" in taiwan
    _, table = listing_and_document(tmp_path, "积分榜：1.利物浦 68分 2.阿森纳 65分")
    assert [s["text"] for s in table["sentences"]] == ["积分榜：1.利物浦 68分 2.阿森纳 65分"]
