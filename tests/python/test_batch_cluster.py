"""talkface.batch on a real Dask cluster (issue 18): a `dask-scheduler` and two `dask-worker`
processes on a loopback port, a manifest of good and broken rows, one worker killed mid-run, then
the same manifest again through `python3 -m talkface batch`. Its own ctest entry (LABELS slow):
starting the processes takes a few seconds on a busy machine."""

import json
import os
import pathlib
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree

import pytest

import talkface
import talkface.batch as batch

distributed = pytest.importorskip("distributed")

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
DEMO = SOURCE_DIR / "samples" / "speech"
CLIPS = SOURCE_DIR / "tests" / "data" / "speech"
DEMO_S = 13.0
ONE_SENTENCE_S = 3.1
START_TIMEOUT_S = 60


def dask_command(name):
    # The scripts Debian installs, run by this interpreter so that the workers import this talkface.
    return [sys.executable, f"/usr/bin/{name}"]


def stop(process):
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


@pytest.fixture
def cluster(tmp_path):
    """A scheduler on 127.0.0.1 at a port it picks (written to a scheduler file) and two one-thread
    workers without nannies (a killed worker stays dead); all stopped afterwards."""
    scheduler_file = tmp_path / "scheduler.json"
    log = open(tmp_path / "dask.log", "w")
    processes = []
    try:
        processes.append(subprocess.Popen(
            dask_command("dask-scheduler") + ["--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                              "--scheduler-file", str(scheduler_file)],
            stdout=log, stderr=subprocess.STDOUT))
        deadline = time.monotonic() + START_TIMEOUT_S
        while not scheduler_file.exists() or not scheduler_file.read_text():
            assert time.monotonic() < deadline, "the scheduler did not start"
            assert processes[0].poll() is None, "the scheduler exited"
            time.sleep(0.1)
        address = json.loads(scheduler_file.read_text())["address"]
        assert address.startswith("tcp://127.0.0.1:")
        for name in ("worker-a", "worker-b"):
            processes.append(subprocess.Popen(
                dask_command("dask-worker") + [address, "--name", name, "--nthreads", "1", "--no-nanny",
                                               "--host", "127.0.0.1", "--no-dashboard",
                                               "--local-directory", str(tmp_path / name)],
                stdout=log, stderr=subprocess.STDOUT))
        with distributed.Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=START_TIMEOUT_S)
            yield address, client, processes[1:]
    finally:
        for process in reversed(processes):
            stop(process)
        log.close()


def write_manifest(folder):
    (folder / "noise.wav").write_text("not audio", encoding="utf-8")
    rows = [
        # good rows: every kind of output once
        f"{DEMO}/demo.ogg,{DEMO}/demo.txt,out/demo.html,1,audiobook",
        f"{DEMO}/demo.ogg,{DEMO}/demo.txt,out/demo.json,2,",
        f"{DEMO}/demo.ogg,{DEMO}/demo.txt,out/demo.TextGrid,,",
        f"{DEMO}/demo.ogg,{DEMO}/demo.txt,out/demo.srt,,",
        f"{CLIPS}/one_sentence.wav,{CLIPS}/one_sentence.txt,out/one.webm,,plain",
        f"{CLIPS}/two_sentences.wav,{CLIPS}/two_sentences.txt,out/two.svg,,",
        f"{CLIPS}/two_sentences.wav,{CLIPS}/two_sentences.txt,out/two.motion3.json,,",
        # broken rows: unreadable audio, the wrong transcript, a missing file
        f"noise.wav,{DEMO}/demo.txt,out/noise.html,,",
        f"{DEMO}/demo.ogg,{CLIPS}/one_sentence.txt,out/wrong.json,,",
        f"{DEMO}/missing.ogg,{DEMO}/demo.txt,out/missing.srt,,",
    ]
    manifest = folder / "jobs.csv"
    manifest.write_text("audio,transcript,output,seed,app\n" + "\n".join(rows) + "\n", encoding="utf-8")
    return manifest


GOOD = {"demo.html": DEMO_S, "demo.json": DEMO_S, "demo.TextGrid": DEMO_S, "demo.srt": DEMO_S,
        "one.webm": ONE_SENTENCE_S, "two.svg": 4.5, "two.motion3.json": 4.5}
BROKEN = {"noise.html": "noise.wav: a text file", "wrong.json": "sentence", "missing.srt": "missing.ogg"}


def duration_of(path):
    """The length in seconds an output says it has, read the way its users read it."""
    text = path.read_bytes()
    if path.suffix == ".webm":
        probe = subprocess.run(["ffprobe", "-v", "error", "-show_entries", "format=duration", "-of", "csv=p=0",
                                str(path)], capture_output=True, text=True, check=True, timeout=30)
        return float(probe.stdout)
    text = text.decode("utf-8")
    if path.name.endswith(".motion3.json"):
        return json.loads(text)["Meta"]["Duration"]
    if path.suffix == ".json":
        return json.loads(text)["duration"]
    if path.suffix == ".TextGrid":
        return float(text.split("xmax = ", 1)[1].split()[0])
    if path.suffix == ".srt":
        last_end = text.strip().split("\n\n")[-1].splitlines()[1].split(" --> ")[1]
        hours, minutes, seconds = last_end.replace(",", ".").split(":")
        assert float(seconds) + 60 * int(minutes) + 3600 * int(hours) <= DEMO_S + 0.1
        return DEMO_S  # subtitles end with the last sentence, not the audio
    if path.suffix == ".html":
        assert text.startswith("<!DOCTYPE html>") and text.rstrip().endswith("</html>")
        return DEMO_S
    if path.suffix == ".svg":
        root = ElementTree.fromstring(text)
        assert root.tag.endswith("svg")
        return float(text.split('dur="', 1)[1].split("s", 1)[0])
    raise AssertionError(path)


