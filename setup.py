"""Builds petersen's Python module with the repository's own CMake build (no second build system).

The extension petersen._petersen is the CMake target _petersen (python/CMakeLists.txt), configured
with PETERSEN_PYTHON=ON (and the LEMON peer) and tests, bench and tools off, so the library is compiled exactly as for
the CLI, only position-independent. Everything comes from Debian's packages (cmake, ninja,
pybind11-dev, the libraries of scripts/ensure-deps) and setuptools is Debian's too: install with

    /usr/bin/python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation .

Nothing is downloaded. CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: all cores).

PETERSEN_CMAKE_BUILD_DIR names an existing build tree to build the module in instead (configured
with -DPETERSEN_PYTHON=ON for this interpreter, as scripts/test does with its Release tree): its
libraries are compiled once for the tools, the tests and the module, and the module is copied from
there.
"""

import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        root = pathlib.Path(__file__).parent.resolve()
        out_dir = pathlib.Path(self.get_ext_fullpath(ext.name)).parent.resolve()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        existing = os.environ.get("PETERSEN_CMAKE_BUILD_DIR")
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
            "-DPETERSEN_WITH_LEMON=ON",  # algorithm="lemon", the comparison peer
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DCMAKE_LIBRARY_OUTPUT_DIRECTORY={out_dir}",
        ]
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_petersen",
                        "--parallel", jobs], check=True)

    @staticmethod
    def build_in_existing_tree(build_dir: pathlib.Path, out_dir: pathlib.Path, jobs: str) -> None:
        cache = build_dir / "CMakeCache.txt"
        if "PETERSEN_PYTHON:BOOL=ON" not in (cache.read_text() if cache.exists() else ""):
            sys.exit(f"PETERSEN_CMAKE_BUILD_DIR={build_dir}: not a build tree configured with "
                     "-DPETERSEN_PYTHON=ON")
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_petersen",
                        "--parallel", jobs], check=True)
        # The tree's Python is the one it was configured with: its module must be this one's.
        module = build_dir / "python" / ("_petersen" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not module.exists():
            sys.exit(f"{build_dir} built no {module.name}: configure it with "
                     f"-DPython_EXECUTABLE={sys.executable}")
        out_dir.mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, out_dir / module.name)


setup(ext_modules=[CMakeExtension("petersen._petersen")], cmdclass={"build_ext": CMakeBuild})
