"""petersen.distributed on a real Dask cluster (three worker processes): a closed mesh of 10^6
triangles, its output checked here with numpy alone, and a worker killed while the parts run."""

import json
import logging
import math
import os
import pathlib
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import petersen
from conftest import chamfered_cubes, open_grid, torus

distributed = pytest.importorskip("distributed")

import petersen.distributed as pd  # noqa: E402  (after the skip: it needs no dask, its test does)

# 2 * 1224 * 408 = 998,784 triangles: a closed torus of genus 1.
NU, NV = 1224, 408
RUN_TIMEOUT = 240  # seconds; a hung cluster fails the test instead of hanging CI


def scan_ordered_torus(tmp_path_factory, nu, nv):
    """A closed torus written as a PLY, the two triangles of each grid square side by side and
    the squares row by row: faces in scan order, so that a range of faces is a patch (as scanners
    and subdivisions store them)."""
    V, F = torus(nu, nv)
    F = F.reshape(2, -1, 3).transpose(1, 0, 2).reshape(-1, 3)
    path = tmp_path_factory.mktemp("dask") / "torus.ply"
    petersen.write_mesh(str(path), V, F)
    return path, V, F


@pytest.fixture(scope="module")
def mesh(tmp_path_factory):
    return scan_ordered_torus(tmp_path_factory, NU, NV)


@pytest.fixture(scope="module")
def small_mesh(tmp_path_factory):
    return scan_ordered_torus(tmp_path_factory, 240, 80)


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=3, processes=True, threads_per_worker=1,
                                       dashboard_address=None, silence_logs=logging.CRITICAL)
    try:
        with distributed.Client(cluster) as c:
            c.wait_for_workers(3, timeout=60)
            yield c
    finally:
        cluster.close(timeout=30)


def run(fn, *args, **kwargs):
    """fn(*args, **kwargs) in a thread, failing the test after RUN_TIMEOUT seconds."""
    box = {}

    def target():
        try:
            box["value"] = fn(*args, **kwargs)
        except BaseException as e:  # handed to the test's thread
            box["error"] = e

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    return thread, box


def finish(thread, box):
    thread.join(RUN_TIMEOUT)
    assert not thread.is_alive(), f"the distributed run took more than {RUN_TIMEOUT} s"
    if "error" in box:
        raise box["error"]
    return box["value"]


def read_ply_faces(path):
    """The output as numpy reads it: vertex bytes, (k, 4) quads and (t, 3) triangles, from the
    header's counts and the uchar-counted records (one run of 17-byte quad records when the size
    says every face is a quad)."""
    data = np.fromfile(path, np.uint8)
    end = bytes(data[:4096]).index(b"end_header\n") + len("end_header\n")
    header = bytes(data[:end]).decode().split("\n")
    n = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
    m = int(next(line.split()[2] for line in header if line.startswith("element face")))
    assert "property list uchar uint vertex_indices" in header
    vertex_bytes = data[end:end + 24 * n]
    faces = data[end + 24 * n:]
    if faces.size == 17 * m:
        records = faces.view(np.dtype([("n", "u1"), ("v", "<u4", (4,))]))
        assert (records["n"] == 4).all()
        return vertex_bytes, records["v"].astype(np.int64), np.zeros((0, 3), np.int64)
    quads, triangles, at = [], [], 0
    for _ in range(m):
        k = int(faces[at])
        assert k in (3, 4)
        (quads if k == 4 else triangles).append(faces[at + 1:at + 1 + 4 * k].view("<u4"))
        at += 1 + 4 * k
    assert at == faces.size
    return (vertex_bytes, np.array(quads, np.int64).reshape(-1, 4),
            np.array(triangles, np.int64).reshape(-1, 3))


def input_vertex_bytes(path, n):
    data = np.fromfile(path, np.uint8)
    end = bytes(data[:4096]).index(b"end_header\n") + len("end_header\n")
    return data[end:end + 24 * n]


