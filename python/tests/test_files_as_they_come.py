"""Meshes as files hold them: dangling attribute references (dropped with one warning, or refused
with strict), faces doubled (counted, and dropped with drop_duplicate_faces, sources naming the
faces as given), degenerate faces kept under all_quad, triangle strips read as their triangles."""

import warnings

import numpy as np
import pytest

import petersen
from checks import check_result
from conftest import torus


def test_dangling_normals_and_texture_coordinates(tmp_path):
    path = tmp_path / "dangling.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
                    "f 1//1 2//1 3//1\nf 1/1 3/2 4/1\n")
    with pytest.warns(petersen.DroppedWarning) as caught:
        mesh = petersen.read_mesh(path)
    messages = [str(w.message) for w in caught]
    assert len(messages) == 2
    assert any("normal indices" in m and "line 6" in m for m in messages)
    assert any("texture coordinate indices" in m and "line 7" in m for m in messages)
    assert len(mesh.F) == 2
    r = petersen.quadrangulate(mesh)
    assert r.stats["pairs"] == 1
    with pytest.raises(ValueError, match=r"dangling.obj:6: face 1: normal index 1 out of range"):
        petersen.read_mesh(path, strict=True)


def test_doubled_faces_counted_and_dropped():
    V, F = torus(8, 6)
    doubled = np.concatenate([F, F[:, ::-1]])
    r = petersen.quadrangulate(V, doubled)
    assert r.stats["duplicate_faces"] == len(F) and r.stats["pairs"] == 0
    dropped = petersen.quadrangulate(V, doubled, drop_duplicate_faces=True)
    single = petersen.quadrangulate(V, F)
    assert dropped.stats["pairs"] == single.stats["pairs"] == len(F) // 2
    assert np.array_equal(dropped.quads, single.quads)
    assert np.array_equal(dropped.sources, single.sources)  # the first copies: the same ids
    # The copies first: sources name the faces as given, past the dropped ones.
    flipped = np.concatenate([F[:, ::-1], F])
    r = petersen.quadrangulate(V, flipped, drop_duplicate_faces=True)
    assert r.stats["pairs"] == len(F) // 2 and r.sources.min() >= 0
    assert r.sources.max() < len(F)
    check_result(V, [tuple(f) for f in F[:, ::-1]], r)


def test_degenerate_faces_kept_under_all_quad():
    V, F = torus(8, 6)
    F = F.copy()
    F[5, 2] = F[5, 1]  # a corner collapsed onto the one before it
    F[17, 0] = F[17, 2]
    r = petersen.quadrangulate(V, F, all_quad=True)
    assert r.stats["degenerate_faces"] == 2
    assert len(r.triangles) == 2 and len(r.polygons) == 0
    assert sorted(map(tuple, r.triangles.tolist())) == sorted([tuple(F[5]), tuple(F[17])])


def test_tristrips(tmp_path):
    path = tmp_path / "strip.ply"
    path.write_text("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                    "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 0 1 2 3 -1\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mesh = petersen.read_mesh(path)
    assert [tuple(f) for f in mesh.F] == [(0, 1, 2), (2, 1, 3)]
