"""petersen.quadrangulate on meshes made in numpy, every algorithm, checked by checks.py."""

import numpy as np
import pytest

import petersen
from checks import check_result
from conftest import octahedron, open_grid, torus


def as_faces(F):
    return [tuple(int(v) for v in f) for f in F]


@pytest.mark.parametrize("algorithm", petersen.ALGORITHMS)
def test_closed_meshes_become_all_quads(algorithm):
    for V, F in (octahedron(), torus(12, 9)):
        r = petersen.quadrangulate(V, F, objective="pairs", algorithm=algorithm)
        check_result(V, as_faces(F), r, lrs=algorithm == "lrs")
        assert r.stats["triangles_left"] == 0 and len(r.triangles) == 0
        assert len(r.quads) == len(F) // 2 == r.stats["pairs"]
        assert r.stats["algorithm"] == algorithm
        assert len(r.tutte_set) == 0


@pytest.mark.parametrize("algorithm", petersen.ALGORITHMS)
def test_an_open_grid_with_a_quad_and_a_pentagon(algorithm):
    V, F = open_grid(5, 4)
    faces = as_faces(F)
    # A quad and a pentagon on new vertices beside the grid, sharing an edge with each other.
    base = len(V)
    V = np.vstack([V, [[7, 0, 0], [8, 0, 0], [8, 1, 0], [7, 1, 0], [9, 0.5, 0], [9, 1.5, 0]]])
    faces += [(base, base + 1, base + 2, base + 3), (base + 1, base + 4, base + 5, base + 2, base + 3)]
    r = petersen.quadrangulate(V, faces, objective="pairs", algorithm=algorithm)
    check_result(V, faces, r, lrs=algorithm == "lrs")
    assert r.stats["polygons_kept"] == 2 and len(r.polygons) == 2
    assert r.stats["triangles_left"] == 0  # 40 triangles of a grid pair up
    assert r.stats["pairs"] == 20


def test_the_quality_objective_is_certified_and_no_worse():
    V, F = torus(16, 12)
    V = V + np.random.default_rng(5).normal(scale=0.05, size=V.shape)  # irregular quads
    pairs = petersen.quadrangulate(V, F, objective="pairs", algorithm="ps")
    best = petersen.quadrangulate(V, F, objective="quality")
    check_result(V, as_faces(F), best)
    assert best.stats["optimality_certified"] is True
    assert best.stats["algorithm"] == "min-cost" and best.stats["triangles_left"] == 0
    # The minimum total: no more than ps's total, summed here from the quads themselves.
    total = petersen.quad_quality(best.V, best.quads).sum()
    assert total <= petersen.quad_quality(pairs.V, pairs.quads).sum() + 1e-6
    assert total == pytest.approx(best.stats["objective_total"], rel=1e-3)
    with pytest.raises(ValueError, match="unknown objective"):
        petersen.quadrangulate(V, F, objective="beauty")


def test_a_threshold_leaves_triangles_rather_than_bad_quads():
    V, F = torus(16, 12)
    V = V + np.random.default_rng(5).normal(scale=0.05, size=V.shape)
    r = petersen.quadrangulate(V, F, objective="quality", max_corner_deviation=20)
    check_result(V, as_faces(F), r)
    assert r.stats["optimality_certified"] is True
    assert r.stats["max_corner_deviation"] == 20
    assert r.stats["cut_edges_by_cause"]["shape"] > 0 and r.stats["triangles_left"] > 0
    assert (petersen.quad_quality(r.V, r.quads) <= 20).all()


def test_all_quad_splits_an_odd_open_mesh():
    V, F = open_grid(3, 3)
    F = F[:-1]  # 17 triangles: one must be left, then split
    r = petersen.quadrangulate(V, F, objective="pairs")
    check_result(V, as_faces(F), r)
    assert r.stats["triangles_left"] == 1 and len(r.triangles) == 1
    assert len(r.tutte_set) == 0 or r.stats["triangles_left"] > 0
    q = petersen.quadrangulate(V, F, all_quad=True)
    check_result(V, as_faces(F), q, all_quad=True)
    assert len(q.triangles) == 0 and q.stats["added_vertices"] >= 1
    assert len(q.V) == len(V) + q.stats["added_vertices"]
    assert q.quads.max() < len(q.V)