def check_faces(quads, triangles, F):
    """Every input triangle in exactly one output face, each quad the union of two input
    triangles sharing an edge (its diagonal), each triangle an input triangle: looked up among
    the input's triangles by sorted corners."""
    def key(a, b, c):
        t = np.sort(np.stack([a, b, c], axis=1), axis=1)
        return (t[:, 0] << 42) | (t[:, 1] << 21) | t[:, 2]

    keys = key(F[:, 0], F[:, 1], F[:, 2])
    order = np.argsort(keys)
    sorted_keys = keys[order]

    def lookup(k):
        at = np.minimum(np.searchsorted(sorted_keys, k), len(sorted_keys) - 1)
        return np.where(sorted_keys[at] == k, order[at], -1)

    q = quads
    assert (np.sort(q, axis=1)[:, 1:] != np.sort(q, axis=1)[:, :-1]).all(), "4 distinct corners"
    by_02 = lookup(key(q[:, 0], q[:, 1], q[:, 2])), lookup(key(q[:, 0], q[:, 2], q[:, 3]))
    by_13 = lookup(key(q[:, 1], q[:, 2], q[:, 3])), lookup(key(q[:, 1], q[:, 3], q[:, 0]))
    ok_02 = (by_02[0] >= 0) & (by_02[1] >= 0)
    ok_13 = (by_13[0] >= 0) & (by_13[1] >= 0)
    assert (ok_02 | ok_13).all(), "each quad is two input triangles sharing its diagonal"
    first = np.where(ok_02, by_02[0], by_13[0])
    second = np.where(ok_02, by_02[1], by_13[1])
    left = lookup(key(triangles[:, 0], triangles[:, 1], triangles[:, 2]))
    assert (left >= 0).all(), "each triangle written is an input triangle"
    cover = np.bincount(np.concatenate([first, second, left]), minlength=len(F))
    assert (cover == 1).all(), "every input triangle in exactly one output face"


@pytest.fixture(scope="module")
def in_memory(mesh):
    _, V, F = mesh
    return petersen.quadrangulate(V, F)


def check_run(stats, out, mesh, in_memory):
    """The output checked with numpy against the input, and sized as the in-memory run's."""
    path, V, F = mesh
    vertex_bytes, quads, triangles = read_ply_faces(out)
    assert np.array_equal(vertex_bytes, input_vertex_bytes(path, len(V))), "vertices unchanged"
    check_faces(quads, triangles, F)
    assert len(quads) == len(in_memory.quads) == stats["pairs"]
    assert len(triangles) == stats["triangles_left"] == in_memory.stats["triangles_left"]
    assert stats["maximum_certified"] is (len(triangles) == 0)
    for key in ("faces_in", "vertices", "triangles"):
        assert stats[key] == in_memory.stats[key], key


def test_closed_mesh_of_a_million_triangles(mesh, client, in_memory, tmp_path):
    out = tmp_path / "quads.ply"
    stats = finish(*run(pd.quadrangulate, str(mesh[0]), str(out), client, parts=3,
                        objective="pairs"))
    check_run(stats, out, mesh, in_memory)
    assert stats["triangles_left"] == 0
    assert stats["parts"] == 3 and stats["part_cut_edges"] > 0
    assert not list(tmp_path.glob("*.tmp-*")), "the temporary file was renamed"


