"""What a mesh carries besides positions and faces, through read_mesh, quadrangulate and
write_mesh: texture coordinates and normals per corner, materials and groups per face, PLY vertex
colours. The corner values of every quad are checked here against the triangles it came from."""

import subprocess

import numpy as np
import pytest

import petersen
from conftest import open_grid


def grid_obj(path, seam, uniform=False):
    """A 2 by 2 grid of squares (open_grid: faces 0-3 the squares' first triangles, 4-7 their
    second) as an OBJ with vt, vn, mtllib, usemtl and g. The triangles of `seam` (face ids) take
    their texture coordinates from a second copy shifted in u, so every edge between one of them
    and another triangle is a UV seam. The left column is material "red" in group "left", the
    right one "blue" in "right"; with `uniform` all is "skin" in "body"."""
    V, F = open_grid(2, 2)
    lines = ["mtllib grid.mtl"]
    lines += [f"v {x:g} {y:g} {z:g}" for x, y, z in V]
    lines += [f"vt {x / 2:g} {y / 2:g}" for x, y, _ in V]
    lines += [f"vt {x / 2 + 0.5:g} {y / 2:g}" for x, y, _ in V]
    lines += ["vn 0 0 1"]
    current = None
    for f, face in enumerate(F):
        names = ("skin", "body") if uniform else \
            ("red", "left") if f % 4 < 2 else ("blue", "right")
        if names != current:
            lines += [f"usemtl {names[0]}", f"g {names[1]}"]
            current = names
        shift = len(V) if f in seam else 0
        lines.append("f " + " ".join(f"{v + 1}/{v + 1 + shift}/1" for v in face))
    path.write_text("\n".join(lines) + "\n")


def corner_values(values, index, F):
    """For each face of F (a list), the value of each corner: values[index[corner]]."""
    out, start = [], 0
    for face in F:
        out.append([tuple(values[index[start + c]]) for c in range(len(face))])
        start += len(face)
    return out


def check_carried(mesh, r):
    """Every output face's corners have the texture coordinate and normal (where the mesh has
    them) of the source triangle corner at the same vertex (the first triangle's where both have
    the vertex), and its material and group are its first source's."""
    a, b = mesh.attributes, r.attributes
    in_faces = [list(f) for f in mesh.F]
    corner_keys = [(v, i) for v, i in (("texcoords", "corner_texcoord"),
                                       ("normals", "corner_normal")) if i in a]
    assert corner_keys and [i for _, i in corner_keys if i not in b] == []
    ins = [corner_values(a[v], a[i], in_faces) for v, i in corner_keys]
    outs = [corner_values(b[v], b[i], r.faces) for v, i in corner_keys]
    for k, (face, (t1, t2)) in enumerate(zip(r.faces, r.sources)):
        for c, v in enumerate(face):
            sources = [t for t in (t1, t2) if t >= 0 and v in in_faces[t]]
            assert sources, f"face {k} corner {c}: vertex {v} is in no source triangle"
            t = sources[0]
            tc = in_faces[t].index(v)
            for values_in, values_out in zip(ins, outs):
                assert values_out[k][c] == values_in[t][tc], (k, c)
        for names, ids in (("material_names", "face_material"), ("group_names", "face_group")):
            if ids in a:
                assert len(b[ids]) == len(r.faces)
                assert b[names][b[ids][k]] == a[names][a[ids][t1]], (k, ids)


def test_an_obj_round_trips_with_its_attributes(tmp_path):
    grid_obj(tmp_path / "g.obj", {0, 4})
    m = petersen.read_mesh(tmp_path / "g.obj")
    a = m.attributes
    assert a["texcoords"].shape == (18, 2) and a["normals"].tolist() == [[0, 0, 1]]
    assert a["material_names"] == ["red", "blue"] and a["group_names"] == ["left", "right"]
    assert a["face_material"].tolist() == [0, 0, 1, 1] * 2
    assert a["material_libraries"] == ["grid.mtl"]
    # Face 0 (vertices 0 3 4) takes the shifted copy (vt 9 onwards), face 2 (3 6 7) the first.
    assert a["corner_texcoord"][:3].tolist() == [9, 12, 13]
    assert a["corner_texcoord"][6:9].tolist() == [3, 6, 7]
    assert m.dropped == []
    assert petersen.write_mesh(tmp_path / "h.obj", m) == []
    back = petersen.read_mesh(tmp_path / "h.obj")
    assert np.array_equal(back.V, m.V) and np.array_equal(back.F, m.F)
    assert back.attributes.keys() == a.keys()
    for key, value in a.items():
        assert np.array_equal(back.attributes[key], value), key
    # PLY has no place for materials or groups: said, and warned.
    with pytest.warns(petersen.DroppedWarning, match="usemtl"):
        dropped = petersen.write_mesh(tmp_path / "h.ply", m.V, m.F, a)
    assert any("usemtl" in line for line in dropped)
    assert not any("vn" in line for line in dropped)
    ply = petersen.read_mesh(tmp_path / "h.ply")
    # The one normal every corner names is per vertex: it becomes PLY's nx ny nz.
    columns = ply.attributes["vertex_properties"]
    assert [columns[name].tolist() for name in ("nx", "ny", "nz")] == \
        [[0.0] * len(m.V), [0.0] * len(m.V), [1.0] * len(m.V)]
    # The corner texture coordinates survive by value (PLY's texcoord list).
    assert corner_values(ply.attributes["texcoords"], ply.attributes["corner_texcoord"],
                         list(ply.F)) == \
        corner_values(a["texcoords"], a["corner_texcoord"], list(m.F))