def test_any_dtype_and_memory_order_gives_the_same_answer():
    V, F = torus(10, 7)
    ref = petersen.quadrangulate(V, F, seed=3)
    variants = [
        (np.asfortranarray(V), np.asfortranarray(F)),
        (V.astype(np.float32).astype(np.float64), F.astype(np.uint32)),
        (V.tolist(), F.astype(np.int16).tolist()),
        (V[::-1][::-1], np.hstack([F, F])[:, :3]),  # non-contiguous views
        (V, F.astype(np.uint64)),
    ]
    for V2, F2 in variants:
        r = petersen.quadrangulate(V2, F2, seed=3)
        assert np.array_equal(r.quads, ref.quads)
        assert np.array_equal(r.sources, ref.sources)
    # float32 positions are accepted and converted (same faces on this mesh).
    r = petersen.quadrangulate(V.astype(np.float32), F, seed=3)
    assert r.V.dtype == np.float64 and np.array_equal(r.quads, ref.quads)


def test_outputs_are_owned_arrays():
    V, F = octahedron()
    r = petersen.quadrangulate(V, F)
    for a in (r.V, r.quads, r.triangles, r.sources, r.tutte_set):
        assert isinstance(a, np.ndarray) and a.flags.owndata and a.flags.writeable


def test_threads_change_nothing():
    V, F = torus(40, 30)
    V = V + np.random.default_rng(3).normal(scale=0.05, size=V.shape)
    for objective in ("pairs", "quality"):
        one = petersen.quadrangulate(V, F, objective=objective, threads=1)
        two = petersen.quadrangulate(V, F, objective=objective, threads=2)
        every = petersen.quadrangulate(V, F, objective=objective)  # threads=0: every core
        for r in (two, every):
            assert np.array_equal(one.quads, r.quads) and np.array_equal(one.sources, r.sources)
            assert one.stats["pairs"] == r.stats["pairs"]
    numpy_count = petersen.quadrangulate(V, F, objective="quality", threads=np.int64(2))
    assert np.array_equal(numpy_count.quads, one.quads)
    with pytest.raises(ValueError, match="threads"):
        petersen.quadrangulate(V, F, threads=-1)
    with pytest.raises(TypeError, match="threads"):
        petersen.quadrangulate(V, F, threads=1.5)


def test_same_seed_same_answer_and_seeds_matter():
    V, F = torus(30, 20)
    a = petersen.quadrangulate(V, F, objective="pairs", algorithm="sg", seed=5)
    b = petersen.quadrangulate(V, F, objective="pairs", algorithm="sg", seed=5)
    assert np.array_equal(a.quads, b.quads)
    others = [petersen.quadrangulate(V, F, objective="pairs", algorithm="sg", seed=s).quads for s in (6, 7, 8)]
    assert any(not np.array_equal(a.quads, o) for o in others)


