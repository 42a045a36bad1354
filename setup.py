"""Builds petersen's Python module with the repository's own CMake build (no second build system).

The extension petersen._petersen is the CMake target _petersen (python/CMakeLists.txt), configured
with PETERSEN_PYTHON=ON (and the LEMON peer) and tests, bench and tools off, so the library is compiled exactly as for
the CLI, only position-independent. Everything comes from Debian's packages (cmake, ninja,
pybind11-dev, the libraries of scripts/ensure-deps) and setuptools is Debian's too: install with

    /usr/bin/python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation .

Nothing is downloaded. CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: all cores).
"""

import os
import pathlib
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        root = pathlib.Path(__file__).parent.resolve()
        out_dir = pathlib.Path(self.get_ext_fullpath(ext.name)).parent.resolve()
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(root), "-B", str(build_dir), "-G", "Ninja",
            "-DCMAKE_BUILD_TYPE=Release",
            "-DPETERSEN_PYTHON=ON",
            "-DPETERSEN_BUILD_TESTS=OFF",
            "-DPETERSEN_BUILD_BENCH=OFF",
            "-DPETERSEN_BUILD_TOOLS=OFF",
            "-DPETERSEN_WITH_LEMON=ON",  # algorithm="lemon", the comparison peer
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DCMAKE_LIBRARY_OUTPUT_DIRECTORY={out_dir}",
        ]
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_petersen",
                        "--parallel", jobs], check=True)


setup(ext_modules=[CMakeExtension("petersen._petersen")], cmdclass={"build_ext": CMakeBuild})
