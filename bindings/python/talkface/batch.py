"""Batch jobs: many speeches made into pages, videos, key frames or exports, on a Dask cluster.

A job is one row of a CSV manifest (read_manifest) or a Job built in Python: a speech, its
transcript and an output whose extension picks what is made. run() spreads jobs over a Dask
cluster (a local one by default) and returns a JobResult per job; run_job() is the work of one job,
for callers who bring another engine (Ray, Spark, a process pool)::

    import talkface.batch
    jobs = talkface.batch.read_manifest("chapters.csv")
    results = talkface.batch.run(jobs, workers=8)
    failed = [result for result in results if result.status == "failed"]

Outputs are written whole or not at all (a temporary file beside the output, renamed), a job done
before with the same inputs and options is skipped unless force is set (job_digest, kept beside
the output), and a failed job does not stop the others. Nothing here prints. docs/batch.md has the manifest's columns and the cluster setups.
"""

from __future__ import annotations

import csv
import dataclasses
import glob
import hashlib
import json
import os
import socket
import time
from typing import Callable, Iterable, List, Optional, Sequence

import talkface

__all__ = [
    "Job",
    "JobResult",
    "MANIFEST_COLUMNS",
    "job_digest",
    "job_kind",
    "local_cluster",
    "read_manifest",
    "run",
    "run_job",
]

#: The manifest's columns: the first three are required.
MANIFEST_COLUMNS = ("audio", "transcript", "output", "face", "app", "style", "seed", "timing")

_PAGE_SUFFIXES = (".html", ".htm")
_VIDEO_FORMATS = ("mp4", "webm", "webp", "gif")
_PAGE_APPS = ("plain", "announcer", "audiobook")
_VIDEO_APPS = ("announcer", "plain")
_NAMED_STYLES = ("normal", "announcer")
_MAX_SEED = 2**64 - 1


@dataclasses.dataclass(frozen=True)
class Job:
    """One job: what to read and what to write. Paths are absolute or relative to the working folder.

    Attributes:
        audio: the speech (any format SpeechAligner.align_file reads).
        transcript: its transcript, UTF-8.
        output: what to write; its extension picks the job (job_kind).
        face: a face model file; "" for the built-in face.
        app: pages: plain, announcer or audiobook (default plain); videos: announcer or plain
            (default announcer); "" for the default.
        style: normal, announcer, or an expression style file (JSON).
        seed: seed of the simulated blinks and head moves.
        timing: a timing file (TextGrid, SRT, WebVTT, JSON) used instead of aligning; "" to align.
        row: the job's line in its manifest (the header is line 1); 0 for a job built in Python.
        manifest: the manifest's path ("" for none), for messages.
    """

    audio: str
    transcript: str
    output: str
    face: str = ""
    app: str = ""
    style: str = "normal"
    seed: int = 0
    timing: str = ""
    row: int = 0
    manifest: str = ""

    def inputs(self) -> List[str]:
        """The files the job reads: audio, transcript, and face, style and timing files if given."""
        paths = [self.audio, self.transcript, self.face, self.timing]
        if self.style not in _NAMED_STYLES:
            paths.append(self.style)
        return [path for path in paths if path]

    def where(self) -> str:
        """"chapters.csv:12" for a manifest row, else the output's path: names the job in messages."""
        return f"{self.manifest}:{self.row}" if self.manifest else self.output


@dataclasses.dataclass(frozen=True)
class JobResult:
    """What became of a job.

    Attributes:
        job: the job.
        status: "done", "skipped" (the output was made from the same inputs and options) or "failed".
        seconds: the job's own wall time on its worker (0 if it never ran).
        output_size: the output's size in bytes (0 if failed).
        message: why it failed ("" otherwise); talkface's messages name the file, line or time.
        worker: "host:pid" of the process that ran it ("" if none did).
    """

    job: Job
    status: str
    seconds: float = 0.0
    output_size: int = 0
    message: str = ""
    worker: str = ""

    def to_json_dict(self) -> dict:
        """The report's line for this job: row, status, seconds, output_size, message, the paths, worker."""
        return {
            "row": self.job.row,
            "status": self.status,
            "seconds": round(self.seconds, 3),
            "output_size": self.output_size,
            "message": self.message,
            "output": self.job.output,
            "audio": self.job.audio,
            "transcript": self.job.transcript,
            "worker": self.worker,
        }


