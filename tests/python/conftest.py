import pytest

import talkface


@pytest.fixture
def face():
    """A fresh default face per test, so tests may modify it."""
    return talkface.FaceModel.default()
