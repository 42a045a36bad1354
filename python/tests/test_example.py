"""examples/convert.py runs as documented, on the bundled mesh and on an open mesh."""

import pathlib
import re
import subprocess
import sys

import numpy as np

import petersen
from conftest import REPO, open_grid
from test_render import png_size

EXAMPLE = REPO / "examples" / "convert.py"


def run(*args):
    done = subprocess.run([sys.executable, str(EXAMPLE), *map(str, args)], check=True,
                          capture_output=True, text=True)
    return done.stdout


def median_of(line):
    return float(re.search(r"median +([0-9.]+) deg", line).group(1))


def test_the_bundled_mesh_with_both_objectives(tmp_path):
    out = run("--out", tmp_path)
    lines = [l for l in out.splitlines() if re.match(r"(pairs|quality) +pairs", l)]
    assert len(lines) == 2, out
    for line in lines:
        assert "pairs    1550" in line and "triangles left     0" in line
        assert re.search(r"median +[0-9.]+ deg, p95 +[0-9.]+ deg, non-convex +[0-9.]+ %", line)
    # The certified minimum total cost makes better quads than ps's pairing on this mesh.
    assert median_of(lines[1]) <= median_of(lines[0])
    for objective in ("pairs", "quality"):
        assert png_size(tmp_path / f"plate-genus2-{objective}.png") == (800, 800)


def test_an_open_mesh_with_all_quad(tmp_path):
    V, F = open_grid(7, 5)
    petersen.write_mesh(tmp_path / "grid.obj", V, F[1:])  # 69 triangles: one is left
    out = run(tmp_path / "grid.obj", "--out", tmp_path, "--algorithm", "sg", "--all-quad")
    for objective in ("pairs", "quality"):
        line = next(l for l in out.splitlines() if l.startswith(objective + " "))
        added = int(re.search(r"added vertices +(\d+)", line).group(1))
        assert added >= 1, line
        assert png_size(tmp_path / f"grid-{objective}.png") == (800, 800)
