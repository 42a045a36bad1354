"""Meshes of other Python libraries in and out of petersen: meshio's Mesh (the real one, Debian's
python3-meshio), trimesh's and pyvista's shapes. trimesh and pyvista are not in Debian, so their
paths are tested with small stand-ins that have the same attributes (``.vertices`` and ``.faces``;
``.points`` and a padded ``.faces``), which is all petersen reads of them."""

import sys
import warnings

import numpy as np
import pytest

import petersen
from conftest import PolyDataLike, TrimeshLike, octahedron, open_grid, torus


def mixed_mesh():
    """A 4 by 4 grid of squares: six as two triangles each, eight quads, and the last two
    pentagons (a vertex added on the edge between them); positions and faces."""
    V, F = open_grid(4, 4)  # square s is F[s] = (a, b, c) and F[16 + s] = (a, c, d)
    faces = [list(F[s]) for s in range(6)] + [list(F[16 + s]) for s in range(6)]
    faces += [[*F[s], F[16 + s][2]] for s in range(6, 14)]
    m = len(V)
    a, b, c, d = *F[14], F[16 + 14][2]
    V = np.vstack([V, (V[c] + V[d]) / 2])  # on the edge c d, which square 15 has as a b
    faces.append([a, b, c, m, d])
    a, b, c, d = *F[15], F[16 + 15][2]
    faces.append([a, m, b, c, d])
    return V, faces


def same_result(a, b):
    assert np.array_equal(a.quads, b.quads)
    assert np.array_equal(a.triangles, b.triangles)
    assert [p.tolist() for p in a.polygons] == [p.tolist() for p in b.polygons]


# --- meshio ---------------------------------------------------------------------------------

def test_quadrangulate_takes_a_meshio_mesh_with_its_blocks():
    meshio = pytest.importorskip("meshio")
    V, F = torus(6, 4)
    m = meshio.Mesh(V, [("triangle", F[:30]), ("quad", [[0, 1, 2, 3]]), ("triangle", F[30:])])
    r = petersen.quadrangulate(m)
    faces = [*F[:30].tolist(), [0, 1, 2, 3], *F[30:].tolist()]
    same_result(r, petersen.quadrangulate(V, faces))
    assert [p.tolist() for p in r.polygons] == [[0, 1, 2, 3]]


def test_meshio_polygons_and_data_carried_other_blocks_warned():
    meshio = pytest.importorskip("meshio")
    V, faces = mixed_mesh()
    tris = np.array([f for f in faces if len(f) == 3])
    pentagons = np.array([f for f in faces if len(f) == 5])
    region = np.arange(len(tris)) % 2  # alternate regions: no quad joins two of them
    m = meshio.Mesh(
        V, [("triangle", tris), ("polygon", pentagons), ("line", [[0, 1]])],
        point_data={"height": V[:, 0] * 2, "rgb": np.zeros((len(V), 3))},
        cell_data={"region": [region, np.array([7, 8]), np.array([0])]})
    with pytest.warns(petersen.DroppedWarning) as caught:
        r = petersen.quadrangulate(m)
    said = " ".join(str(w.message) for w in caught)
    assert "'line'" in said and "'rgb'" in said
    assert r.stats["cut_edges_by_cause"]["face_property"] > 0
    for quad_sources in r.sources[: len(r.quads)]:
        assert region[quad_sources[0]] == region[quad_sources[1]]
    assert [p.tolist() for p in r.polygons] == pentagons.tolist()
    carried = r.attributes["face_properties"]["region"]
    assert len(carried) == len(r.faces)
    assert np.array_equal(carried[-2:], [7, 8])
    assert np.array_equal(r.attributes["vertex_properties"]["height"], V[:, 0] * 2)


def test_result_to_meshio_quads_and_triangles_as_blocks():
    meshio = pytest.importorskip("meshio")
    V, F = open_grid(5, 3)
    r = petersen.quadrangulate(V, F[:-1])  # an odd count: a triangle is left
    m = r.to_meshio()
    assert isinstance(m, meshio.Mesh)
    assert [b.type for b in m.cells] == ["quad", "triangle"]
    assert np.array_equal(m.cells[0].data, r.quads)
    assert np.array_equal(m.cells[1].data, r.triangles)
    assert np.array_equal(m.points, r.V)


def test_result_to_meshio_maps_attributes(tmp_path):
    pytest.importorskip("meshio")
    V, F = open_grid(2, 2)
    a = {"material_names": ["red", "blue"], "face_material": np.array([0, 0, 1, 1, 0, 0, 1, 1]),
         "vertex_properties": {"w": np.arange(len(V), dtype=np.float32)}}
    r = petersen.quadrangulate(V, F, attributes=a)
    with pytest.warns(petersen.DroppedWarning, match="material_names"):
        m = r.to_meshio()
    materials = np.concatenate(m.cell_data["face_material"])
    assert np.array_equal(materials, r.attributes["face_material"])
    assert np.array_equal(m.point_data["w"], a["vertex_properties"]["w"])
    m.write(tmp_path / "r.vtk")  # a format of meshio's own takes it