def job_kind(output: str) -> str:
    """What an output's extension asks for: "page" (.html), "svg" (the bare SVG animation), "video"
    (.mp4 .webm .webp .gif), "keyframes" (.json: key frames and events), or "export:FORMAT" (.tsv .xml
    .dat .motion3.json .TextGrid .srt .vtt, as `talkface export` writes them).

    Raises:
        talkface.InvalidArgument: any other extension (named, with the known ones).
    """
    lower = output.lower()
    if lower.endswith(_PAGE_SUFFIXES):
        return "page"
    if lower.endswith(".svg"):
        return "svg"
    try:
        if talkface.video_format_from_path(output).name in _VIDEO_FORMATS:
            return "video"
    except talkface.InvalidArgument:
        pass
    if lower.endswith(".json") and not lower.endswith(".motion3.json"):
        return "keyframes"
    try:
        return "export:" + talkface.export_format_for_path(output)
    except talkface.InvalidArgument:
        raise _invalid_argument(
            "output",
            f'"{output}": no job makes this kind of file; the extension picks the job: .html (page), .svg '
            "(SVG animation), .mp4 .webm .webp .gif (video), .json (key frames), .tsv .xml .dat .motion3.json "
            ".TextGrid .srt .vtt (exports)",
        ) from None


def read_manifest(path: str) -> List[Job]:
    """The jobs of a CSV manifest: a header row naming the columns (MANIFEST_COLUMNS, any order;
    audio, transcript and output required), then one job a row. Paths are relative to the manifest's
    folder. Blank lines are skipped. Every row is checked before any job runs: the output's
    extension, app, style and seed, and that no two rows write the same output; the input files are
    not opened (a missing one fails its job only).

    Raises:
        talkface.FileError: the manifest cannot be read.
        talkface.ParseError: a malformed header or row; the message starts "PATH:LINE:" and names
            the column (also in .path, .line and .item).
    """
    try:
        with open(path, "rb") as manifest:
            data = manifest.read()
    except OSError as error:
        raise _file_error(path, f"{path}: cannot read the manifest: {error.strerror or error}") from None
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise _parse_error(path, data[: error.start].count(b"\n") + 1, "", "not UTF-8 text") from None
    folder = os.path.dirname(os.path.abspath(path))
    reader = csv.reader(text.splitlines(keepends=True), strict=True)
    columns: Optional[List[str]] = None
    jobs: List[Job] = []
    output_rows: dict = {}
    next_line = 1
    while True:
        line = next_line
        try:
            fields = next(reader)
        except StopIteration:
            break
        except csv.Error as error:
            raise _parse_error(path, reader.line_num, "", f"not CSV: {error}") from None
        next_line = reader.line_num + 1
        if not any(field.strip() for field in fields):
            continue
        if columns is None:
            columns = _read_header(path, line, fields)
            continue
        job = _read_row(path, line, folder, columns, fields)
        if job.output in output_rows:
            raise _parse_error(path, line, "output",
                               f'"{job.output}" is also the output of line {output_rows[job.output]}')
        output_rows[job.output] = line
        jobs.append(job)
    if columns is None:
        raise _parse_error(path, 1, "", "empty: expected a header row (audio,transcript,output,...)")
    return jobs


