"""Builds the `sphereset` Python package with the project's CMake build (python/CMakeLists.txt).

Used by `pip install --no-build-isolation .` (pyproject.toml). The extension is configured with
the interpreter that runs pip (-DPython3_EXECUTABLE), without tests, benchmarks or the CLI;
CMAKE_ARGS in the environment adds options (e.g. "-DSPHERESET_WITH_REPAIR=OFF" for an MIT-only
module), CMAKE_BUILD_PARALLEL_LEVEL sets the build jobs (default 2). The CMake build and
setuptools' own files go to build-pip/ in the source tree (SPHERESET_PIP_BUILD_DIR chooses
another folder), where a second install builds incrementally.
"""

import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("SPHERESET_PIP_BUILD_DIR", ROOT / "build-pip")).resolve()


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = BUILD
        args = [
            "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}", "-DSPHERESET_BUILD_TESTS=OFF",
            "-DSPHERESET_BUILD_BENCH=OFF", "-DSPHERESET_BUILD_PYTHON=ON",
        ]
        if shutil.which("ccache"):
            args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        args += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        subprocess.run(args, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(["cmake", "--build", str(build), "--target", "_sphereset", "-j", jobs],
                       check=True)
        built = sorted((build / "python" / "sphereset").glob("_sphereset*.so"))
        if not built:
            raise RuntimeError(f"no _sphereset module in {build / 'python' / 'sphereset'}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    packages=["sphereset"],
    package_dir={"": "python"},
    package_data={"sphereset": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("sphereset._sphereset")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    options={"build": {"build_base": str(BUILD / "setuptools")},
             "egg_info": {"egg_base": str(BUILD)}},
)
