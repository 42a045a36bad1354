"""Builds petersen's Python module with the repository's own CMake build (no second build system).

The extension petersen._petersen is the CMake target _petersen (python/CMakeLists.txt), configured
with PETERSEN_PYTHON=ON and tests, bench and tools off, so the library is compiled exactly as for
the CLI, only position-independent. Everything comes from Debian's packages (cmake, ninja,
pybind11-dev, the libraries of scripts/ensure-deps) and setuptools is Debian's too: install with

    /usr/bin/python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation .

Nothing is downloaded. CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: all cores).

An existing build tree is reused when there is one: PETERSEN_CMAKE_BUILD_DIR names it, and
without it build/release is taken when it was configured with -DPETERSEN_PYTHON=ON (as scripts/run
and scripts/test configure it). Its libraries are compiled once for the tools, the tests and the
module, and the module is copied from there; PETERSEN_CMAKE_BUILD_DIR= (empty) builds afresh.

pip shows a build's output only with -v, so the build's progress lines go to the terminal
(/dev/tty) when there is one.
"""

import functools
import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig
from typing import List

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


@functools.lru_cache(maxsize=None)
def progress_stream():
    """Where the build's progress goes: the terminal when there is one (pip captures stdout and
    stderr until the end), else stderr."""
    try:
        return open("/dev/tty", "w", buffering=1)
    except OSError:
        return sys.stderr


def run_with_progress(command: List[str]) -> None:
    out = progress_stream()
    print("petersen: " + " ".join(command), file=out)
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          bufsize=1) as build:
        for line in build.stdout:
            print("petersen: " + line.rstrip(), file=out)
    if build.returncode != 0:
        raise subprocess.CalledProcessError(build.returncode, command)


def configured_for_python(build_dir: pathlib.Path) -> bool:
    cache = build_dir / "CMakeCache.txt"
    return "PETERSEN_PYTHON:BOOL=ON" in (cache.read_text() if cache.exists() else "")


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        root = pathlib.Path(__file__).parent.resolve()
        out_dir = pathlib.Path(self.get_ext_fullpath(ext.name)).parent.resolve()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        existing = os.environ.get("PETERSEN_CMAKE_BUILD_DIR")
        if existing is None and configured_for_python(root / "build" / "release"):
            existing = str(root / "build" / "release")
        if existing:
            self.build_in_existing_tree(pathlib.Path(existing).resolve(), out_dir, jobs)
            return
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(root), "-B", str(build_dir), "-G", "Ninja",
            "-DCMAKE_BUILD_TYPE=Release",
            "-DPETERSEN_PYTHON=ON",
            "-DPETERSEN_BUILD_TESTS=OFF",
            "-DPETERSEN_BUILD_BENCH=OFF",
            "-DPETERSEN_BUILD_TOOLS=OFF",
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DCMAKE_LIBRARY_OUTPUT_DIRECTORY={out_dir}",
        ]
        run_with_progress(configure)
        run_with_progress(["cmake", "--build", str(build_dir), "--target", "_petersen",
                           "--parallel", jobs])

    @staticmethod
    def build_in_existing_tree(build_dir: pathlib.Path, out_dir: pathlib.Path, jobs: str) -> None:
        if not configured_for_python(build_dir):
            sys.exit(f"PETERSEN_CMAKE_BUILD_DIR={build_dir}: not a build tree configured with "
                     "-DPETERSEN_PYTHON=ON")
        print(f"petersen: reusing the build tree {build_dir}", file=progress_stream())
        run_with_progress(["cmake", "--build", str(build_dir), "--target", "_petersen",
                           "--parallel", jobs])
        # The tree's Python is the one it was configured with: its module must be this one's.
        module = build_dir / "python" / ("_petersen" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not module.exists():
            sys.exit(f"{build_dir} built no {module.name}: configure it with "
                     f"-DPython_EXECUTABLE={sys.executable}")
        out_dir.mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, out_dir / module.name)


setup(ext_modules=[CMakeExtension("petersen._petersen")], cmdclass={"build_ext": CMakeBuild})
