#!/usr/bin/env python3
"""Batch jobs on Dask (issue 18): jobs per minute with 1 and 2 local worker processes, measured in
one run, their ratio, and the scheduler's overhead per job beside a job's own time; the machine's
load during each phase, since others share it.

The jobs are audio-book pages (.html, the audiobook app) of the bundled speech looped to --loops
times its 13 s (ffmpeg), each with its own seed; the same jobs run serially in this process first
(a job's own time), then on a local cluster of 1 worker, then of 2 (each timed from the first
submit to the last result; starting the cluster is timed apart). A Dask task that does nothing
gives the scheduler's round trip alone. One video job (.mp4, 1280x720 at 30 fps) of the bundled
speech gives a video's own time per second of speech, for the estimate in docs/batch.md.

usage: PYTHONPATH=build/python /usr/bin/python3 bench/batch_bench.py OUT_DIR [--jobs N] [--loops N]
(needs python3-distributed and ffmpeg: cmake/install-deps.sh test; about 1-2 minutes on 2 cores)
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

import distributed
import psutil

import talkface
import talkface.batch as batch

HERE = os.path.dirname(os.path.abspath(__file__))
SPEECH = os.path.join(HERE, "..", "samples", "speech")
IDLE_S = 3.0


class Load:
    """The machine's busy share of its cores during a phase, and the part of it this run's
    processes (this one and its children, the workers) took."""

    def __init__(self):
        self.start_s = time.monotonic()
        self.busy_start = self.machine_busy_s()
        self.ours_start = self.our_cpu_s()
        self.load_start = os.getloadavg()[0]

    @staticmethod
    def machine_busy_s():
        times = psutil.cpu_times()
        return times.user + times.nice + times.system + times.irq + times.softirq + times.steal

    @staticmethod
    def our_cpu_s():
        me = psutil.Process()
        total = 0.0
        for process in [me] + me.children(recursive=True):
            try:
                times = process.cpu_times()
                total += times.user + times.system + times.children_user + times.children_system
            except psutil.NoSuchProcess:
                pass
        return total

    def stop(self):
        """Ends the phase: returns (this run's CPU seconds in it, a line describing the load)."""
        wall_s = time.monotonic() - self.start_s
        cores = psutil.cpu_count()
        busy = (self.machine_busy_s() - self.busy_start) / wall_s / cores
        ours_s = self.our_cpu_s() - self.ours_start
        ours = ours_s / wall_s / cores
        return ours_s, (f"machine busy {100 * busy:.0f}% of {cores} cores (this run {100 * ours:.0f}%, others "
                        f"{100 * max(busy - ours, 0):.0f}%), load average {self.load_start:.1f} -> "
                        f"{os.getloadavg()[0]:.1f}")

    def text(self):
        return self.stop()[1]


def looped_speech(out_dir, loops):
    audio = os.path.join(out_dir, f"speech_x{loops}.flac")
    transcript = os.path.join(out_dir, f"speech_x{loops}.txt")
    if not os.path.exists(audio):
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-stream_loop", str(loops - 1), "-i",
                        os.path.join(SPEECH, "demo.ogg"), "-ac", "1", "-ar", "16000", audio], check=True)
    with open(os.path.join(SPEECH, "demo.txt"), encoding="utf-8") as demo:
        text = demo.read()
    with open(transcript, "w", encoding="utf-8") as out:
        out.write(text * loops)
    return audio, transcript


