"""talkface.batch without a cluster: the manifest, each job kind, skipping, and files left behind.
The jobs run on the bundled speech's shortest clip (tests/data/speech/one_sentence: 3.1 s)."""

import dataclasses
import json
import os
import pathlib
import xml.etree.ElementTree as ElementTree

import pytest

import talkface
import talkface.batch as batch

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
SPEECH = SOURCE_DIR / "tests" / "data" / "speech"
AUDIO = SPEECH / "one_sentence.wav"
TRANSCRIPT = SPEECH / "one_sentence.txt"
AUDIO_S = 3.1


def write_manifest(tmp_path, text, name="jobs.csv"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


def parse_error(tmp_path, text):
    path = write_manifest(tmp_path, text)
    with pytest.raises(talkface.ParseError) as raised:
        batch.read_manifest(path)
    return path, raised.value


def test_manifest_rows_become_jobs_with_paths_beside_the_manifest(tmp_path):
    (tmp_path / "sub").mkdir()
    path = write_manifest(
        tmp_path / "sub",
        "\ufeffoutput, audio ,transcript,seed,app,style,face,timing\n"
        "out/a.html,a.ogg,a.txt,7,audiobook,announcer,,\n"
        "\n"
        '"out/b, with comma.mp4",/abs/b.wav,b.txt,,plain,my_style.json,face.xml,b.srt\n',
    )
    jobs = batch.read_manifest(path)
    folder = str(tmp_path / "sub")
    assert [job.row for job in jobs] == [2, 4]
    first, second = jobs
    assert first.output == os.path.join(folder, "out", "a.html")
    assert first.audio == os.path.join(folder, "a.ogg")
    assert (first.seed, first.app, first.style, first.face, first.timing) == (7, "audiobook", "announcer", "", "")
    assert second.output == os.path.join(folder, "out", "b, with comma.mp4")
    assert second.audio == "/abs/b.wav"
    assert second.style == os.path.join(folder, "my_style.json")
    assert second.face == os.path.join(folder, "face.xml")
    assert second.timing == os.path.join(folder, "b.srt")
    assert second.seed == 0
    assert second.where() == f"{path}:4"
    assert set(second.inputs()) == {second.audio, second.transcript, second.face, second.style, second.timing}


@pytest.mark.parametrize(
    "text, line, item, words",
    [
        ("audio,transcript\n", 1, "output", 'no "output" column'),
        ("audio,transcript,output,speed\n", 1, "speed", 'unknown column "speed"'),
        ("audio,transcript,output,audio\n", 1, "audio", "appears twice"),
        ("audio,transcript,output\na.ogg,a.txt,a.html\nb.ogg,b.txt\n", 3, "", "2 fields"),
        ("audio,transcript,output\na.ogg,a.txt,a.html\n\nb.ogg,,b.html\n", 4, "transcript", "empty"),
        ("audio,transcript,output\na.ogg,a.txt,a.docx\n", 2, "output", "a.docx"),
        ("audio,transcript,output,seed\na.ogg,a.txt,a.html,-1\n", 2, "seed", '"-1"'),
        ("audio,transcript,output,seed\na.ogg,a.txt,a.html,18446744073709551616\n", 2, "seed", "2^64-1"),
        ("audio,transcript,output,app\na.ogg,a.txt,a.json,audiobook\n", 2, "app", "only pages and videos"),
        ("audio,transcript,output,app\na.ogg,a.txt,a.mp4,audiobook\n", 2, "app", "announcer, plain"),
        ("audio,transcript,output\na.ogg,a.txt,x.html\nb.ogg,b.txt,./x.html\n", 3, "output", "line 2"),
        ('audio,transcript,output\na.ogg,"a.txt,a.html\n', 2, "", "not CSV"),
        ("", 1, "", "empty"),
    ],
)
def test_manifest_errors_name_file_line_and_column(tmp_path, text, line, item, words):
    path, error = parse_error(tmp_path, text)
    assert str(error).startswith(f"{path}:{line}: ")
    assert words in str(error)
    assert (error.path, error.line, error.item) == (path, line, item)
    if item:
        assert f"column {item}" in str(error)


def test_a_manifest_that_is_not_utf8_names_its_line(tmp_path):
    path = tmp_path / "jobs.csv"
    path.write_bytes(b"audio,transcript,output\na.ogg,a.txt,a.html\n\xff.ogg,a.txt,b.html\n")
    with pytest.raises(talkface.ParseError, match=r"jobs.csv:3: not UTF-8"):
        batch.read_manifest(str(path))


def test_a_missing_manifest_is_a_file_error(tmp_path):
    with pytest.raises(OSError) as raised:
        batch.read_manifest(str(tmp_path / "none.csv"))
    assert isinstance(raised.value, talkface.FileError)
    assert "none.csv" in str(raised.value)


@pytest.mark.parametrize(
    "output, kind",
    [("a.html", "page"), ("a.svg", "svg"), ("a.mp4", "video"), ("a.WEBM", "video"), ("a.webp", "video"), ("a.gif", "video"),
     ("a.json", "keyframes"), ("a.motion3.json", "export:live2d"), ("a.tsv", "export:rhubarb-tsv"),
     ("a.xml", "export:rhubarb-xml"), ("a.dat", "export:moho"), ("a.TextGrid", "export:textgrid"),
     ("a.srt", "export:srt"), ("a.vtt", "export:vtt")],
)
def test_the_extension_picks_the_job(output, kind):
    assert batch.job_kind(output) == kind


def test_an_unknown_extension_lists_the_known_ones():
    with pytest.raises(talkface.InvalidArgument, match=r"\.html .*\.mp4 .*\.TextGrid") as raised:
        batch.job_kind("frames.png")  # a numbered sequence is many files: not a batch output
    assert raised.value.parameter == "output"


def check_whole(path):
    """The output parses as its kind and spans the clip's 3.1 s."""
    text = path.read_text(encoding="utf-8")
    if path.name.endswith(".motion3.json"):
        assert json.loads(text)["Meta"]["Duration"] == pytest.approx(AUDIO_S, abs=0.1)
    elif path.suffix == ".json":
        assert json.loads(text)["duration"] == pytest.approx(AUDIO_S, abs=0.1)
    elif path.suffix == ".html":
        assert text.startswith("<!DOCTYPE html>") and text.rstrip().endswith("</html>")
    elif path.suffix == ".svg":
        assert ElementTree.fromstring(text).tag.endswith("svg")
    elif path.suffix == ".TextGrid":
        xmax = float(text.split("xmax = ", 1)[1].split()[0])
        assert xmax == pytest.approx(AUDIO_S, abs=0.1)
    else:
        assert text


@pytest.mark.parametrize("name", ["a.json", "a.html", "a.svg", "a.TextGrid", "a.srt", "a.motion3.json"])
def test_run_job_writes_a_whole_output_and_nothing_else(tmp_path, name):
    output = tmp_path / "new folder" / name
    result = batch.run_job(batch.Job(str(AUDIO), str(TRANSCRIPT), str(output)))
    assert (result.status, result.message) == ("done", "")
    assert result.output_size == output.stat().st_size > 0
    assert result.seconds > 0 and result.worker.endswith(f":{os.getpid()}")
    check_whole(output)
    assert sorted(os.listdir(output.parent)) == sorted([name, f".{name}.talkface-job"])


def copied_inputs(tmp_path):
    """The clip's audio and transcript, and a style and a timing file, as files of the test's own."""
    inputs = {"audio": tmp_path / "speech.wav", "transcript": tmp_path / "speech.txt",
              "style": tmp_path / "style.json", "timing": tmp_path / "speech.json"}
    inputs["audio"].write_bytes(AUDIO.read_bytes())
    inputs["transcript"].write_bytes(TRANSCRIPT.read_bytes())
    inputs["style"].write_text(talkface.ExpressionStyle.from_name("normal").to_json(), encoding="utf-8")
    timeline = talkface.SpeechAligner().align_file(str(AUDIO), talkface.load_transcript(str(TRANSCRIPT)))
    inputs["timing"].write_text(talkface.timeline_to_json(timeline), encoding="utf-8")
    return inputs


def edited_with_its_old_time(path, change):
    """Changes a file's bytes and gives it back its time: a change no file time shows."""
    before = path.stat()
    change(path)
    os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))