def test_quads_keep_their_triangles_corner_values(tmp_path):
    grid_obj(tmp_path / "g.obj", {0, 4})
    m = petersen.read_mesh(tmp_path / "g.obj")
    r = petersen.quadrangulate(m)
    # The column border is a material border (one of its edges is counted as a UV seam).
    assert len(r.quads) == 4 and r.stats["cut_edges_by_cause"]["material"] >= 1
    check_carried(m, r)
    written = petersen.write_mesh(tmp_path / "q.obj", r.V, r.faces, r.attributes)
    assert written == []
    back = petersen.read_mesh(tmp_path / "q.obj")
    assert corner_values(back.attributes["texcoords"], back.attributes["corner_texcoord"],
                         list(back.F)) == \
        corner_values(r.attributes["texcoords"], r.attributes["corner_texcoord"], r.faces)


def test_a_seam_is_not_crossed_unless_asked(tmp_path):
    # Faces 0 and 1 (the first triangles of the left column's squares) have every edge on the
    # seam, which leaves their partners 4 and 5 nothing to pair with either.
    grid_obj(tmp_path / "g.obj", {0, 1}, uniform=True)
    m = petersen.read_mesh(tmp_path / "g.obj")
    assert m.attributes["material_names"] == ["skin"]
    seam = {0, 1}
    r = petersen.quadrangulate(m)
    check_carried(m, r)
    assert r.stats["cut_edges_by_cause"]["uv_seam"] > 0
    assert all((s0 in seam) == (s1 in seam) for s0, s1 in r.sources if s1 >= 0)
    assert r.stats["triangles_left"] == 4
    assert sorted(r.sources[len(r.quads):, 0]) == [0, 1, 4, 5]
    crossed = petersen.quadrangulate(m, cross=["uv_seam"])
    check_carried(m, crossed)
    assert crossed.stats["triangles_left"] == 0
    assert any((s0 in seam) != (s1 in seam) for s0, s1 in crossed.sources)
    assert set(petersen.CROSSABLE) >= {"uv_seam", "normal_seam", "material", "group"}
    every = petersen.quadrangulate(m, cross=petersen.CROSSABLE)
    assert np.array_equal(every.quads, crossed.quads)
    # Without the attributes there is no seam; with them given explicitly, the same as the Mesh.
    plain = petersen.quadrangulate(m.V, m.F)
    assert plain.stats["triangles_left"] == 0 and plain.attributes == {}
    explicit = petersen.quadrangulate(m.V, m.F, attributes=m.attributes)
    assert np.array_equal(explicit.quads, r.quads)
    # The structure's cuts are never crossed; unknown names are refused.
    with pytest.raises(ValueError, match="boundary"):
        petersen.quadrangulate(m, cross=["boundary"])
    with pytest.raises(ValueError, match="unknown cause 'uv' .crossable: uv_seam, normal_seam"):
        petersen.quadrangulate(m, cross=["uv"])


def test_every_corner_its_own_value_through_quads_triangles_and_polygons():
    # 7 triangles of a grid (one is left) and a quad beside them, each corner with its own
    # random texture coordinate and normal: every edge a seam, crossed by request, so each quad
    # takes the shared edge's values from its first triangle. The output's attributes follow
    # r.faces (quads, the triangle left, the polygon), checked corner by corner.
    V, F = open_grid(2, 2)
    V = np.vstack([V, [[5, 0, 0], [6, 0, 0], [6, 1, 0], [5, 1, 0]]])
    faces = [[9, 10, 11, 12]] + [list(f) for f in F[:-1]]
    corners = sum(len(f) for f in faces)
    rng = np.random.default_rng(13)
    attributes = {
        "texcoords": rng.random((corners, 2)), "corner_texcoord": rng.permutation(corners),
        "normals": rng.random((corners, 3)), "corner_normal": rng.permutation(corners),
        "material_names": ["a", "b", "c"], "face_material": np.arange(len(faces)) % 3,
        "group_names": ["g"], "face_group": np.zeros(len(faces), int),
    }
    mesh = petersen.Mesh(V, [np.array(f) for f in faces], attributes)
    r = petersen.quadrangulate(mesh, cross=["uv_seam", "normal_seam", "material"])
    assert len(r.quads) == 3 and len(r.triangles) == 1 and len(r.polygons) == 1
    check_carried(mesh, r)
    assert len(r.attributes["corner_texcoord"]) == 3 * 4 + 3 + 4
    # Not crossed, the seams leave every triangle alone.
    alone = petersen.quadrangulate(mesh)
    assert len(alone.quads) == 0 and alone.stats["cut_edges_by_cause"]["uv_seam"] > 0
    check_carried(mesh, alone)


