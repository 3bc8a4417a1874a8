# Type stubs for the compiled talkface._talkface_photo module, face from a photo (kept by hand next
# to bindings/python/src/bind_photo.cpp). talkface imports it on the first use of these names.
import os

import numpy
import numpy.typing

from ._talkface import FaceModel

_PathLike = str | os.PathLike[str]

class PhotoFeature:
    name: str
    confidence: float
    from_prior: bool
    source: str

class PhotoFaceResult:
    face: FaceModel
    features: list[PhotoFeature]
    locator: str
    face_box: tuple[int, int, int, int]
    faces_found: int
    def confidence(self, feature_name: str) -> float: ...
    def write_overlay(self, photo: _PathLike, output_png: _PathLike) -> None: ...

def has_dlib_locator() -> bool: ...
def face_model_from_photo(photo: _PathLike | numpy.typing.NDArray[numpy.uint8], *, locator: str = "automatic",
                          face_index: int = -1, cascade_dir: str = "", dlib_model_path: str = "",
                          min_face_width_px: int = 64) -> FaceModel: ...
def face_from_photo(photo: _PathLike | numpy.typing.NDArray[numpy.uint8], *, locator: str = "automatic",
                    face_index: int = -1, cascade_dir: str = "", dlib_model_path: str = "",
                    min_face_width_px: int = 64) -> PhotoFaceResult: ...