def test_a_job_is_skipped_while_its_inputs_and_options_are_those_it_was_made_from(tmp_path):
    inputs = copied_inputs(tmp_path)
    output = tmp_path / "page.html"
    job = batch.Job(str(inputs["audio"]), str(inputs["transcript"]), str(output), app="plain",
                    style=str(inputs["style"]), seed=3, timing=str(inputs["timing"]))
    assert batch.run_job(job).status == "done"
    first = output.stat().st_mtime_ns
    skipped = batch.run_job(job)
    assert (skipped.status, skipped.output_size) == ("skipped", output.stat().st_size)
    assert output.stat().st_mtime_ns == first
    # Nothing that leaves the contents and the options as they were redoes it: newer times, the
    # inputs copied elsewhere, the default app named.
    for path in inputs.values():
        os.utime(path, ns=(first + 10**9,) * 2)
    moved = tmp_path / "moved"
    moved.mkdir()
    for path in inputs.values():
        (moved / path.name).write_bytes(path.read_bytes())
    for same in [job, dataclasses.replace(job, audio=str(moved / "speech.wav"), transcript=str(moved / "speech.txt"),
                                          style=str(moved / "style.json"), timing=str(moved / "speech.json")),
                 dataclasses.replace(job, app="")]:
        assert batch.run_job(same).status == "skipped", same
    assert output.stat().st_mtime_ns == first
    assert batch.run_job(job, force=True).status == "done"