def test_parts_left_unpaired_are_paired_across_the_cuts(small_mesh, client, tmp_path):
    # Parts of odd sizes: each leaves a triangle the repair must pair across a cut.
    out = tmp_path / "quads.ply"
    m = len(small_mesh[2])
    bounds = [0, m // 4 + 1, m // 2, 3 * m // 4 + 1, m]
    stats = finish(*run(pd.quadrangulate, str(small_mesh[0]), str(out), client, parts=bounds,
                        objective="pairs"))
    check_run(stats, out, small_mesh, petersen.quadrangulate(small_mesh[1], small_mesh[2]))
    assert stats["unpaired_after_parts"] >= 4 and stats["parts_certified"] is True
    assert stats["repair_unpaired_before"] == stats["unpaired_after_parts"]
    assert stats["repair_augmenting_paths"] * 2 == stats["unpaired_after_parts"]
    assert stats["repair_unpaired_after"] == 0


def test_an_open_mesh_keeps_the_triangles_no_pairing_takes(client, tmp_path):
    # A grid with three triangles cut out: an odd count, so triangles stay; the bands reach over
    # the whole of this small mesh, so the pairing is as large as the in-memory one.
    V, F = open_grid(40, 30)
    F = np.delete(F, [5, 700, 1333], axis=0)
    path, out = tmp_path / "grid.ply", tmp_path / "quads.ply"
    petersen.write_mesh(str(path), V, F)
    stats = finish(*run(pd.quadrangulate, str(path), str(out), client, parts=3,
                        objective="pairs"))
    check_run(stats, out, (path, V, F), petersen.quadrangulate(V, F, objective="pairs"))
    assert stats["triangles_left"] > 0 and stats["boundary_edges"] > 0


@pytest.fixture(scope="module")
def jittered_open_grid(tmp_path_factory):
    """An open grid whose points are moved at random in its plane, with faces cut out: quads of
    many shapes, a boundary and holes."""
    V, F = open_grid(60, 40)
    rng = np.random.default_rng(5)
    V = V + rng.uniform(-0.2, 0.2, V.shape) * [1, 1, 0]
    F = np.delete(F, rng.choice(len(F), 40, replace=False), axis=0)
    path = tmp_path_factory.mktemp("dask") / "jittered.ply"
    petersen.write_mesh(str(path), V, F)
    return path, V, F


@pytest.mark.parametrize("which", ["jittered_open_grid", "small_mesh"])
def test_the_default_objective_is_bounded_by_the_in_memory_optimum(which, request, client,
                                                                    tmp_path):
    # Each part by its certified least-cost pairing, then the seams: the stitched lower bound is
    # at most the in-memory optimum, which is at most the total found.
    mesh = request.getfixturevalue(which)
    path, V, F = mesh
    out = tmp_path / "quads.ply"
    stats = finish(*run(pd.quadrangulate, str(path), str(out), client, parts=4))
    vertex_bytes, quads, triangles = read_ply_faces(out)
    assert np.array_equal(vertex_bytes, input_vertex_bytes(path, len(V))), "vertices unchanged"
    check_faces(quads, triangles, F)
    assert len(quads) == stats["pairs"] and len(triangles) == stats["triangles_left"]
    assert stats["objective"] == "quads" and stats["costs_certified"] is True
    assert stats["input"] == str(path) and stats["output"] == str(out)
    # The written quads' worst corners, measured here on the positions as read: the nearest
    # rank of the costs binned per 1/1024 degree, the non-convex count exact.
    cost = np.sort(petersen.quad_quality(petersen.read_mesh(str(path)).V, quads))
    binned = np.floor(cost * 1024) / 1024
    rank = lambda p: max(1, math.ceil(p * len(cost))) - 1  # noqa: E731
    assert stats["quality_median"] == binned[rank(0.5)] > 0
    assert stats["quality_p95"] == binned[rank(0.95)]
    assert stats["nonconvex_quads"] == int((cost > 90).sum())
    memory = petersen.quadrangulate(V, F)
    assert memory.stats["optimality_certified"]
    optimum = memory.stats["objective_total"]
    assert stats["lower_bound"] <= optimum + 1e-6
    assert optimum <= stats["objective_total"] + 1e-6
    assert stats["gap"] == pytest.approx(stats["objective_total"] - stats["lower_bound"])
    assert stats["optimality_certified"] is (stats["gap"] == 0)
    assert stats["parts"] == 4 and stats["part_cut_edges"] > 0
    quality = finish(*run(pd.quadrangulate, str(path), str(out), client, parts=4,
                          objective="quality", max_corner_deviation=40.0))
    _, quads, triangles = read_ply_faces(out)
    check_faces(quads, triangles, F)
    assert quality["objective"] == "quality" and quality["optimality_certified"] is False
    assert "lower_bound" not in quality and len(quads) == quality["pairs"]


def test_a_worker_killed_mid_run_costs_a_retry(mesh, client, in_memory, tmp_path):
    pids = client.run(os.getpid)
    out = tmp_path / "quads.ply"
    thread, box = run(pd.quadrangulate, str(mesh[0]), str(out), client, parts=6,
                      objective="pairs")
    victim = None
    deadline = time.monotonic() + RUN_TIMEOUT
    while victim is None and thread.is_alive() and time.monotonic() < deadline:
        for address, keys in client.processing().items():
            if any("_pair_part" in str(k) for k in keys) and address in pids:
                victim = pids[address]
                break
        time.sleep(0.01)
    assert victim is not None, "no part was seen running"
    os.kill(victim, signal.SIGKILL)
    stats = finish(thread, box)
    check_run(stats, out, mesh, in_memory)
    with pytest.raises(ProcessLookupError):
        os.kill(victim, 0)
    assert victim not in client.run(os.getpid).values()


def test_bad_input_is_named(client, tmp_path):
    path = tmp_path / "quad.ply"
    petersen.write_mesh(str(path), np.eye(4, 3), np.array([[0, 1, 2, 3]]))
    with pytest.raises(ValueError, match="quad.ply"):
        pd.quadrangulate(str(path), str(tmp_path / "out.ply"), client, parts=2)
    text = tmp_path / "text.off"
    petersen.write_mesh(str(text), np.eye(3), np.array([[0, 1, 2]]))
    with pytest.raises(ValueError, match="not a PLY"):
        pd.quadrangulate(str(text), str(tmp_path / "out.ply"), client)
    with pytest.raises(TypeError, match="flow_weight.*augment, objective"):
        pd.quadrangulate(str(text), str(tmp_path / "out.ply"), client, flow_weight=2)
    with pytest.raises(TypeError, match="triangle_cost.*all_quad"):
        pd.quadrangulate(str(text), str(tmp_path / "out.ply"), client, all_quad=True,
                         triangle_cost=30)
    with pytest.raises(TypeError, match="sharp_angle.*objective pairs"):
        pd.quadrangulate(str(text), str(tmp_path / "out.ply"), client, objective="pairs",
                         sharp_angle=30)
    with pytest.raises(TypeError, match="triangle_cost.*objective quality"):
        pd.quadrangulate(str(text), str(tmp_path / "out.ply"), client, objective="quality",
                         triangle_cost=30)
    assert not (tmp_path / "out.ply").exists()


def test_the_layout_is_the_library_readers_and_a_face_property_is_refused(tmp_path):
    # The header is read by the library's PLY reader (as `petersen quad --memory-limit` reads it):
    # the offsets frame the vertex block exactly, and the faces and positions read back are the
    # ones written.
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5]], np.float64)
    F = np.array([[0, 1, 2], [2, 1, 3]])
    path = tmp_path / "two.ply"
    petersen.write_mesh(str(path), V, F)
    layout = pd.read_layout(str(path))
    assert (layout.vertex_count, layout.face_count) == (4, 2)
    data = path.read_bytes()
    assert data[:layout.vertex_offset].endswith(b"end_header\n")
    assert layout.face_offset - layout.vertex_offset == 4 * 3 * 8  # x, y, z as double
    assert len(data) == layout.face_offset + 2 * 13
    assert layout.vertex_header[0] == "element vertex 4"
    assert pd._read_faces(layout, 1, 2).tolist() == [[2, 1, 3]]
    assert np.array_equal(pd._corner_positions(layout, F), V[F])
    # A face property the output could not carry is refused, naming it, not read past.
    header = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
              b"property float y\nproperty float z\nelement face 1\n"
              b"property list uchar int vertex_indices\nproperty uchar quality\nend_header\n")
    body = np.eye(3, dtype="<f4").tobytes() + bytes([3]) + np.arange(3, dtype="<i4").tobytes()
    with_property = tmp_path / "quality.ply"
    with_property.write_bytes(header + body + bytes([7]))
    with pytest.raises(ValueError, match="quality.ply.*face properties besides"):
        pd.read_layout(str(with_property))


