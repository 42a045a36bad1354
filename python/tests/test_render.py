"""petersen.render and quad_quality; the pixels themselves are checked by tests/render (C++)."""

import struct

import numpy as np
import pytest

import petersen
from conftest import octahedron, open_grid


def png_size(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    return width, height


def test_render_writes_png_and_svg(tmp_path):
    V, F = open_grid(6, 4)
    r = petersen.quadrangulate(V, F[:-1], all_quad=True)
    faces = [*r.quads, *r.triangles]
    petersen.render(tmp_path / "g.png", r.V, faces, first_added_vertex=len(V),
                    caption=["an open grid"], width=640, height=480)
    assert png_size(tmp_path / "g.png") == (640, 480)
    petersen.render(tmp_path / "g.svg", r.V, r.quads, view=(0, 0, -1))
    assert b"<svg" in (tmp_path / "g.svg").read_bytes()[:400]


def test_render_refuses_bad_input(tmp_path):
    V, F = octahedron()
    with pytest.raises(ValueError, match=r"\.png or \.svg"):
        petersen.render(tmp_path / "x.bmp", V, F)
    with pytest.raises(ValueError, match="view"):
        petersen.render(tmp_path / "x.png", V, F, view=(0, 0, 0))
    with pytest.raises(ValueError, match="vertex"):
        petersen.render(tmp_path / "x.png", V, F + 6)


def test_quad_quality_of_known_quads():
    s = 1 / np.sqrt(3)
    V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [1 + s, 1, 0], [s, 1, 0], [4, 0, 0],
         [3, 1, 0]]
    # A square, a 60/120 degree parallelogram, the trapezoid (0,0) (4,0) (3,1) (0,1) of angles
    # 90, 45, 135, 90.
    quads = np.array([[0, 1, 2, 3], [0, 1, 4, 5], [0, 6, 7, 3]], dtype=np.int32)
    cost = petersen.quad_quality(V, quads)
    assert cost == pytest.approx([0, 30, 45])
    with pytest.raises(ValueError, match="not 4"):
        petersen.quad_quality(V, [[0, 1, 2]])
    with pytest.raises(ValueError, match="out of range"):
        petersen.quad_quality(V, [[0, 1, 2, 30]])