def run_job(job: Job, force: bool = False,
            progress: Optional[Callable[[float, str], Optional[bool]]] = None) -> JobResult:
    """Does one job in this process and says how it went; never raises for a failed job.

    Skips the job ("skipped") if its output was made from the same inputs and options (is_up_to_date),
    unless force. Otherwise
    aligns the speech (or times it by job.timing), animates the face and writes the output through
    a temporary file beside it that is renamed: a failure, a cancel or a killed process leaves no
    output (a killed process's temporary file, OUTPUT.tmp-XXXXXX, is removed when the job runs
    again). The output's folder is created if missing. The job's digest (job_digest) is written
    beside the output once the output is whole.

    This is the function to call from another engine (Ray, Spark, multiprocessing): it reads its
    inputs and writes its output itself and returns a picklable JobResult. Thread-safe.

    Args:
        job: what to do.
        force: redo the job even if its output is up to date.
        progress: progress(fraction, stage) during the long steps; returning False cancels (the
            result is then "failed" with a message saying so).
    """
    start = time.monotonic()
    worker = f"{socket.gethostname()}:{os.getpid()}"
    try:
        remove_temporary_files(job.output)
        # Taken before the work: an input changed while the job reads it makes the next run redo it.
        digest = job_digest(job)
        if not force and _kept_digest(job.output) == digest and os.path.exists(job.output):
            return JobResult(job, "skipped", time.monotonic() - start, os.stat(job.output).st_size, "", worker)
        folder = os.path.dirname(job.output)
        if folder:
            os.makedirs(folder, exist_ok=True)
        _make_output(job, progress)
        _write_atomically(digest_path(job.output), digest + "\n")
        size = os.stat(job.output).st_size
        return JobResult(job, "done", time.monotonic() - start, size, "", worker)
    except talkface.Error as error:
        message = str(error)
    except OSError as error:
        message = f"{error.filename}: {error.strerror}" if error.filename else str(error)
    except Exception as error:  # a bug must not stop the other jobs; the report carries it
        message = f"internal error (a bug in talkface): {type(error).__name__}: {error}"
    return JobResult(job, "failed", time.monotonic() - start, 0, message, worker)


def is_up_to_date(job: Job) -> bool:
    """True if the output exists and the digest kept beside it is the job's digest now (job_digest):
    made by this talkface from inputs of the same contents with the same options. False if an
    input cannot be read (the job then fails and says why)."""
    try:
        return os.path.exists(job.output) and _kept_digest(job.output) == job_digest(job)
    except OSError:
        return False


def job_digest(job: Job) -> str:
    """SHA-256 (hex) of what a job's output depends on: talkface's version, the kind of output, the
    options that apply to it (app, named style, seed) and the contents of its input files (audio,
    transcript, and face, style and timing files if given). Not file times, nor paths: an input
    edited with an old time counts as changed; the same files moved or touched do not.

    Raises:
        OSError: an input cannot be read.
    """
    kind = job_kind(job.output)
    options = {"talkface": talkface.__version__, "kind": kind, "seed": job.seed}
    if kind == "page":
        options["app"] = job.app or "plain"
    elif kind == "video":
        options["app"] = job.app or "announcer"
    files = {"audio": job.audio, "transcript": job.transcript, "timing": job.timing}
    if not kind.startswith("export:"):  # an export's timing does not depend on the face
        files["face"] = job.face
    if job.style in _NAMED_STYLES:
        options["style"] = job.style
    else:
        files["style"] = job.style
    digest = hashlib.sha256(json.dumps(options, sort_keys=True).encode())
    for name, path in sorted(files.items()):
        if not path:
            digest.update(f"\0{name}\0none\0".encode())
            continue
        with open(path, "rb") as file:
            # The length first: no file's bytes can pass for the next file's name.
            digest.update(f"\0{name}\0{os.fstat(file.fileno()).st_size}\0".encode())
            for block in iter(lambda: file.read(1 << 20), b""):
                digest.update(block)
    return digest.hexdigest()


def digest_path(output: str) -> str:
    """Where the digest of the job that made `output` is kept: .NAME.talkface-job beside it (hidden,
    so that a folder of outputs published as it is carries no clutter)."""
    folder, name = os.path.split(output)
    return os.path.join(folder, f".{name}.talkface-job")


def _kept_digest(output: str) -> str:
    try:
        with open(digest_path(output), encoding="ascii") as file:
            return file.read().strip()
    except (OSError, UnicodeDecodeError):
        return ""


