"""pip support: `pip install --no-build-isolation .` builds the _talkface module with CMake.

The library is built static (BUILD_SHARED_LIBS=OFF) into the extension, so the wheel needs no
libtalkface.so beside it. TALKFACE_CMAKE_BUILD_DIR, if set, is the CMake build folder (the packaging
ctest keeps it out of the source tree); CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs as usual.
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent


def project_version() -> str:
    cmake_lists = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(talkface VERSION (\d+\.\d+\.\d+)", cmake_lists).group(1)


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build_dir = Path(os.environ.get("TALKFACE_CMAKE_BUILD_DIR") or Path(self.build_temp) / "cmake")
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
            ],
            check=True,
        )
        build = ["cmake", "--build", str(build_dir), "--target", "_talkface"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        subprocess.run(build, check=True)

        built = build_dir / "python" / "talkface" / ("_talkface" + sysconfig.get_config_var("EXT_SUFFIX"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    packages=["talkface"],
    package_dir={"talkface": "bindings/python/talkface"},
    package_data={"talkface": ["py.typed", "_talkface.pyi"]},
    ext_modules=[CMakeExtension("talkface._talkface")],
    cmdclass={"build_ext": CMakeBuild},
    # build-pip/, not setuptools' build/: build/ is a common name for a developer's CMake build folder.
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
