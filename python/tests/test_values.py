"""Bad values are refused with a ValueError that names them: coordinates that are not finite
(from arrays and from the other libraries' meshes), options out of their range, a mesh with no
faces. And the stats say which attribute cuts left many triangles, with the ``cross`` that lets
pairs cross them."""

import math

import numpy as np
import pytest

import petersen
from conftest import PolyDataLike, TrimeshLike, octahedron, open_grid, torus


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_non_finite_coordinates_name_the_vertex(bad, tmp_path):
    V, F = octahedron()
    V[4, 2] = bad
    with pytest.raises(ValueError, match=r"vertex 4 has a coordinate that is not finite"):
        petersen.quadrangulate(V, F)
    with pytest.raises(ValueError, match=r"vertex 4 "):
        petersen.write_mesh(tmp_path / "x.obj", V, F)
    with pytest.raises(ValueError, match=r"vertex 4 "):
        petersen.quad_quality(V, [[0, 2, 4, 1]])
    assert not (tmp_path / "x.obj").exists()
    # float32 arrays too: converted first, checked after.
    with pytest.raises(ValueError, match=r"vertex 4 "):
        petersen.quadrangulate(V.astype(np.float32), F)


def test_non_finite_coordinates_from_other_libraries():
    V, F = octahedron()
    V[1, 0] = math.nan
    with pytest.raises(ValueError, match=r"vertex 1 "):
        petersen.quadrangulate(TrimeshLike(V, F))
    padded = np.hstack([np.full((len(F), 1), 3), F]).ravel()
    with pytest.raises(ValueError, match=r"vertex 1 "):
        petersen.quadrangulate(PolyDataLike(V, padded))
    meshio = pytest.importorskip("meshio")
    with pytest.raises(ValueError, match=r"vertex 1 "):
        petersen.quadrangulate(meshio.Mesh(V, [("triangle", F)]))


def test_non_finite_coordinates_of_a_file(tmp_path):
    path = tmp_path / "nan.off"
    path.write_text("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n")
    with pytest.raises(ValueError, match=r"nan.off:4: vertex 1"):
        petersen.read_mesh(path)


@pytest.mark.parametrize("keyword, value, range_text", [
    ("max_corner_deviation", math.nan, r"\[0, 270\]"),
    ("max_corner_deviation", -1.0, r"\[0, 270\]"),
    ("max_corner_deviation", 270.5, r"\[0, 270\]"),
    ("max_corner_deviation", math.inf, r"\[0, 270\]"),
    ("sharp_angle", 181, r"\[0, 180\]"),
    ("sharp_angle", -math.inf, r"\[0, 180\]"),
])
def test_angles_out_of_range_name_the_keyword(keyword, value, range_text):
    V, F = open_grid(3, 3)
    with pytest.raises(ValueError, match=f"{keyword} must be a finite number of degrees in "
                       f"{range_text}, not {value!r}"):
        petersen.quadrangulate(V, F, **{keyword: value})


def test_angles_at_the_ends_of_their_ranges_are_accepted():
    V, F = open_grid(3, 3)
    every = petersen.quadrangulate(V, F, max_corner_deviation=270, sharp_angle=180)
    assert every.stats["pairs"] == petersen.quadrangulate(V, F).stats["pairs"]
    squares = petersen.quadrangulate(V, F, max_corner_deviation=0, sharp_angle=0)
    assert squares.stats["maximum_certified"]
    with pytest.raises(TypeError, match="sharp_angle"):
        petersen.quadrangulate(V, F, sharp_angle="30")


def test_threads_above_the_limit_are_refused():
    V, F = open_grid(3, 3)
    with pytest.raises(ValueError, match=r"threads must be 0 \(every core\) or at most 1024, "
                       r"not 1025"):
        petersen.quadrangulate(V, F, threads=1025)
    with pytest.raises(ValueError, match="threads"):
        petersen.quadrangulate(V, F, threads=-1)


@pytest.mark.parametrize("V, F", [
    (np.zeros((0, 3)), np.zeros((0, 3), np.int64)),
    (np.zeros((4, 3)), np.zeros((0, 3), np.int64)),
    (np.zeros((4, 3)), []),
])
def test_a_mesh_with_no_faces_is_refused(V, F):
    with pytest.raises(ValueError, match=r"quadrangulate: the mesh has no faces \(\d+ vertices\)"):
        petersen.quadrangulate(V, F)