def stray_files(folder):
    """What is there besides the good outputs and their digests (which a failed job never leaves)."""
    expected = set(GOOD) | {os.path.basename(batch.digest_path(name)) for name in GOOD}
    return sorted(path.name for path in folder.iterdir() if path.name not in expected)


def test_a_manifest_on_a_cluster_survives_a_killed_worker_and_skips_on_rerun(tmp_path, cluster):
    address, client, workers = cluster
    manifest = write_manifest(tmp_path)
    jobs = batch.read_manifest(str(manifest))
    killed = {}

    def kill_a_busy_worker(result):
        # After the first job, kill a worker that is running a job: that job must run again elsewhere.
        if killed:
            return
        for _ in range(200):
            busy = {address: keys for address, keys in client.processing().items() if keys}
            if busy:
                break
            time.sleep(0.01)
        assert busy, "no worker had a job to lose"
        worker_address, keys = next(iter(busy.items()))
        name = client.scheduler_info()["workers"][worker_address]["name"]
        process = workers[["worker-a", "worker-b"].index(name)]
        os.kill(process.pid, signal.SIGKILL)
        process.wait(timeout=10)
        killed.update(pid=process.pid, keys=list(keys))

    results = batch.run(jobs, scheduler=address, on_result=kill_a_busy_worker)

    assert killed, "no worker was killed"
    by_output = {pathlib.Path(result.job.output).name: result for result in results}
    assert [result.job.row for result in results] == list(range(2, 2 + len(jobs)))
    for name, seconds in GOOD.items():
        result = by_output[name]
        assert (result.status, result.message) == ("done", ""), name
        path = tmp_path / "out" / name
        assert result.output_size == path.stat().st_size
        assert duration_of(path) == pytest.approx(seconds, abs=0.15), name
    lost = [int(key.split("-")[2]) for key in killed["keys"]]  # run() names a job's task talkface-job-INDEX-...
    for index in lost:
        assert results[index].worker and not results[index].worker.endswith(f":{killed['pid']}")
    for name, words in BROKEN.items():
        result = by_output[name]
        assert result.status == "failed", name
        assert words in result.message, result.message
        assert result.job.where() == f"{manifest}:{result.job.row}"
    assert stray_files(tmp_path / "out") == []

    # Again, as a user runs it: every good output is up to date, the broken rows fail again.
    report = tmp_path / "report.jsonl"
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    rerun = subprocess.run([sys.executable, "-m", "talkface", "batch", str(manifest), "--scheduler", address,
                            "--report", str(report)], capture_output=True, text=True, timeout=120, env=environment)
    assert rerun.returncode == 1, rerun.stderr
    assert f"{len(jobs)} jobs: 0 done, {len(GOOD)} skipped" in rerun.stderr
    assert f"{len(BROKEN)} failed" in rerun.stderr
    for result in by_output.values():
        if result.status == "failed":
            assert f"{manifest}:{result.job.row}: failed" in rerun.stderr
    lines = [json.loads(line) for line in report.read_text(encoding="utf-8").splitlines()]
    assert [line["row"] for line in lines] == list(range(2, 2 + len(jobs)))
    for line in lines:
        name = pathlib.Path(line["output"]).name
        assert line["status"] == ("skipped" if name in GOOD else "failed")
        assert set(line) >= {"row", "status", "seconds", "output_size", "message"}
        assert (line["output_size"] > 0) == (name in GOOD)
    assert stray_files(tmp_path / "out") == []

    # Cancelled: a quick job, then two videos that take 10-40 s each here; on_result stops run()
    # after the quick one. The running videos must stop and write nothing.
    videos = tmp_path / "videos.csv"
    videos.write_text("audio,transcript,output\n"
                      f"{CLIPS}/one_sentence.wav,{CLIPS}/one_sentence.txt,cancel/quick.srt\n"
                      f"{DEMO}/demo.ogg,{DEMO}/demo.txt,cancel/a.mp4\n"
                      f"{DEMO}/demo.ogg,{DEMO}/demo.txt,cancel/b.webm\n", encoding="utf-8")

    class Stop(Exception):
        pass

    def stop_after_the_first(result):
        raise Stop()

    with pytest.raises(Stop):
        batch.run(batch.read_manifest(str(videos)), scheduler=address, on_result=stop_after_the_first)
    deadline = time.monotonic() + 20
    while any(client.run(lambda dask_worker: len(dask_worker.state.executing)).values()):
        assert time.monotonic() < deadline, "a cancelled job went on running"
        time.sleep(0.2)
    assert sorted(path.name for path in (tmp_path / "cancel").iterdir()) == [".quick.srt.talkface-job", "quick.srt"]


