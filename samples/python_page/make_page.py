#!/usr/bin/python3
"""A talking-face web page made end to end from Python: load the transcript, align it with the
speech, simulate blinks and head moves, animate, write the page.

    make_page.py AUDIO TRANSCRIPT OUT.html [--app plain|announcer|audiobook]
"""
import argparse
import sys

import talkface


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("audio")
    parser.add_argument("transcript")
    parser.add_argument("output")
    parser.add_argument("--app", choices=list(talkface.WebPageApp.__members__), default="plain")
    args = parser.parse_args()

    face = talkface.default_face()
    transcript = talkface.load_transcript(args.transcript)
    timeline = talkface.SpeechAligner().align_file(args.audio, transcript)
    simulator = talkface.ExpressionSimulator(timeline, seed=5)
    animation = talkface.animate(face, timeline, simulator)
    options = talkface.WebPageOptions(app=talkface.WebPageApp.__members__[args.app], title="talkface from Python")
    talkface.write_web_page(args.output, talkface.SvgAnimator(face), animation, timeline, args.audio, options)
    print(f"wrote {args.output}: {len(animation)} frames, {len(timeline.sentences)} sentences")


if __name__ == "__main__":
    try:
        main()
    except talkface.Error as error:
        sys.exit(f"make_page.py: {error}")