def remove_temporary_files(output: str) -> None:
    """Removes the temporary files (OUTPUT.tmp-XXXXXX, and its digest's) a killed writer of `output`
    left behind."""
    for path in glob.glob(glob.escape(output) + ".tmp-*") + glob.glob(glob.escape(digest_path(output)) + ".tmp-*"):
        try:
            os.remove(path)
        except FileNotFoundError:
            pass


def run(jobs: Iterable[Job], scheduler=None, workers: Optional[int] = None,
        on_result: Optional[Callable[[JobResult], None]] = None, retries: Optional[int] = None,
        force: bool = False) -> List[JobResult]:
    """Runs jobs on a Dask cluster and returns their results in the order of `jobs`.

    Args:
        jobs: the jobs (read_manifest() or Job(...)).
        scheduler: None starts a local cluster of `workers` single-threaded worker processes for the
            call; a scheduler address ("tcp://host:8786") connects to that cluster; a
            distributed.Client uses the caller's client (left open).
        workers: the local cluster's worker processes (default: the machine's cores). Only with
            scheduler None.
        on_result: called with each JobResult as its job finishes, on the calling thread.
        retries: how many times a job runs again when the worker running it dies (default: Dask's
            distributed.scheduler.allowed-failures, 3). Only with scheduler None: a running
            scheduler has its own setting.
        force: redo jobs whose outputs are up to date.

    A job that keeps killing its workers fails with a message saying so; every other failure is
    the job's own (JobResult.message). If run() is interrupted (or on_result raises), the jobs not
    started are cancelled and the running ones stop at their next progress report (within a
    frame of a video, a moment of an alignment), leaving no output; temporary files of jobs cut
    short are removed before returning, for outputs this machine can see.

    Raises:
        ImportError: Dask's distributed is not installed (Debian: python3-distributed).
        ValueError: workers or retries given with a scheduler, or out of range.
        OSError: the scheduler cannot be reached (named in the message).
    """
    import distributed

    jobs = list(jobs)
    if scheduler is not None and (workers is not None or retries is not None):
        raise _invalid_argument(
            "workers" if workers is not None else "retries",
            "applies to the local cluster only; a running scheduler has its own workers and "
            "distributed.scheduler.allowed-failures")
    cluster = None
    client = None
    futures = []
    try:
        if isinstance(scheduler, distributed.Client):
            client = scheduler
        elif scheduler is None:
            cluster = local_cluster(workers, retries)
            client = distributed.Client(cluster)
        else:
            client = _connect(distributed, str(scheduler))
        results: List[Optional[JobResult]] = [None] * len(jobs)
        index_of = {}
        for index, job in enumerate(jobs):
            # Up to date is decided here, once, not on the worker: a worker that dies after writing
            # its output but before reporting gets its job run again, and that run must redo the
            # job, not report the dead worker's output as skipped.
            if not force and is_up_to_date(job):
                results[index] = JobResult(job, "skipped", 0.0, os.stat(job.output).st_size)
                if on_result is not None:
                    on_result(results[index])
                continue
            # pure=False: the same job submitted twice (a second run) must run again, not be looked up.
            future = client.submit(_run_on_dask_worker, job, pure=False,
                                   key=f"talkface-job-{index}-{os.urandom(6).hex()}")
            index_of[future.key] = index
            futures.append(future)
        for future in distributed.as_completed(futures):
            index = index_of[future.key]
            results[index] = _result_of(future, jobs[index])
            future.release()
            if on_result is not None:
                on_result(results[index])
        return results
    finally:
        if client is not None and futures:
            client.cancel([future for future in futures if not future.done()])
        if client is not None and client is not scheduler:
            client.close()
        if cluster is not None:
            cluster.close()
        for job in jobs:
            remove_temporary_files(job.output)


def _run_on_dask_worker(job: Job) -> JobResult:
    # Dask cannot stop a running task: when run() cancels its futures (interrupted, or on_result
    # raised), the worker marks the running task cancelled, and the job's next progress report
    # sees it and stops the work, which removes its temporary file.
    import distributed

    worker = distributed.get_worker()
    key = worker.get_current_task()

    def is_wanted(fraction: float, stage: str) -> bool:
        task = worker.state.tasks.get(key)
        return task is not None and task.state != "cancelled"

    return run_job(job, True, is_wanted)


