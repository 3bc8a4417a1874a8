"""What the browser suites share: one Chromium a module (browser.py), each case on a page of its own."""
from browser import chromium  # noqa: F401 (the fixture, for every module here)