def test_the_write_stage_quads_follow_the_first_triangle_and_refuse_a_non_pair():
    # (0, 1, 2) and (1, 0, 3) share the first's side 0-1: the quad (0, 3, 1, 2) runs the first's
    # way; (5, 6, 7) and (6, 7, 8) share its side 6-7, which starts the quad (6, 8, 7, 5).
    quads = petersen._petersen.quads_of_pairs(np.array([[0, 1, 2], [5, 6, 7]]),
                                              np.array([[1, 0, 3], [6, 7, 8]]))
    assert quads.tolist() == [[0, 3, 1, 2], [6, 8, 7, 5]]
    with pytest.raises(RuntimeError, match=r"\(0, 1, 2\) and \(0, 1, 2\) share no single edge"):
        petersen._petersen.quads_of_pairs(np.array([[0, 1, 2]]), np.array([[0, 1, 2]]))
    with pytest.raises(ValueError, match="as many rows"):
        petersen._petersen.quads_of_pairs(np.zeros((2, 3), np.int64), np.zeros((1, 3), np.int64))


def out_of_core_bounds(face_count, part_triangles):
    """The parts `petersen quad --memory-limit --part-triangles N` makes (out_of_core.cpp,
    part_size): as many as N-sized parts need, of equal even size."""
    parts = -(-face_count // part_triangles)
    size = -(-face_count // parts)
    size += size % 2
    return list(range(0, face_count, size)) + [face_count]


def after_header(path):
    data = pathlib.Path(path).read_bytes()
    return data[data.index(b"end_header\n") + len(b"end_header\n"):]


ALL_QUAD_KEYS = ("added_vertices", "split_edges", "centre_vertices", "degenerate_faces",
                 "all_quad_parts", "all_quad_parts_certified", "all_quad_certified",
                 "split_quads", "faces_out", "pairs", "triangles_left", "parts")


@pytest.fixture(scope="module")
def jittered_torus(tmp_path_factory):
    """A closed torus in scan order whose points are moved at random: with a corner threshold
    many triangles stay unpaired, and all_quad splits them on a surface with no boundary."""
    V, F = torus(120, 40)
    V = V + np.random.default_rng(3).uniform(-0.05, 0.05, V.shape)
    F = F.reshape(2, -1, 3).transpose(1, 0, 2).reshape(-1, 3)
    path = tmp_path_factory.mktemp("dask") / "jittered_torus.ply"
    petersen.write_mesh(str(path), V, F)
    return path, V, F


@pytest.mark.parametrize("options", [{}, {"max_corner_deviation": 30}], ids=["default", "mcd30"])
@pytest.mark.parametrize("which", ["jittered_open_grid", "jittered_torus"])
def test_all_quad_part_by_part_is_the_out_of_core_conversion(which, options, request, client,
                                                             cli, tmp_path):
    # The same parts as `petersen quad --memory-limit 1G --part-triangles N --all-quad`: the
    # same pairing, the same seams and plans, hence the same file after the header (which names
    # its writer); every face a quad, the input's vertices first and unmoved.
    path, V, F = request.getfixturevalue(which)
    n = len(F)
    part_triangles = n // 4 + 2
    bounds = out_of_core_bounds(n, part_triangles)
    out = tmp_path / "dask.ply"
    stats = finish(*run(pd.quadrangulate, str(path), str(out), client, parts=bounds,
                        all_quad=True, keep_polygons=True, **options))
    mesh = petersen.read_mesh(str(out))
    source = petersen.read_mesh(str(path))
    assert np.asarray(mesh.F).ndim == 2 and np.asarray(mesh.F).shape[1] == 4, "all quads"
    assert len(mesh.F) == stats["faces_out"]
    assert len(mesh.V) == len(V) + stats["added_vertices"]
    assert np.array_equal(mesh.V[:len(V)], source.V), "the input's vertices first, unmoved"
    assert stats["added_vertices"] == stats["split_edges"] + stats["centre_vertices"]
    assert stats["all_quad_certified"] is False and stats["all_quad_parts_certified"] is True
    assert stats["parts"] == stats["all_quad_parts"] == len(bounds) - 1 >= 4
    assert stats["degenerate_faces"] == 0 and not list(tmp_path.glob("*.tmp-*"))

    flags = [f"--max-corner-deviation={options['max_corner_deviation']}"] if options else []
    reference, figures = tmp_path / "ooc.ply", tmp_path / "ooc.json"
    subprocess.run([cli, "quad", str(path), str(reference), "--memory-limit", "1G",
                    "--part-triangles", str(part_triangles), "--all-quad", "--stats-json",
                    str(figures)] + flags, check=True, capture_output=True, timeout=RUN_TIMEOUT)
    ooc = json.loads(figures.read_text())
    assert after_header(out) == after_header(reference), "the out-of-core file, byte for byte"
    for key in ALL_QUAD_KEYS:
        assert stats[key] == ooc[key], key
    for key in ("split_quality_median", "split_quality_p95"):
        assert stats[key] == pytest.approx(ooc[key], abs=1e-3), key
    # The pairing's quads measured as out of core measures them: the same binned figures.
    for key in ("quality_median", "quality_p95", "nonconvex_quads"):
        assert stats[key] == ooc[key], key

    memory = petersen.quadrangulate(V, F, all_quad=True, **options)
    print(f"{which} {options}: added vertices dask {stats['added_vertices']}, out of core "
          f"{ooc['added_vertices']}, in memory {memory.stats['added_vertices']} "
          f"(minimum {memory.stats.get('added_vertices_minimum')})")

    check = pathlib.Path(cli).resolve().parent.parent / "tests/partition/petersen_check_quads"
    if check.is_file():
        result = subprocess.run([str(check), str(path), str(out)], capture_output=True,
                                text=True, timeout=RUN_TIMEOUT)
        assert result.returncode == 0, result.stderr
        assert "all quads" in result.stdout or "a quad mesh of the same surface" in result.stdout


def test_all_quad_without_parts_of_the_out_of_core_sizes_is_all_quads(jittered_open_grid, client,
                                                                       tmp_path):
    # Parts of odd sizes (the pairing's repair pairs across the cuts), objective pairs: still
    # every face a quad, and the counts the statistics give.
    path, V, F = jittered_open_grid
    m = len(F)
    out = tmp_path / "quads.ply"
    stats = finish(*run(pd.quadrangulate, str(path), str(out), client, objective="pairs",
                        parts=[0, m // 3 + 1, 2 * m // 3 - 1, m], all_quad=True))
    mesh = petersen.read_mesh(str(out))
    assert np.asarray(mesh.F).shape == (stats["faces_out"], 4)
    assert len(mesh.V) == len(V) + stats["added_vertices"]
    assert np.array_equal(mesh.V[:len(V)], petersen.read_mesh(str(path)).V)
    assert stats["all_quad_parts"] == 3 and stats["all_quad_parts_certified"] is True


def test_own_triangles_beside_the_cuts_are_priced_as_in_memory(client, cli, tmp_path):
    # A model's own triangles (the cubes' corners) may stay for less than the price; a part sees
    # the pairs across its cuts only in the seam step, which prices them again: every cube comes
    # back whole with its corners left, at the in-memory optimum.
    V, F = chamfered_cubes(cli, tmp_path, 12)
    path, out = tmp_path / "cubes.ply", tmp_path / "quads.ply"
    petersen.write_mesh(str(path), V, F)
    memory = petersen.quadrangulate(V, F)
    assert memory.stats["optimality_certified"] and memory.stats["triangles_left"] == 8 * 12
    stats = finish(*run(pd.quadrangulate, str(path), str(out), client, parts=5))
    _, quads, triangles = read_ply_faces(out)
    check_faces(quads, triangles, F)
    assert stats["parts"] == 5 and stats["part_cut_edges"] > 0
    assert len(triangles) == stats["triangles_left"] == 8 * 12
    assert stats["objective_total"] == pytest.approx(memory.stats["objective_total"], abs=1e-6)
    assert stats["lower_bound"] <= memory.stats["objective_total"] + 1e-6


def test_a_band_too_thin_for_the_seams_prices_is_refused_before_any_work(client, tmp_path):
    with pytest.raises(ValueError, match="band_radius >= 3, not 2"):
        pd.quadrangulate(str(tmp_path / "absent.ply"), str(tmp_path / "out.ply"), client,
                         band_radius=2)
    assert not (tmp_path / "out.ply").exists()
