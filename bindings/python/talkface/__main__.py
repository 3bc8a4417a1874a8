"""`python3 -m talkface batch MANIFEST`: the jobs of a CSV manifest on a Dask cluster (docs/batch.md).

Exit status: 0 every job done or skipped; 1 some job failed, or the manifest is wrong; 2 a usage
error; 130 interrupted.
"""

import argparse
import importlib
import json
import os
import sys

EXIT_FAILED = 1
EXIT_INTERRUPTED = 130


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="python3 -m talkface",
        description="talkface's Python commands.",
        epilog="exit status: 0 success; 1 some job failed or the manifest is wrong; 2 usage error; 130 interrupted",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    batch = commands.add_parser(
        "batch",
        help="run the jobs of a CSV manifest on a Dask cluster",
        description="Runs one job a row of a CSV manifest (columns audio,transcript,output and optionally "
        "face,app,style,seed,timing; paths relative to the manifest) on a Dask cluster. The output's "
        "extension picks the job: .html page, .svg animation, .mp4/.webm/.webp/.gif video, .json key frames, "
        ".tsv/.xml/.dat/.motion3.json/.TextGrid/.srt/.vtt export. Jobs whose output was made from the same "
        "inputs and options are skipped. docs/batch.md.",
        epilog="exit status: 0 every job done or skipped; 1 some job failed, or the manifest is wrong; "
        "2 usage error; 130 interrupted",
    )
    batch.add_argument("manifest", metavar="MANIFEST", help="the CSV manifest")
    batch.add_argument("--scheduler", metavar="ADDRESS",
                       help="a running Dask scheduler (tcp://host:8786); default: a local cluster for this run")
    batch.add_argument("--workers", metavar="N", type=int,
                       help="the local cluster's single-threaded worker processes (default: the cores)")
    batch.add_argument("--report", metavar="FILE",
                       help="write a JSON line per job: row, status, seconds, output_size, message, paths")
    batch.add_argument("--retries", metavar="N", type=int,
                       help="how many times a job runs again when its worker dies (local cluster; default 3)")
    batch.add_argument("--force", action="store_true", help="redo jobs whose outputs are up to date")
    batch.add_argument("-q", "--quiet", action="store_true", help="print only failures and the summary")
    options = parser.parse_args(argv)
    if options.scheduler is not None and (options.workers is not None or options.retries is not None):
        parser.error("--workers and --retries set up the local cluster; a running scheduler (--scheduler) "
                     "has its own workers and retries (docs/batch.md)")
    if options.workers is not None and options.workers < 1:
        parser.error(f"--workers: expected 1 or more, found {options.workers}")
    if options.retries is not None and options.retries < 0:
        parser.error(f"--retries: expected 0 or more, found {options.retries}")
    return options


class Progress:
    """A bar redrawn as jobs finish on a terminal, else one line per job; failures always in full."""

    def __init__(self, total, stream, quiet):
        self.total = total
        self.stream = stream
        self.quiet = quiet
        self.is_terminal = stream.isatty()
        self.counts = {"done": 0, "skipped": 0, "failed": 0}

    def __call__(self, result):
        self.counts[result.status] += 1
        if self.is_terminal:
            self.stream.write("\r\033[K")
        count = f"{self.finished()}/{self.total}"
        if result.status == "failed":
            self.stream.write(f"talkface: {count} {failure_text(result)}\n")
        elif not self.is_terminal and not self.quiet:
            self.stream.write(f"talkface: {count} {result.job.where()}: {result.status} {result.job.output} "
                              f"({result.seconds:.1f} s, {size_text(result.output_size)})\n")
        if self.is_terminal and not self.quiet:
            self.draw_bar()
        self.stream.flush()

    def finished(self):
        return sum(self.counts.values())

    def draw_bar(self):
        width = 30
        filled = width * self.finished() // max(self.total, 1)
        self.stream.write(f"[{'#' * filled}{'.' * (width - filled)}] {self.finished()}/{self.total} jobs: "
                          f"{self.counts['done']} done, {self.counts['skipped']} skipped, "
                          f"{self.counts['failed']} failed")

    def close(self):
        if self.is_terminal and not self.quiet:
            self.stream.write("\n")
            self.stream.flush()


def failure_text(result):
    job = result.job
    message = result.message.replace("\n", "\n  ")
    return f"{job.where()}: failed: {job.audio} + {job.transcript} -> {job.output}:\n  {message}"


def size_text(size):
    return f"{size} bytes" if size < 10_000 else f"{size / 1000:.0f} kB" if size < 10_000_000 else f"{size / 1e6:.0f} MB"


def write_report(path, results):
    # Whole or not at all, like every output.
    import tempfile

    folder = os.path.dirname(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(prefix=os.path.basename(path) + ".tmp-", dir=folder)
    try:
        with os.fdopen(descriptor, "w", encoding="utf-8") as report:
            for result in results:
                report.write(json.dumps(result.to_json_dict(), ensure_ascii=False) + "\n")
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        os.remove(temporary)
        raise


def run_batch(options):
    import logging

    import talkface
    import talkface.batch

    try:
        importlib.import_module("distributed")
    except ImportError as error:
        print(f"talkface: error: batch jobs need Dask's distributed (Debian: python3-distributed): {error}",
              file=sys.stderr)
        return EXIT_FAILED
    # Dask warns of each worker it kills when the local cluster closes, as it must on a busy
    # machine; the command reports every job itself.
    logging.getLogger("distributed").setLevel(logging.ERROR)
    try:
        jobs = talkface.batch.read_manifest(options.manifest)
    except talkface.Error as error:
        print(f"talkface: error: {error}", file=sys.stderr)
        return EXIT_FAILED
    where = options.scheduler or f"a local cluster of {options.workers or os.cpu_count()} workers"
    if not options.quiet:
        print(f"talkface: {len(jobs)} jobs of {options.manifest} on {where}", file=sys.stderr)
    progress = Progress(len(jobs), sys.stderr, options.quiet)
    try:
        results = talkface.batch.run(jobs, scheduler=options.scheduler, workers=options.workers,
                                     on_result=progress, retries=options.retries, force=options.force)
    except (OSError, ImportError, talkface.Error) as error:
        progress.close()
        print(f"talkface: error: {error}", file=sys.stderr)
        return EXIT_FAILED
    progress.close()
    if options.report:
        write_report(options.report, results)
    counts = progress.counts
    summary = f"talkface: {len(jobs)} jobs: {counts['done']} done, {counts['skipped']} skipped"
    if counts["skipped"]:
        summary += " (made before from the same inputs and options; --force redoes them)"
    summary += f", {counts['failed']} failed"
    print(summary, file=sys.stderr)
    return EXIT_FAILED if counts["failed"] else 0


def main(argv=None):
    options = parse_arguments(sys.argv[1:] if argv is None else argv)
    try:
        return run_batch(options)
    except KeyboardInterrupt:
        print("\ntalkface: interrupted; the jobs not finished wrote nothing", file=sys.stderr)
        return EXIT_INTERRUPTED


# Guarded: Dask's worker processes are spawned and import the main module again.
if __name__ == "__main__":
    sys.exit(main())