def on_cluster(jobs, workers):
    start = time.monotonic()
    with batch.local_cluster(workers) as cluster, distributed.Client(cluster) as client:
        started_s = time.monotonic() - start
        client.submit(sum, [0]).result()  # the workers are up and have imported what a task needs
        idle = Load()
        time.sleep(IDLE_S)
        idle_share = idle.stop()[0] / IDLE_S  # cores the waiting cluster keeps busy (event loops, heartbeats)
        load = Load()
        begin = time.monotonic()
        results = batch.run(jobs, scheduler=client, force=True)
        wall_s = time.monotonic() - begin
        cpu_s, load_text = load.stop()
        begin = time.monotonic()
        empty = client.map(int, range(len(jobs) * 4), pure=False)
        client.gather(empty)
        empty_s = (time.monotonic() - begin) / len(empty)
    assert all(result.status == "done" for result in results), [r.message for r in results if r.message]
    return started_s, wall_s, results, empty_s, cpu_s - idle_share * wall_s, idle_share, load_text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out_dir")
    parser.add_argument("--jobs", type=int, default=16)
    parser.add_argument("--loops", type=int, default=10, help="the bundled 13 s speech looped this many times")
    options = parser.parse_args()
    os.makedirs(options.out_dir, exist_ok=True)
    audio, transcript = looped_speech(options.out_dir, options.loops)
    speech_s = talkface.audio_duration_s(audio)
    jobs = [batch.Job(audio, transcript, os.path.join(options.out_dir, "pages", f"page{k:03d}.html"), app="audiobook",
                      seed=k) for k in range(options.jobs)]
    print(f"talkface {talkface.__version__}, Dask distributed {distributed.__version__}, {psutil.cpu_count()} cores; "
          f"{len(jobs)} audiobook pages of {speech_s:.1f} s of speech each")

    load = Load()
    serial = [batch.run_job(job, force=True) for job in jobs]
    own_s = [result.seconds for result in serial]
    assert all(result.status == "done" for result in serial)
    cpu_s, load_text = load.stop()
    serial_cpu_s = cpu_s / len(jobs)
    print(f"\nserial, in this process: a job's own time median {statistics.median(own_s):.3f} s, "
          f"mean {statistics.mean(own_s):.3f} s; CPU {cpu_s / len(jobs):.3f} s a job "
          f"({cpu_s / len(jobs) / speech_s * 1000:.1f} ms per second of speech); {load_text}")

    rows = []
    for workers in (1, 2):
        started_s, wall_s, results, empty_s, cpu_s, idle_share, load_text = on_cluster(jobs, workers)
        worker_own_s = statistics.mean(result.seconds for result in results)
        rows.append((workers, started_s, wall_s, worker_own_s, empty_s, cpu_s, idle_share, load_text))

    print("\n| workers | cluster start | wall, all jobs | jobs per minute | job's own time on a worker | "
          "overhead per job | empty task round trip | CPU per job | idle cluster's CPU |")
    print("|---|---|---|---|---|---|---|---|---|")
    for workers, started_s, wall_s, worker_own_s, empty_s, cpu_s, idle_share, _ in rows:
        per_job_s = wall_s * workers / len(jobs)
        print(f"| {workers} | {started_s:.1f} s | {wall_s:.2f} s | {60 * len(jobs) / wall_s:.0f} | "
              f"{worker_own_s * 1000:.0f} ms | {(per_job_s - worker_own_s) * 1000:.0f} ms | {empty_s * 1000:.1f} ms | "
              f"{cpu_s / len(jobs) * 1000:.0f} ms | {100 * idle_share:.0f}% of a core |")
    ratio = rows[0][2] / rows[1][2]
    print(f"\n2 workers / 1 worker, jobs per minute: {ratio:.2f}x (measured)")
    # Under contention this run gets a share of the cores whatever its worker count (Linux gives each
    # session, not each process, its share: sched_autogroup), so the CPU a job takes (less what the
    # idle cluster burns meanwhile) tells what Dask costs as workers are added: 2 x its ratio is
    # the speed-up two free cores would give.
    print(f"CPU per job, the idle cluster's share taken out: serial {serial_cpu_s * 1000:.0f} ms, 1 worker "
          f"{rows[0][5] / len(jobs) * 1000:.0f} ms, 2 workers {rows[1][5] / len(jobs) * 1000:.0f} ms; on 2 free cores "
          f"2 workers would make {2 * rows[0][5] / rows[1][5]:.2f}x the jobs per minute of 1")
    for workers, *_, load_text in rows:
        print(f"load while {workers} worker{'s' if workers > 1 else ''} ran: {load_text}")

    load = Load()
    video = batch.run_job(batch.Job(os.path.join(SPEECH, "demo.ogg"), os.path.join(SPEECH, "demo.txt"),
                                    os.path.join(options.out_dir, "video.mp4")), force=True)
    assert video.status == "done", video.message
    demo_s = talkface.audio_duration_s(os.path.join(SPEECH, "demo.ogg"))
    cpu_s, load_text = load.stop()
    print(f"\none video job (.mp4 1280x720, 30 fps) of {demo_s:.1f} s: {video.seconds:.1f} s, CPU {cpu_s:.1f} s "
          f"({cpu_s / demo_s:.2f} CPU-s per second of speech); {load_text}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