def test_empty_objects_of_other_libraries_are_refused():
    with pytest.raises(ValueError, match="no faces"):
        petersen.quadrangulate(TrimeshLike(np.zeros((0, 3)), np.zeros((0, 3), np.int64)))
    with pytest.raises(ValueError, match="no faces"):
        petersen.quadrangulate(PolyDataLike(np.zeros((0, 3)), np.zeros(0, np.int64)))


def two_material_square():
    """A square of two triangles in two materials: the border between them is a cut."""
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    attributes = {"material_names": ["a", "b"], "face_material": np.array([0, 1])}
    return V, F, attributes


def test_stats_say_which_cuts_left_the_triangles():
    V, F, attributes = two_material_square()
    r = petersen.quadrangulate(V, F, attributes=attributes)
    assert r.stats["triangles_left"] == 2
    assert r.stats["cross_to_pair"] == {"material": 1}
    crossed = petersen.quadrangulate(V, F, attributes=attributes,
                                     cross=list(r.stats["cross_to_pair"]))
    assert crossed.stats["triangles_left"] == 0 and len(crossed.quads) == 1
    assert "cross_to_pair" not in crossed.stats
    # Without the attributes nothing is cut, nothing is left, nothing to explain.
    assert "cross_to_pair" not in petersen.quadrangulate(V, F).stats


def flat_shaded_obj(path, V, F):
    """An OBJ whose every triangle has its own geometric normal at its three corners (flat
    shading: each face its own ``vn``), and nothing else besides positions and faces."""
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in V]
    for f, (a, b, c) in enumerate(F):
        n = np.cross(V[b] - V[a], V[c] - V[a])
        n /= np.linalg.norm(n)
        lines.append(f"vn {n[0]!r} {n[1]!r} {n[2]!r}")
    lines += [f"f {a + 1}//{f + 1} {b + 1}//{f + 1} {c + 1}//{f + 1}"
              for f, (a, b, c) in enumerate(F)]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("objective", ["pairs", "quality"])
def test_a_mesh_and_its_arrays_give_the_same_pairs_when_flat_shaded(objective, tmp_path):
    """quadrangulate(mesh) differs from quadrangulate(mesh.V, mesh.F) only by the cuts of the
    mesh's attributes; flat shading makes none, so the pairs are the same."""
    V, F = torus(12, 6)
    flat_shaded_obj(tmp_path / "flat.obj", V, F)
    mesh = petersen.read_mesh(tmp_path / "flat.obj")
    assert "corner_normal" in mesh.attributes
    with_attributes = petersen.quadrangulate(mesh, objective=objective)
    arrays_only = petersen.quadrangulate(mesh.V, mesh.F, objective=objective)
    assert with_attributes.stats["cut_edges"] == 0
    np.testing.assert_array_equal(with_attributes.quads, arrays_only.quads)
    np.testing.assert_array_equal(with_attributes.sources, arrays_only.sources)
    assert with_attributes.stats["triangles_left"] == arrays_only.stats["triangles_left"] == 0
    # One corner normal turned away from its triangle's normal: that triangle is no longer flat
    # shaded, and the normals its neighbours give the ends of its three edges differ from its
    # own, so all three are normal seams.
    smooth = dict(mesh.attributes)
    smooth["normals"] = np.vstack([mesh.attributes["normals"], [[0.0, 0.0, 1.0]]])
    corner_normal = np.array(smooth["corner_normal"])
    corner_normal[0] = len(smooth["normals"]) - 1
    smooth["corner_normal"] = corner_normal
    seamed = petersen.quadrangulate(mesh.V, mesh.F, attributes=smooth, objective=objective)
    assert seamed.stats["cut_edges_by_cause"]["normal_seam"] == 3


def test_a_threshold_with_quality_keeps_the_best_shapes():
    """docs/cli.md's torus: at 45 degrees any pairing within the threshold (objective "pairs",
    the threshold's default) makes far worse quads than the cheapest one, which is the same as
    with no threshold at all."""
    V, F = torus(48, 16)
    best = petersen.quadrangulate(V, F, objective="quality")
    within = petersen.quadrangulate(V, F, max_corner_deviation=45, objective="quality")
    anyhow = petersen.quadrangulate(V, F, max_corner_deviation=45, objective="pairs")
    for r in (within, anyhow):
        assert r.stats["triangles_left"] == 0 and r.stats["maximum_certified"]
        assert petersen.quad_quality(r.V, r.quads).max() <= 45
    assert within.stats["optimality_certified"]
    assert within.stats["quality_p95"] == pytest.approx(best.stats["quality_p95"])
    assert within.stats["objective_total"] == pytest.approx(best.stats["objective_total"])
    assert anyhow.stats["quality_p95"] > 10 * within.stats["quality_p95"]
