"""Meshes made in numpy for the tests, and where the CLI and the shared meshes are."""

import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import petersen

REPO = pathlib.Path(__file__).resolve().parents[2]


class TrimeshLike:
    """What petersen reads of a trimesh.Trimesh."""

    def __init__(self, vertices, faces):
        self.vertices, self.faces = np.asarray(vertices), np.asarray(faces)


class PolyDataLike:
    """What petersen reads of a pyvista.PolyData: points and padded faces."""

    def __init__(self, points, faces):
        self.points, self.faces = np.asarray(points), np.asarray(faces)


def octahedron():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                  [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return V, F


def torus(nu, nv, R=3.0, r=1.0):
    """A closed torus of 2 nu nv triangles (genus 1), each grid square split along a diagonal."""
    u, v = np.meshgrid(np.arange(nu) * 2 * np.pi / nu, np.arange(nv) * 2 * np.pi / nv,
                       indexing="ij")
    V = np.stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u),
                  r * np.sin(v)], axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a = i * nv + j
    b = ((i + 1) % nu) * nv + j
    c = ((i + 1) % nu) * nv + (j + 1) % nv
    d = i * nv + (j + 1) % nv
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                        np.stack([a, c, d], -1).reshape(-1, 3)])
    return V, F


def open_grid(nx, ny):
    """A flat nx by ny grid of squares, each split into two triangles: a disc with boundary."""
    x, y = np.meshgrid(np.arange(nx + 1, dtype=float), np.arange(ny + 1, dtype=float),
                       indexing="ij")
    V = np.stack([x, y, np.zeros_like(x)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    a = i * (ny + 1) + j
    b = (i + 1) * (ny + 1) + j
    c = b + 1
    d = a + 1
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                        np.stack([a, c, d], -1).reshape(-1, 3)])
    return V, F


def chamfered_cubes(cli, folder, count):
    """`count` of the generators' chamfered cubes (`petersen generate --kind chamfered-cube`: 6
    squares, 12 bevels, 8 corner triangles) side by side, exported triangulated: each quad cut
    along the diagonal from its first corner (even cubes) or its second (odd). A hard-surface
    model whose own triangles are its corners."""
    path = pathlib.Path(folder) / "chamfered-cube.obj"
    subprocess.run([cli, "generate", str(path), "--kind", "chamfered-cube"], check=True,
                   capture_output=True)
    cube = petersen.read_mesh(str(path))
    P, faces = np.asarray(cube.V, np.float64), [np.asarray(f) for f in cube.F]
    V, F = [], []
    for i in range(count):
        V.append(P + [3.0 * i, 0, 0])
        k = i % 2
        for c in faces:
            c = c + len(P) * i
            if len(c) == 3:
                F.append(c)
            else:
                F += [[c[k], c[k + 1], c[(k + 2) % 4]], [c[k], c[(k + 2) % 4], c[(k + 3) % 4]]]
    return np.concatenate(V), np.array(F, dtype=np.int64)


@pytest.fixture
def cli():
    """The petersen CLI: PETERSEN_CLI, else build/release/tools/petersen; skip (with the reason
    shown by -rs) when neither exists."""
    path = os.environ.get("PETERSEN_CLI") or str(REPO / "build/release/tools/petersen")
    if not (os.path.isfile(path) and os.access(path, os.X_OK)) and not shutil.which(path):
        pytest.skip(f"the petersen CLI is not built ({path}); set PETERSEN_CLI")
    return path


@pytest.fixture
def shared_meshes():
    """The shared meshes: PETERSEN_SHARED_MESHES, else ../shared/meshes beside the clone."""
    path = pathlib.Path(os.environ.get("PETERSEN_SHARED_MESHES") or REPO.parent / "shared/meshes")
    if not path.is_dir():
        pytest.skip(f"shared meshes not found at {path}; set PETERSEN_SHARED_MESHES")
    return path