@pytest.mark.parametrize("change", ["audio", "transcript", "style", "timing", "seed", "app", "named style",
                                    "output removed", "digest removed"])
def test_each_kind_of_change_redoes_the_job(tmp_path, change):
    inputs = copied_inputs(tmp_path)
    output = tmp_path / "page.html"
    job = batch.Job(str(inputs["audio"]), str(inputs["transcript"]), str(output), app="plain",
                    style=str(inputs["style"]), seed=3, timing=str(inputs["timing"]))
    assert batch.run_job(job).status == "done"
    assert batch.is_up_to_date(job)
    if change == "audio":  # a quieter recording, same length, same time
        edited_with_its_old_time(inputs["audio"], lambda path: path.write_bytes(
            path.read_bytes()[:44] + bytes(b & 0xFE for b in path.read_bytes()[44:])))
    elif change == "transcript":  # one character changed, same length, same time
        edited_with_its_old_time(inputs["transcript"], lambda path: path.write_text(
            path.read_text(encoding="utf-8").replace("。", "！", 1), encoding="utf-8"))
    elif change == "style":
        edited_with_its_old_time(inputs["style"], lambda path: path.write_text(
            talkface.ExpressionStyle.from_name("announcer").to_json(), encoding="utf-8"))
    elif change == "timing":
        def later(path):
            timeline = talkface.timeline_from_json(path.read_text(encoding="utf-8"))
            syllables = timeline.syllables
            syllables[0].start_s += 0.01
            timeline.syllables = syllables
            path.write_text(talkface.timeline_to_json(timeline), encoding="utf-8")
        edited_with_its_old_time(inputs["timing"], later)
    elif change == "seed":
        job = dataclasses.replace(job, seed=4)
    elif change == "app":
        job = dataclasses.replace(job, app="audiobook")
    elif change == "named style":
        job = dataclasses.replace(job, style="announcer")
    elif change == "output removed":
        output.unlink()
    else:
        (tmp_path / ".page.html.talkface-job").unlink()  # an output made before the digest was kept
    assert not batch.is_up_to_date(job)
    assert batch.run_job(job).status == "done"
    assert batch.run_job(job).status == "skipped"


def test_a_failed_job_says_why_and_leaves_no_file(tmp_path):
    not_audio = tmp_path / "noise.wav"
    not_audio.write_text("not audio", encoding="utf-8")
    leftover = tmp_path / "a.html.tmp-Ab12Cd"  # as a killed writer leaves it
    leftover.write_text("half a page", encoding="utf-8")
    cases = [
        (batch.Job(str(not_audio), str(TRANSCRIPT), str(tmp_path / "a.html")), "noise.wav: a text file"),
        (batch.Job(str(tmp_path / "none.wav"), str(TRANSCRIPT), str(tmp_path / "b.json")), "none.wav"),
        (batch.Job(str(AUDIO), str(tmp_path / "none.txt"), str(tmp_path / "c.srt")), "none.txt"),
        (batch.Job(str(AUDIO), str(SPEECH / "run_together.txt"), str(tmp_path / "d.json")), "sentence"),
        (batch.Job(str(AUDIO), str(TRANSCRIPT), str(tmp_path / "e.json"), face=str(TRANSCRIPT)), "one_sentence.txt:1"),
    ]
    for job, words in cases:
        result = batch.run_job(job)
        assert result.status == "failed", job
        assert words in result.message
        assert result.output_size == 0
    assert sorted(os.listdir(tmp_path)) == ["noise.wav"]