def _result_of(future, job: Job) -> JobResult:
    try:
        return future.result()
    except Exception as error:  # the job never finished: its workers died, or the cluster cancelled it
        from distributed.scheduler import KilledWorker

        if isinstance(error, KilledWorker):
            message = (f"the worker running it died each time it was tried ({error.allowed_failures + 1} "
                       "times); the job may need more memory than a worker has")
        else:
            message = f"the cluster did not finish it: {type(error).__name__}: {error}"
        return JobResult(job, "failed", 0.0, 0, message, "")


def local_cluster(workers: Optional[int] = None, retries: Optional[int] = None):
    """The local Dask cluster run() starts when given no scheduler, for callers who keep one across
    several run() calls (pass distributed.Client(cluster) as the scheduler; close both after).

    Args:
        workers: single-threaded worker processes (default: the machine's cores).
        retries: how many times a job runs again when its worker dies (default: Dask's, 3).

    Example:
        >>> with talkface.batch.local_cluster(2) as cluster, distributed.Client(cluster) as client:
        ...     results = talkface.batch.run(jobs, scheduler=client)
    """
    import dask
    import distributed

    if workers is not None and workers < 1:
        raise _invalid_argument("workers", f"expected 1 or more, found {workers}")
    if retries is not None and retries < 0:
        raise _invalid_argument("retries", f"expected 0 or more, found {retries}")
    # The workers' statistical profiler samples every thread 100 times a second: CPU taken from
    # the jobs, for a dashboard nobody opens here.
    settings = {"distributed.worker.profile.enabled": False}
    if retries is not None:
        settings["distributed.scheduler.allowed-failures"] = retries
    # One thread a worker: one job fits one core, and processes keep jobs' memory apart. Only on
    # the loopback interface, and no dashboard: it would take a port the caller did not ask for.
    with dask.config.set(settings):
        return distributed.LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                        processes=True, dashboard_address=None, host="127.0.0.1")


def _connect(distributed, address: str):
    try:
        return distributed.Client(address, timeout="20s")
    except (OSError, TimeoutError) as error:
        raise OSError(f"cannot reach the Dask scheduler at {address}: {error}") from None


def _make_output(job: Job, progress) -> None:
    kind = job_kind(job.output)
    style = (talkface.ExpressionStyle.from_name(job.style) if job.style in _NAMED_STYLES
             else talkface.ExpressionStyle.load(job.style))
    face = talkface.FaceModel.load(job.face) if job.face else talkface.FaceModel.default()
    # What the commands do: the video's frame rate is the video's (30), the rest the lip sync's (25).
    fps = talkface.VideoOptions().fps if kind == "video" else talkface.LipSyncOptions().fps
    video_options = None
    if kind == "video":
        layout = talkface.FrameLayout.face if (job.app or "announcer") == "plain" else talkface.FrameLayout.announcer
        video_options = talkface.FaceVideoOptions(video=talkface.VideoOptions(fps=fps), layout=layout)
        talkface.check_video_options(job.output, video_options.video)  # before the slow part
    transcript = talkface.load_transcript(job.transcript)
    if job.timing:
        timeline = talkface.time_transcript(job.timing, job.audio, transcript)
    else:
        timeline = talkface.SpeechAligner().align_file(job.audio, transcript, progress=_part(progress, 0.0, 0.8))
    simulator = talkface.ExpressionSimulator(timeline, job.seed, style)
    if kind.startswith("export:"):
        face = talkface.FaceModel.default()  # as `talkface export`: the timing does not depend on the face
    animation = talkface.animate(face, timeline, simulator, talkface.LipSyncOptions(fps=fps))
    if kind == "page":
        options = talkface.WebPageOptions(app=talkface.WebPageApp.__members__[job.app or "plain"])
        talkface.write_web_page(job.output, talkface.SvgAnimator(face), animation, timeline, job.audio, options)
    elif kind == "svg":
        talkface.SvgAnimator(face).write_animation_svg(job.output, animation)
    elif kind == "video":
        talkface.render_video(job.output, face, animation, job.audio, video_options,
                              progress=_part(progress, 0.8, 1.0))
    elif kind == "keyframes":
        _write_atomically(job.output, animation.key_frames_json())
    else:
        talkface.export_to_file(job.output, timeline, animation, kind[len("export:"):], job.audio)


