"""What a browser shows of `talkface render`: headless Chromium screenshots (the module's Chromium,
tests/apps/browser.py), checked pixel by pixel.

The SVG's user space is the face's image space offset by the viewBox origin, and the window is the
SVG's own size, so a point of the document lands on pixel (x - viewBox.x, y - viewBox.y).
"""
import os
import re
import subprocess
import xml.etree.ElementTree as ET

import pytest

from browser import CHROMIUM

CLI = os.environ["TALKFACE_CLI"]
SVG_NS = "{http://www.w3.org/2000/svg}"

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")


class Rendered:
    """A rendered face: its SVG tree and its screenshot."""

    def __init__(self, chromium, tmp_path, name, *args):
        svg_path = tmp_path / f"{name}.svg"
        subprocess.run([CLI, "render", *args, "-o", str(svg_path)], check=True, timeout=60)
        self.root = ET.parse(svg_path).getroot()
        self.origin = [float(v) for v in self.root.get("viewBox").split()[:2]]
        width, height = int(self.root.get("width")), int(self.root.get("height"))
        with chromium.page(width, height) as browser:
            browser.load(svg_path.as_uri())
            self.image = browser.screenshot()
        assert self.image.size == (width, height)

    def element(self, class_name):
        return next(e for e in self.root.iter() if e.get("class") == class_name)

    def colour(self, class_name):
        hex_colour = self.element(class_name).get("fill")
        return tuple(int(hex_colour[i:i + 2], 16) for i in (1, 3, 5))

    def box(self, class_name):
        """Bounding box of an element's coordinates, in screenshot pixels."""
        element = self.element(class_name)
        numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", element.get("d") or element.get("points"))]
        xs = [x - self.origin[0] for x in numbers[0::2]]
        ys = [y - self.origin[1] for y in numbers[1::2]]
        return min(xs), min(ys), max(xs), max(ys)

    def share_of(self, colour, box, tolerance=24):
        """The share of pixels in box (left, top, right, bottom) within tolerance of colour."""
        left, top, right, bottom = (int(round(v)) for v in box)
        matching = total = 0
        for y in range(top, bottom):
            for x in range(left, right):
                pixel = self.image.getpixel((x, y))
                total += 1
                matching += all(abs(p - c) <= tolerance for p, c in zip(pixel, colour))
        return matching / max(total, 1), matching


@pytest.fixture(scope="module")
def open_mouth(chromium, tmp_path_factory):
    return Rendered(chromium, tmp_path_factory.mktemp("a"), "mouth_a", "--mouth", "a")


@pytest.fixture(scope="module")
def closed_mouth(chromium, tmp_path_factory):
    return Rendered(chromium, tmp_path_factory.mktemp("m"), "mouth_m", "--mouth", "m")


def test_skin_dominates_the_face_centre(open_mouth):
    left, top, right, bottom = open_mouth.box("face-contour")
    width, height = right - left, bottom - top
    centre = (left + 0.25 * width, top + 0.1 * height, right - 0.25 * width, bottom - 0.15 * height)
    share, _ = open_mouth.share_of(open_mouth.colour("face-contour"), centre)
    assert share > 0.5


def test_hair_colour_appears_above_the_face(open_mouth):
    hair_left, hair_top, hair_right, _ = open_mouth.box("hair")
    face_left, face_top, face_right, _ = open_mouth.box("face-contour")
    middle = (face_left + face_right) / 2
    above = (middle - 10, hair_top + 4, middle + 10, face_top - 4)
    share, _ = open_mouth.share_of(open_mouth.colour("hair"), above)
    assert share > 0.6


def test_open_mouth_shows_the_inside_and_a_closed_mouth_does_not(open_mouth, closed_mouth):
    # The dark, the upper teeth and the tongue, each the opening's outline (moved) filled.
    dark, teeth, tongue = (open_mouth.colour(part) for part in ("mouth-opening", "upper-teeth", "tongue"))
    for colour, least in ((dark, 60), (teeth, 30), (tongue, 30)):
        _, open_pixels = open_mouth.share_of(colour, open_mouth.box("lips"), tolerance=16)
        _, closed_pixels = closed_mouth.share_of(colour, closed_mouth.box("lips"), tolerance=16)
        assert open_pixels > least
        assert closed_pixels < 5
