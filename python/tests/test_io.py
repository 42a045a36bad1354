"""petersen.read_mesh and write_mesh: round trips in every format, and located errors."""

import numpy as np
import pytest

import petersen
from conftest import octahedron, torus


@pytest.mark.parametrize("ext", ["off", "obj", "ply", "off.gz", "obj.gz", "ply.gz"])
def test_triangles_round_trip(tmp_path, ext):
    V, F = torus(6, 5)
    V = V * np.pi  # coordinates with many digits: the text formats write them exactly
    path = tmp_path / f"t.{ext}"
    petersen.write_mesh(path, V, F)
    m = petersen.read_mesh(path)
    assert isinstance(m.F, np.ndarray) and m.F.shape == F.shape and m.F.dtype == np.int64
    assert np.array_equal(m.F, F)
    assert np.array_equal(m.V, V)  # bit for bit
    assert m.V.flags.owndata and m.F.flags.owndata


@pytest.mark.parametrize("ext", ["off", "obj", "ply"])
def test_polygons_round_trip_as_a_list(tmp_path, ext):
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0.5, 0], [3, 1, 0]], float)
    faces = [[0, 1, 2, 3], [1, 4, 2], [4, 5, 2, 1, 0]]
    path = tmp_path / f"p.{ext}"
    petersen.write_mesh(path, V, faces)
    m = petersen.read_mesh(path)
    assert isinstance(m.F, list)
    assert [f.tolist() for f in m.F] == faces
    assert np.array_equal(m.V, V)


def test_a_quadrangulation_written_and_read_back(tmp_path):
    V, F = octahedron()
    r = petersen.quadrangulate(V, F)
    petersen.write_mesh(tmp_path / "q.obj", r.V, r.quads)
    m = petersen.read_mesh(tmp_path / "q.obj")
    assert [f.tolist() for f in m.F] == r.quads.tolist()


def test_errors_name_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    with pytest.raises(ValueError, match=r"bad\.off:6"):
        petersen.read_mesh(bad)
    with pytest.raises(ValueError, match="missing.off"):
        petersen.read_mesh(tmp_path / "missing.off")
    with pytest.raises(ValueError, match="extension|format"):
        petersen.read_mesh(tmp_path / "x.stl")
    V, F = octahedron()
    with pytest.raises(ValueError, match="out of range"):
        petersen.write_mesh(tmp_path / "w.off", V, F + 10)
    with pytest.raises(ValueError):
        petersen.write_mesh(tmp_path / "w.xyz", V, F)
    with pytest.raises(ValueError):
        petersen.write_mesh(tmp_path / "no-such-dir" / "w.off", V, F)
    assert not (tmp_path / "w.off").exists()