def test_a_ply_keeps_its_vertex_colours(tmp_path):
    V, F = open_grid(3, 2)
    rgb = (np.arange(len(V) * 3).reshape(-1, 3) * 7 % 256).astype(np.uint8)
    header = ["ply", "format ascii 1.0", f"element vertex {len(V)}", "property float x",
              "property float y", "property float z", "property uchar red", "property uchar green",
              "property uchar blue", f"element face {len(F)}",
              "property list uchar int vertex_indices", "end_header"]
    body = [f"{x:g} {y:g} {z:g} {r} {g} {b}" for (x, y, z), (r, g, b) in zip(V, rgb)]
    body += ["3 " + " ".join(str(v) for v in f) for f in F]
    (tmp_path / "c.ply").write_text("\n".join(header + body) + "\n")
    m = petersen.read_mesh(tmp_path / "c.ply")
    props = m.attributes["vertex_properties"]
    assert list(props) == ["red", "green", "blue"]
    assert all(props[k].dtype == np.uint8 for k in props)
    assert np.array_equal(np.stack([props["red"], props["green"], props["blue"]], 1), rgb)
    assert "position_type" not in m.attributes  # ascii positions keep their digits
    r = petersen.quadrangulate(m, all_quad=True)
    out = r.attributes["vertex_properties"]
    assert all(len(out[k]) == len(r.V) and out[k].dtype == np.uint8 for k in out)
    assert np.array_equal(np.stack([out[k][:len(V)] for k in ("red", "green", "blue")], 1), rgb)
    assert petersen.write_mesh(tmp_path / "q.ply", r.V, r.faces, r.attributes) == []
    back = petersen.read_mesh(tmp_path / "q.ply")
    for k in ("red", "green", "blue"):
        assert back.attributes["vertex_properties"][k].dtype == np.uint8
        assert np.array_equal(back.attributes["vertex_properties"][k], out[k])
    # A binary float PLY stays float.
    petersen.write_mesh(tmp_path / "f.ply", V, F, {"position_type": "float32"})
    assert petersen.read_mesh(tmp_path / "f.ply").attributes == {"position_type": "float32"}
    # Colours made in numpy (int64) are written as the nearest PLY type.
    made = {"vertex_properties": {"red": np.full(len(V), 200)}}
    petersen.write_mesh(tmp_path / "n.ply", V, F, made)
    assert petersen.read_mesh(tmp_path / "n.ply").attributes["vertex_properties"]["red"].tolist() \
        == [200] * len(V)


def test_bad_attributes_are_refused(tmp_path):
    V, F = open_grid(1, 1)
    with pytest.raises(ValueError, match="unknown attribute 'colour'"):
        petersen.write_mesh(tmp_path / "x.ply", V, F, {"colour": [1, 2, 3, 4]})
    with pytest.raises(ValueError):  # one value per vertex, not three
        petersen.write_mesh(tmp_path / "x.ply", V, F, {"vertex_properties": {"red": [1, 2, 3]}})
    with pytest.raises(ValueError, match="-1 means none"):
        petersen.quadrangulate(V, F, attributes={"face_material": [-2, 0],
                                                 "material_names": ["a"]})
    with pytest.raises(ValueError, match="texcoords"):
        petersen.quadrangulate(V, F, attributes={"texcoords": np.zeros((4, 5))})
    with pytest.raises(TypeError, match=r"attributes\['material_names'\]\[0\] is not a str"):
        petersen.write_mesh(tmp_path / "x.ply", V, F,
                            {"material_names": [3], "face_material": [0, 0]})
    with pytest.raises(TypeError, match="must hold integers"):
        petersen.quadrangulate(V, F, attributes={"face_group": [0.5, 0], "group_names": ["g"]})
    assert not (tmp_path / "x.ply").exists()


@pytest.mark.parametrize("cross", [[], ["uv_seam"]])
def test_spot_as_the_cli_makes_it(tmp_path, cli, shared_meshes, cross):
    # spot.obj has UV seams: the module and `petersen quad --cross` make the same faces with the
    # same corner texture coordinates, each its triangle corner's.
    mesh_path = shared_meshes / "spot.obj.gz"
    if not mesh_path.exists():
        pytest.skip(f"{mesh_path} is absent")
    out = tmp_path / "q.obj"
    subprocess.run([cli, "quad", str(mesh_path), str(out)] +
                   (["--cross", ",".join(cross)] if cross else []), check=True,
                   capture_output=True)
    mesh = petersen.read_mesh(mesh_path)
    r = petersen.quadrangulate(mesh, cross=cross)
    check_carried(mesh, r)
    assert (r.stats["cut_edges_by_cause"]["uv_seam"] > 0) == (not cross)
    written = petersen.read_mesh(out)
    w = written.attributes
    faces = list(written.F)

    def keyed(F, uv):
        return sorted((tuple(int(v) for v in f), tuple(u)) for f, u in zip(F, uv))

    assert keyed(faces, corner_values(w["texcoords"], w["corner_texcoord"], faces)) == \
        keyed(r.faces, corner_values(r.attributes["texcoords"], r.attributes["corner_texcoord"],
                                     r.faces))