def _part(progress, start: float, end: float):
    if progress is None:
        return None
    return lambda fraction, stage: progress(start + (end - start) * fraction, stage)


def _write_atomically(path: str, text: str) -> None:
    # The library's pattern (OUTPUT.tmp-XXXXXX), so that remove_temporary_files() finds it too.
    import tempfile

    folder = os.path.dirname(path) or "."
    descriptor, temporary = tempfile.mkstemp(prefix=os.path.basename(path) + ".tmp-", dir=folder)
    try:
        with os.fdopen(descriptor, "w", encoding="utf-8", newline="") as file:
            file.write(text)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        try:
            os.remove(temporary)
        except FileNotFoundError:
            pass
        raise


def _read_header(path: str, line: int, fields: Sequence[str]) -> List[str]:
    columns = [field.strip() for field in fields]
    for column in columns:
        if column not in MANIFEST_COLUMNS:
            raise _parse_error(path, line, column,
                               f'unknown column "{column}"; the columns are {", ".join(MANIFEST_COLUMNS)}')
        if columns.count(column) > 1:
            raise _parse_error(path, line, column, f'column "{column}" appears twice')
    for column in MANIFEST_COLUMNS[:3]:
        if column not in columns:
            raise _parse_error(path, line, column,
                               f'the header has no "{column}" column (audio, transcript and output are required)')
    return columns


def _read_row(path: str, line: int, folder: str, columns: List[str], fields: Sequence[str]) -> Job:
    if len(fields) != len(columns):
        raise _parse_error(path, line, "", f"{len(fields)} fields, but the header names {len(columns)} columns")
    values = {column: field.strip() for column, field in zip(columns, fields)}

    def resolved(column: str) -> str:
        value = values.get(column, "")
        return os.path.normpath(os.path.join(folder, value)) if value else ""

    for column in MANIFEST_COLUMNS[:3]:
        if not values[column]:
            raise _parse_error(path, line, column, f'"{column}" is empty')
    output = resolved("output")
    try:
        kind = job_kind(output)
    except talkface.InvalidArgument as error:
        raise _parse_error(path, line, "output", str(error).split(": ", 1)[-1]) from None
    app = values.get("app", "")
    if app:
        allowed = _PAGE_APPS if kind == "page" else _VIDEO_APPS if kind == "video" else ()
        if app not in allowed:
            where = f"a {kind} takes {', '.join(allowed)}" if allowed else "only pages and videos take an app"
            raise _parse_error(path, line, "app", f'"{app}": {where}')
    style = values.get("style", "") or "normal"
    if style not in _NAMED_STYLES:
        style = resolved("style")
    seed_text = values.get("seed", "") or "0"
    if not seed_text.isdigit() or int(seed_text) > _MAX_SEED:
        raise _parse_error(path, line, "seed", f'expected a whole number from 0 to 2^64-1, found "{seed_text}"')
    return Job(audio=resolved("audio"), transcript=resolved("transcript"), output=output, face=resolved("face"),
               app=app, style=style, seed=int(seed_text), timing=resolved("timing"), row=line, manifest=path)


def _parse_error(path: str, line: int, item: str, problem: str) -> "talkface.ParseError":
    error = talkface.ParseError(f"{path}:{line}: " + (f"column {item}: " if item else "") + problem)
    error.path, error.line, error.column, error.item = path, line, 0, item
    error.code = talkface.ErrorCode.parse
    return error


def _file_error(path: str, message: str) -> "talkface.FileError":
    error = talkface.FileError(message)
    error.filename = path
    error.code = talkface.ErrorCode.file
    return error


def _invalid_argument(parameter: str, problem: str) -> "talkface.InvalidArgument":
    error = talkface.InvalidArgument(f"{parameter}: {problem}")
    error.parameter = parameter
    error.code = talkface.ErrorCode.invalid_argument
    return error
