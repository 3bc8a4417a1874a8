"""How open the built-in face's mouth is in a picture of it (a page's screenshot, a video's frame): the
pixels of the mouth's inside colours within the lips' box, for the page and the video tests."""

# What an open mouth shows inside the lips on the built-in face: the dark (FaceColors::mouth_inside),
# the upper and lower teeth and the tongue (src/render/face_drawing.cpp's paints).
LIPS = (0xC8, 0x5A, 0x5A)
MOUTH_INSIDE = ((0x6A, 0x1E, 0x22), (0xFA, 0xF7, 0xF0), (0xE9, 0xDD, 0xD7), (0xDF, 0x7D, 0x84))


def is_near(pixel, colour, tolerance):
    return all(abs(p - c) <= tolerance for p, c in zip(pixel, colour))


def mouth_inside_pixels(image, tolerance):
    """Pixels within `tolerance` of the mouth's inside colours within the lips' box (the teeth's white is
    the eyes' too)."""
    width = image.width
    lips = [i for i, pixel in enumerate(image.getdata()) if is_near(pixel, LIPS, 24)]
    assert lips, "no lips in the picture"
    left, right = min(i % width for i in lips), max(i % width for i in lips)
    top, bottom = min(lips) // width, max(lips) // width
    box = image.crop((left, top, right + 1, bottom + 1))
    return sum(1 for pixel in box.getdata() if any(is_near(pixel, colour, tolerance) for colour in MOUTH_INSIDE))