def test_a_cancelled_job_leaves_no_file(tmp_path):
    output = tmp_path / "a.json"
    result = batch.run_job(batch.Job(str(AUDIO), str(TRANSCRIPT), str(output)), progress=lambda fraction, stage: False)
    assert result.status == "failed" and "cancel" in result.message.lower()
    assert os.listdir(tmp_path) == []


def test_run_refuses_local_cluster_settings_for_a_running_scheduler():
    pytest.importorskip("distributed")
    with pytest.raises(ValueError, match="workers: applies to the local cluster only"):
        batch.run([], scheduler="tcp://127.0.0.1:1", workers=2)
    with pytest.raises(ValueError, match="retries"):
        batch.run([], retries=-1)


def run_command(*arguments):
    import subprocess
    import sys

    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    return subprocess.run([sys.executable, "-m", "talkface", *arguments], capture_output=True, text=True,
                          timeout=60, env=environment)


def test_the_command_names_a_wrong_manifest_before_starting_a_cluster(tmp_path):
    path = write_manifest(tmp_path, "audio,transcript,output\na.ogg,a.txt,a.docx\n")
    finished = run_command("batch", path)
    assert finished.returncode == 1
    assert finished.stderr.startswith(f"talkface: error: {path}:2: column output:")


@pytest.mark.parametrize(
    "arguments, words",
    [(["--workers", "0"], "--workers: expected 1 or more"),
     (["--retries", "-1"], "--retries: expected 0 or more"),
     (["--scheduler", "tcp://127.0.0.1:1", "--workers", "2"], "local cluster"),
     (["--speed", "2"], "unrecognized arguments")],
)
def test_the_command_refuses_wrong_options_with_status_2(tmp_path, arguments, words):
    path = write_manifest(tmp_path, "audio,transcript,output\n")
    finished = run_command("batch", path, *arguments)
    assert finished.returncode == 2
    assert words in finished.stderr


def test_a_job_whose_workers_all_died_is_reported_failed():
    distributed_scheduler = pytest.importorskip("distributed.scheduler")

    class LostFuture:
        def result(self):
            raise distributed_scheduler.KilledWorker("talkface-job-0-x", None, 3)

    job = batch.Job("a.ogg", "a.txt", "a.html", row=5, manifest="jobs.csv")
    result = batch._result_of(LostFuture(), job)
    assert (result.status, result.job, result.output_size) == ("failed", job, 0)
    assert "died each time it was tried (4 times)" in result.message


def test_the_local_cluster_is_one_thread_a_worker_on_loopback_with_its_retries(monkeypatch):
    distributed = pytest.importorskip("distributed")
    import dask

    made = {}

    def local_cluster(**arguments):
        # What the cluster would read from Dask's settings as it starts.
        made.update(arguments, allowed_failures=dask.config.get("distributed.scheduler.allowed-failures"),
                    profile=dask.config.get("distributed.worker.profile.enabled"))
        return "cluster"

    monkeypatch.setattr(distributed, "LocalCluster", local_cluster)
    assert batch.local_cluster(workers=3, retries=0) == "cluster"
    assert (made["n_workers"], made["threads_per_worker"], made["processes"]) == (3, 1, True)
    assert (made["host"], made["dashboard_address"]) == ("127.0.0.1", None)
    assert (made["allowed_failures"], made["profile"]) == (0, False)
    assert dask.config.get("distributed.worker.profile.enabled") is True  # set for the cluster only
    batch.local_cluster()
    assert (made["n_workers"], made["allowed_failures"]) == (os.cpu_count(), 3)
    with pytest.raises(ValueError, match="workers: expected 1 or more"):
        batch.local_cluster(workers=0)
