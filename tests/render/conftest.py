"""The browser suite here starts one Chromium a module, as tests/apps' do (tests/apps/browser.py)."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "apps"))

from browser import chromium  # noqa: E402,F401 (the fixture, for every module here)
