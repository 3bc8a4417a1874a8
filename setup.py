"""pip support: `pip install --no-build-isolation .` builds the _talkface modules with CMake.

The library is built static (BUILD_SHARED_LIBS=OFF) into the extensions, so the wheel needs no
libtalkface.so beside it; _talkface_photo (face from a photo, OpenCV) is a module of its own, which
the package imports on first use, and FFmpeg's work is the library's module talkface/talkface_ffmpeg.so
in the package, which the library opens on first use. Nothing is written into the source tree, so a read-only checkout
installs: setuptools' build and egg-info folders and the CMake build go to a folder under the
temporary directory named for this checkout (TALKFACE_PIP_BUILD_DIR overrides it).
TALKFACE_CMAKE_BUILD_DIR, if set, is the CMake build folder; CMAKE_BUILD_PARALLEL_LEVEL sets the
build's jobs as usual; CMAKE_ARGS adds options to CMake's configure step, split as a shell splits
them and given after talkface's own, so that they win (CMAKE_ARGS="-DCMAKE_BUILD_TYPE=Debug"): the
variable conda-forge and scikit-build pass CMake options through pip with.
"""

import hashlib
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent
# One folder per checkout (pip runs setup.py several times per install; each run finds the same one).
BUILD_BASE = Path(
    os.environ.get("TALKFACE_PIP_BUILD_DIR")
    or Path(tempfile.gettempdir())
    / f"talkface-pip-{os.getuid()}-{hashlib.sha256(str(SOURCE_DIR).encode()).hexdigest()[:12]}"
)
BUILD_BASE.mkdir(parents=True, exist_ok=True)  # egg_info wants its egg_base to exist
EXTENSION_MODULES = ("_talkface", "_talkface_photo")


def project_version() -> str:
    cmake_lists = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(talkface VERSION (\d+\.\d+\.\d+)", cmake_lists).group(1)


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    @staticmethod
    def photo_configured(build_dir: Path) -> bool:
        cache = (build_dir / "CMakeCache.txt").read_text(encoding="utf-8")
        return re.search(r"^TALKFACE_WITH_PHOTO:BOOL=ON$", cache, re.MULTILINE) is not None

    def build_extension(self, ext: Extension) -> None:
        build_dir = Path(os.environ.get("TALKFACE_CMAKE_BUILD_DIR") or BUILD_BASE / "cmake")
        build_dir.mkdir(parents=True, exist_ok=True)
        subprocess.run(
            [
                "cmake", "-S", str(SOURCE_DIR), "-B", str(build_dir),
                "-DCMAKE_BUILD_TYPE=Release",
                f"-DPython3_EXECUTABLE={sys.executable}",
                "-DTALKFACE_BUILD_PYTHON=ON",
                "-DTALKFACE_BUILD_TESTS=OFF",
                "-DTALKFACE_BUILD_SAMPLES=OFF",
                "-DTALKFACE_BUILD_CLI=OFF",
                "-DTALKFACE_INSTALL=OFF",
                "-DBUILD_SHARED_LIBS=OFF",
                *shlex.split(os.environ.get("CMAKE_ARGS", "")),
            ],
            check=True,
        )
        module = ext.name.rsplit(".", 1)[1]
        built = build_dir / "python" / "talkface" / (module + sysconfig.get_config_var("EXT_SUFFIX"))
        build = ["cmake", "--build", str(build_dir), "--target", module]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        if module == "_talkface_photo" and not self.photo_configured(build_dir):
            return  # built without the photo stage (no OpenCV): the package works without it
        subprocess.run(build, check=True)

        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)
        if module == "_talkface":
            # FFmpeg's module, which libtalkface (linked into _talkface) opens from talkface/ beside
            # itself on first use (src/audio/ffmpeg_module.hpp); built with libtalkface.
            ffmpeg_module = "talkface_ffmpeg" + sysconfig.get_config_var("SHLIB_SUFFIX")
            (target.parent / "talkface").mkdir(exist_ok=True)
            shutil.copyfile(build_dir / "src" / "talkface" / ffmpeg_module, target.parent / "talkface" / ffmpeg_module)


setup(
    version=project_version(),
    license_files=["LICENSE"],
    packages=["talkface"],
    package_dir={"talkface": "bindings/python/talkface"},
    package_data={"talkface": ["py.typed", "_talkface.pyi", "_talkface_photo.pyi"]},
    ext_modules=[CMakeExtension("talkface." + module) for module in EXTENSION_MODULES],
    cmdclass={"build_ext": CMakeBuild},
    # Out of the source tree (module docstring); not setuptools' build/, a common name for a
    # developer's CMake build folder.
    options={"build": {"build_base": str(BUILD_BASE / "build")}, "egg_info": {"egg_base": str(BUILD_BASE)}},
    zip_safe=False,
)