def test_stats_have_the_cli_keys_but_the_file_ones():
    V, F = octahedron()
    s = petersen.quadrangulate(V, F, objective="pairs", algorithm="lrs").stats
    for key in ("algorithm", "augment", "vertices", "faces_in", "triangles", "polygons_kept",
                "genus", "euler_characteristic", "components", "closed_components", "mesh_edges",
                "cut_edges", "cut_edges_by_cause", "inconsistent_edges", "check_seconds",
                "dual_seconds", "initial_seconds", "initial_paired_percent",
                "unpaired_after_initial", "augment_seconds", "matching_seconds",
                "augmenting_paths", "blossoms", "nodes_labelled", "reductions", "flipped_edges",
                "irreducible_vertices", "lrs_fallback_components", "verify_seconds",
                "maximum_certified", "pairs", "triangles_left", "quads_seconds", "added_vertices",
                "all_quad_seconds", "total_seconds"):
        assert key in s, key
    for key in ("input", "output", "load_seconds", "write_seconds"):
        assert key not in s
    assert s["genus"] == 0 and s["euler_characteristic"] == 2
    assert isinstance(s["cut_edges_by_cause"], dict) and s["cut_edges_by_cause"]["boundary"] == 0
    assert "augment" not in petersen.quadrangulate(V, F, objective="pairs", algorithm="ds").stats
    # The octahedron's dual is the cube, a bipartite graph: the ordered sweep (eight nodes are a
    # local numbering) or, where it leaves nodes, Schrijver's algorithm matches it perfectly.
    auto = petersen.quadrangulate(V, F, objective="pairs", algorithm="auto").stats
    assert auto["schrijver"] != auto["ordered_sweep"]
    assert auto["unpaired_after_initial"] == 0
    # ps is the paper's Puli-Segal alone: neither the sweep nor Schrijver's algorithm runs.
    ps = petersen.quadrangulate(V, F, objective="pairs", algorithm="ps").stats
    assert not ps["schrijver"] and not ps["ordered_sweep"]
    assert "schrijver" not in s and "ordered_sweep" not in s


def test_sharp_angle_and_keep_edges_cut_edges():
    V, F = octahedron()
    # Every dihedral angle of the octahedron is about 109.5 degrees between normals of 70.5:
    # a threshold of 60 cuts every edge, so nothing pairs.
    r = petersen.quadrangulate(V, F, sharp_angle=60)
    assert r.stats["pairs"] == 0 and r.stats["cut_edges_by_cause"]["sharp"] == 12
    # Keeping the four edges around the equator leaves two caps of four triangles each.
    r = petersen.quadrangulate(V, F, keep_edges=[[0, 2], [2, 1], [1, 3], [3, 0]])
    assert r.stats["cut_edges_by_cause"]["user"] == 4 and r.stats["pairs"] == 4
    check_result(V, as_faces(F), r)


def test_bad_input_raises_value_error_with_the_message():
    V, F = octahedron()
    with pytest.raises(ValueError, match="face 2"):
        petersen.quadrangulate(V, [[0, 1, 2], [1, 2, 3], [0, 1, 99]])
    with pytest.raises(ValueError, match="out of range"):
        petersen.quadrangulate(V, [[0, 1, -1]])
    with pytest.raises(ValueError, match="at least three"):
        petersen.quadrangulate(V, [[0, 1, 2], [0, 1]])
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        petersen.quadrangulate(V[:, :2], F)
    with pytest.raises(ValueError, match="unknown algorithm 'nope'"):
        petersen.quadrangulate(V, F, algorithm="nope")
    with pytest.raises(ValueError, match="unknown augment"):
        petersen.quadrangulate(V, F, augment="x")
    with pytest.raises(TypeError, match="integers"):
        petersen.quadrangulate(V, F.astype(float))


def test_a_weight_the_run_would_not_read_is_refused():
    V, F = open_grid(6, 5)
    # Given as the defaults, the weights give the default's answer.
    default = petersen.quadrangulate(V, F).stats
    given = petersen.quadrangulate(V, F, triangle_cost=90.0, flow_weight=0.0).stats
    assert (given["pairs"], given["objective_total"]) == (default["pairs"],
                                                          default["objective_total"])
    with pytest.raises(TypeError, match="triangle_cost.*objective 'quality' pairs the maximum"):
        petersen.quadrangulate(V, F, objective="quality", triangle_cost=40)
    with pytest.raises(TypeError, match="triangle_cost: with all_quad"):
        petersen.quadrangulate(V, F, all_quad=True, triangle_cost=40)
    with pytest.raises(TypeError, match="flow_weight.*not 'pairs'"):
        petersen.quadrangulate(V, F, objective="pairs", flow_weight=1)
