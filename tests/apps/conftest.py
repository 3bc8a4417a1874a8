"""What the browser suites share: one Chromium a module (browser.py), each case on a page of its own."""
import pytest

from browser import CHROMIUM, Chromium


@pytest.fixture(scope="module")
def chromium():
    if CHROMIUM is None:
        pytest.skip("chromium is not installed")
    with Chromium() as shared:
        yield shared
