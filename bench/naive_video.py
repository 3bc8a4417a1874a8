"""The naive route to a video of the talking face, for bench/video_bench.sh: every frame written as
an SVG document (talkface.SvgAnimator), rasterised by rsvg-convert at 1280x720, the PNGs encoded
with the speech by the ffmpeg program (libx264 + AAC). Frames are sampled (every STEP-th one) and
the per-frame costs extrapolated to the whole speech, since running every frame would take longer
than the measurement is worth; the script says so in its output.

usage: naive_video.py SPEECH.wav TRANSCRIPT.txt WORK_DIR [--step N]
prints one line: frames, sampled, seconds per stage (extrapolated), total seconds, CPU seconds
"""
import argparse
import os
import pathlib
import resource
import subprocess
import time

import talkface


def children_cpu_s():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def self_cpu_s():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("speech")
    parser.add_argument("transcript")
    parser.add_argument("work_dir")
    parser.add_argument("--step", type=int, default=20)
    parser.add_argument("--fps", type=float, default=30.0)
    args = parser.parse_args()
    work = pathlib.Path(args.work_dir)
    (work / "frames").mkdir(parents=True, exist_ok=True)

    started, cpu_started = time.perf_counter(), self_cpu_s()
    timeline = talkface.SpeechAligner().align_file(args.speech, talkface.load_transcript(args.transcript))
    face = talkface.FaceModel.default()
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 0),
                                 talkface.LipSyncOptions(fps=args.fps))
    animator = talkface.SvgAnimator(face, talkface.SvgOptions(background="#1d3b5c"))
    align_s, align_cpu_s = time.perf_counter() - started, self_cpu_s() - cpu_started

    frames = animation.frames
    sampled = list(range(0, len(frames), args.step))
    svg_s = rsvg_s = svg_cpu_s = rsvg_cpu_s = 0.0
    for n, k in enumerate(sampled):
        t0, c0 = time.perf_counter(), self_cpu_s()
        svg_path = work / "frames" / "frame.svg"
        animator.write_svg(str(svg_path), frames[k])
        svg_s += time.perf_counter() - t0
        svg_cpu_s += self_cpu_s() - c0
        t0, c0 = time.perf_counter(), children_cpu_s()
        subprocess.run(["rsvg-convert", "-w", "1280", "-h", "720", "--keep-aspect-ratio",
                        "--background-color", "#1d3b5c", str(svg_path), "-o",
                        str(work / "frames" / f"{n:06d}.png")], check=True)
        rsvg_s += time.perf_counter() - t0
        rsvg_cpu_s += children_cpu_s() - c0
    # The sampled PNGs (the face's canvas, centred on 1280x720 by ffmpeg's pad) encoded as the
    # whole video would be, at the same settings as talkface's MP4.
    t0, c0 = time.perf_counter(), children_cpu_s()
    subprocess.run(["ffmpeg", "-nostdin", "-v", "error", "-y", "-framerate", str(args.fps), "-i",
                    str(work / "frames" / "%06d.png"), "-vf",
                    "pad=1280:720:(ow-iw)/2:(oh-ih)/2:color=0x1d3b5c,format=yuv420p",
                    "-c:v", "libx264", "-preset", "superfast", "-tune", "animation", "-crf", "20",
                    "-threads", "1", str(work / "naive.mp4")], check=True)
    encode_s, encode_cpu_s = time.perf_counter() - t0, children_cpu_s() - c0
    scale = len(frames) / len(sampled)
    total_s = align_s + (svg_s + rsvg_s + encode_s) * scale
    total_cpu_s = align_cpu_s + (svg_cpu_s + rsvg_cpu_s + encode_cpu_s) * scale
    print(f"naive: {len(frames)} frames, {len(sampled)} sampled (every {args.step}th, extrapolated x{scale:.1f}); "
          f"align {align_s:.1f} s, svg {svg_s * scale:.1f} s, rsvg-convert {rsvg_s * scale:.1f} s, "
          f"ffmpeg {encode_s * scale:.1f} s; total {total_s:.1f} s wall, {total_cpu_s:.1f} s cpu")
    print(f"naive_total_wall_s={total_s:.2f} naive_total_cpu_s={total_cpu_s:.2f}")


if __name__ == "__main__":
    main()