def test_read_mesh_as_meshio_and_write_mesh_of_meshio(tmp_path):
    meshio = pytest.importorskip("meshio")
    V, faces = mixed_mesh()
    petersen.write_mesh(tmp_path / "m.off", V, faces)
    m = petersen.read_mesh(tmp_path / "m.off", as_meshio=True)
    assert isinstance(m, meshio.Mesh)
    assert [b.type for b in m.cells] == ["triangle", "quad", "polygon"]
    read_back = [f.tolist() for b in m.cells for f in b.data]
    assert read_back == faces
    petersen.write_mesh(tmp_path / "again.obj", m)
    again = petersen.read_mesh(tmp_path / "again.obj")
    assert [f.tolist() for f in again.F] == faces
    assert np.array_equal(again.V, V)


def test_meshio_2d_points_lie_on_z_0():
    meshio = pytest.importorskip("meshio")
    V, F = open_grid(3, 3)
    r = petersen.quadrangulate(meshio.Mesh(V[:, :2], [("triangle", F)]))
    assert r.V.shape == (len(V), 3) and np.all(r.V[:, 2] == 0)
    assert r.stats["pairs"] == 9


def test_without_meshio_a_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "meshio", None)
    V, F = octahedron()
    with pytest.raises(ImportError, match="python3-meshio"):
        petersen.quadrangulate(V, F).to_meshio()


# --- trimesh's and pyvista's shapes (stand-ins) ----------------------------------------------

def test_an_object_with_vertices_and_faces():
    V, F = torus(8, 6)
    same_result(petersen.quadrangulate(TrimeshLike(V, F)), petersen.quadrangulate(V, F))


def test_padded_faces_in_and_out():
    V, faces = mixed_mesh()
    flat = np.concatenate([[len(f), *f] for f in faces])
    expected = petersen.quadrangulate(V, faces)
    same_result(petersen.quadrangulate(V, flat), expected)
    same_result(petersen.quadrangulate(PolyDataLike(V, flat)), expected)
    padded = expected.padded_faces()
    assert padded.dtype == np.int64
    assert [f.tolist() for f in petersen.interop.faces_from_padded(padded)] == \
        [f.tolist() for f in expected.faces]
    grid = petersen.quadrangulate(*open_grid(3, 2))
    assert np.array_equal(petersen.interop.faces_from_padded(grid.padded_faces()), grid.quads)


def test_write_mesh_of_shapes(tmp_path):
    V, F = torus(5, 4)
    petersen.write_mesh(tmp_path / "t.ply", TrimeshLike(V, F))
    assert np.array_equal(petersen.read_mesh(tmp_path / "t.ply").F, F)
    petersen.write_mesh(tmp_path / "p.off", PolyDataLike(V, petersen.interop.padded(F)))
    assert np.array_equal(petersen.read_mesh(tmp_path / "p.off").F, F)
    r = petersen.quadrangulate(V, F)
    petersen.write_mesh(tmp_path / "r.obj", r)
    assert [f.tolist() for f in petersen.read_mesh(tmp_path / "r.obj").F] == \
        [f.tolist() for f in r.faces]


def test_bad_padded_faces_and_objects_are_named():
    V, F = octahedron()
    with pytest.raises(ValueError, match="position 4 is 2"):
        petersen.quadrangulate(V, np.array([3, 0, 1, 2, 2, 0, 1]))
    with pytest.raises(ValueError, match="position 4 has 5 corners but only 3"):
        petersen.quadrangulate(V, np.array([3, 0, 1, 2, 5, 0, 1, 2]))
    with pytest.raises(TypeError, match="not both"):
        petersen.quadrangulate(TrimeshLike(V, F), F)
    with pytest.raises(TypeError, match="got dict"):
        petersen.quadrangulate({"V": V})


# --- render ----------------------------------------------------------------------------------

def test_render_takes_a_mesh_and_a_result(tmp_path):
    V, F = open_grid(6, 4)
    petersen.write_mesh(tmp_path / "g.obj", V, F[:-1])
    mesh = petersen.read_mesh(tmp_path / "g.obj")
    petersen.render(tmp_path / "mesh.png", mesh, width=240, height=200)
    r = petersen.quadrangulate(mesh, all_quad=True)
    assert r.first_added_vertex == len(V) < len(r.V)
    petersen.render(tmp_path / "result.png", r, width=240, height=200)
    for name in ("mesh.png", "result.png"):
        assert (tmp_path / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        petersen.render(tmp_path / "shape.svg", TrimeshLike(V, F))
