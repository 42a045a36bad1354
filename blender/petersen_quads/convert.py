"""The operator's work apart from its user interface: read the selected triangles of a mesh, pair
them with petersen, and make the quads in the mesh's Edit Mode BMesh.

The quads are made by Blender's own BMesh operations (joining a pair removes its shared edge,
``all_quad`` splits edges and faces), so every corner keeps the UVs, colours and other corner
attributes it had, every face its material and smoothing, and every edge that stays its seam and
sharp flags. Custom split normals are stored in BMesh as offsets from the automatic normals, which
change when faces change; the operator records them before and sets them again after
(``record_corner_normals``, ``restore_corner_normals``).
"""

from dataclasses import dataclass
import math
import re

import bmesh
import numpy as np

#: A temporary corner attribute holding each corner's normal while the faces change.
CORNER_NORMAL_ATTRIBUTE = "petersen_corner_normal"


@dataclass
class Selection:
    """The selected, visible triangles of a mesh, as its ``Mesh`` data holds them."""

    #: (t,) the face index of each triangle.
    faces: np.ndarray
    #: (t, 3) the vertex index of each corner, in the face's order.
    triangles: np.ndarray
    #: (t, 3) the loop (corner) index of each corner.
    loops: np.ndarray


def _get(collection, attribute, dtype, width=1):
    """One property of every item of a Blender collection as a numpy array."""
    values = np.empty(len(collection) * width, dtype)
    collection.foreach_get(attribute, values)
    return values.reshape(-1, width) if width > 1 else values


def selected_triangles(mesh):
    """The selected triangles of ``mesh`` that are not hidden (``Selection``).

    Reads the ``Mesh`` data: in Edit Mode call ``object.update_from_editmode()`` first.
    """
    loop_total = _get(mesh.polygons, "loop_total", np.int32)
    loop_start = _get(mesh.polygons, "loop_start", np.int64)
    select = _get(mesh.polygons, "select", bool)
    hide = _get(mesh.polygons, "hide", bool)
    faces = np.flatnonzero(select & ~hide & (loop_total == 3))
    loops = loop_start[faces, None] + np.arange(3)
    vertex_of_loop = _get(mesh.loops, "vertex_index", np.int64)
    return Selection(faces, vertex_of_loop[loops], loops)


def delimited_edges(mesh, selection, seam=False, sharp=False, materials=False, uvs=False,
                    vcols=False):
    """The edges between two selected triangles that no quad may remove, as an (e, 2) array of
    vertex indices: those marked as seams (``seam``) or sharp (``sharp``), those between faces of
    different materials (``materials``), and those across which a UV map (``uvs``) or a corner
    colour attribute (``vcols``) does not continue (a corner of one face has another value than
    the other face's corner at the same vertex). The same tests as Blender's Tris to Quads."""
    count = len(selection.faces)
    if count == 0 or not (seam or sharp or materials or uvs or vcols):
        return np.empty((0, 2), np.int64)
    edge_of_loop = _get(mesh.loops, "edge_index", np.int64)
    corner_loop = selection.loops.ravel()
    corner_edge = edge_of_loop[corner_loop]
    order = np.argsort(corner_edge, kind="stable")
    sorted_edges = corner_edge[order]
    starts = np.flatnonzero(np.r_[True, sorted_edges[1:] != sorted_edges[:-1]])
    sizes = np.diff(np.r_[starts, len(sorted_edges)])
    shared = starts[sizes == 2]  # an edge of exactly two selected triangles
    a, b = order[shared], order[shared + 1]  # their corners that start the edge
    edge = sorted_edges[shared]
    keep = np.zeros(len(shared), bool)
    if seam:
        keep |= _get(mesh.edges, "use_seam", bool)[edge]
    if sharp:
        keep |= _get(mesh.edges, "use_edge_sharp", bool)[edge]
    if materials:
        material = _get(mesh.polygons, "material_index", np.int64)[selection.faces]
        keep |= material[a // 3] != material[b // 3]
    layers = []
    if uvs:
        layers += [_get(uv.data, "uv", np.float32, 2) for uv in mesh.uv_layers]
    if vcols:
        layers += [_get(c.data, "color", np.float32, 4) for c in _corner_colours(mesh)]
    if layers:
        def next_corner(c):
            return c - c % 3 + (c + 1) % 3
        vertex = selection.triangles.ravel()
        # The corners of each triangle at the edge's two ends u (where a starts) and v.
        a_u, a_v = corner_loop[a], corner_loop[next_corner(a)]
        same_start = vertex[b] == vertex[a]
        b_u = np.where(same_start, corner_loop[b], corner_loop[next_corner(b)])
        b_v = np.where(same_start, corner_loop[next_corner(b)], corner_loop[b])
        for values in layers:
            keep |= np.any(values[a_u] != values[b_u], axis=1)
            keep |= np.any(values[a_v] != values[b_v], axis=1)
    ends = _get(mesh.edges, "vertices", np.int64, 2)
    return ends[edge[keep]]


def _corner_colours(mesh):
    """The colour attributes stored per corner."""
    attributes = getattr(mesh, "color_attributes", None)
    if attributes is None:  # before Blender 3.2: the vertex colour layers
        return list(mesh.vertex_colors)
    return [c for c in attributes if c.domain == 'CORNER']


def pair_triangles(petersen, mesh, selection, keep_edges, *, objective, face_threshold,
                   shape_threshold, all_quad):
    """petersen's quadrangulation of the selected triangles (a ``petersen.QuadResult`` over their
    vertices renumbered from 0, in the order of ``used_vertices``) and those vertex indices.

    ``face_threshold`` and ``shape_threshold`` are Blender's, in radians (180 degrees or more:
    no limit): the first becomes petersen's ``sharp_angle`` (an edge whose two faces' normals
    differ by more is not removed), the second its ``max_corner_deviation`` (no quad whose worst
    corner is further than that from a right angle).
    """
    positions = _get(mesh.vertices, "co", np.float64, 3)
    used_vertices, local = np.unique(selection.triangles, return_inverse=True)
    local = local.reshape(-1, 3)
    keep_local = np.searchsorted(used_vertices, keep_edges) if len(keep_edges) else None

    def limit(radians):
        degrees = math.degrees(radians)
        return None if degrees >= 180.0 else degrees

    result = petersen.quadrangulate(
        positions[used_vertices], local,
        objective=objective,
        all_quad=all_quad,
        sharp_angle=limit(face_threshold),
        max_corner_deviation=limit(shape_threshold),
        keep_edges=keep_local,
    )
    return result, used_vertices


def in_blender_terms(message, selection):
    """petersen's error message with the faces it names (indices among the selected triangles it
    was given, "input face N" or "face N (input)") as Blender's face indices, and its option as
    Blender's."""
    def face(match):
        n = int(match.group(1) or match.group(2))
        return f"face {selection.faces[n]}" if n < len(selection.faces) else match.group(0)
    message = re.sub(r"input face (\d+)|face (\d+) \(input\)", face, str(message))
    return message.replace("--all-quad", "All Quads")


def make_quads(bm, mesh, selection, result, used_vertices):
    """Makes ``result`` (from ``pair_triangles``) in ``bm``, the Edit Mode BMesh of ``mesh``
    whose ``Mesh`` data was written from it just before (same order of vertices, edges, faces).

    Each pair's two triangles are joined (their shared edge removed); with ``all_quad`` the added
    vertices split their edges (a face beyond the selection sharing such an edge gets the vertex
    too, so no gap opens) and the pieces are cut out of the faces they lie in. The output faces
    end up selected, the faces beyond the selection keep their selection. Returns the number of
    pairs joined.
    """
    if len(bm.faces) != len(mesh.polygons) or len(bm.edges) != len(mesh.edges):
        raise RuntimeError("the mesh data is not the Edit Mode mesh's (update_from_editmode first)")
    bm.faces.ensure_lookup_table()
    bm.verts.ensure_lookup_table()
    sources = result.sources[: len(result.quads)]
    pairs = selection.faces[np.unique(sources[sources[:, 1] >= 0], axis=0)]
    faces = bm.faces
    triangles = [(faces[a], faces[b]) for a, b in pairs.tolist()]
    verts = [bm.verts[i] for i in used_vertices.tolist()]
    join = bmesh.utils.face_join
    joined = 0
    for pair in triangles:
        quad = join(pair)
        if quad is not None:
            quad.select = True
            joined += 1
    if len(result.V) > len(used_vertices):
        _split_for_added_vertices(bm, result, verts)
    bm.select_flush_mode()
    return joined


def _split_for_added_vertices(bm, result, verts):
    """Splits edges and faces of ``bm`` so that it holds the faces of ``result`` that use
    vertices ``all_quad`` added: a midpoint splits the edge it lies on, a centre (where a path
    turns inside a quad) is made by cutting the quad. ``verts``: the BMVert of each of the
    result's original vertices."""
    original = len(verts)
    vert_of = dict(enumerate(verts))  # result vertex id: BMVert
    bm_vert = vert_of.get

    faces = [f.tolist() for f in result.faces if f.max() >= original]
    # A midpoint's edge: two original neighbours (in the output faces) whose midpoint it is.
    neighbours = {}
    for face in faces:
        for k, x in enumerate(face):
            if x >= original:
                neighbours.setdefault(x, set()).update((face[k - 1], face[(k + 1) % len(face)]))
    for x, around in sorted(neighbours.items()):
        ends = sorted(v for v in around if v < original)
        best = None
        for i, u in enumerate(ends):
            for w in ends[i + 1:]:
                gap = np.abs((result.V[u] + result.V[w]) / 2 - result.V[x]).max()
                edge = bm.edges.get((bm_vert(u), bm_vert(w)))
                if edge is not None and (best is None or gap < best[0]):
                    best = (gap, edge, u)
        scale = max(1.0, float(np.abs(result.V[x]).max()))
        if best is not None and best[0] <= 1e-9 * scale:
            _, edge, u = best
            _, vert = bmesh.utils.edge_split(edge, bm_vert(u), 0.5)
            vert.co = result.V[x]
            vert_of[x] = vert
    for face in faces:
        _cut_out(face, bm_vert, vert_of, result.V)


def _cut_out(face, bm_vert, vert_of, positions):
    """Cuts the output face ``face`` (result vertex ids) out of the BMesh face that holds it,
    one chord at a time; a run of vertices not made yet (a centre) is made along its chord."""
    for _ in range(2 * len(face)):
        known = [bm_vert(x) for x in face if bm_vert(x) is not None]
        if len(known) == len(face):
            target = set(known)
            made = [f for f in known[0].link_faces if set(f.verts) == target]
            if made:
                for f in made:
                    f.select = True
                return
        holders = set(known[0].link_faces)
        for v in known[1:]:
            holders &= set(v.link_faces)
        if not holders:
            raise RuntimeError(f"no face holds the output face {face}")
        parent = min(holders, key=lambda f: len(f.verts))
        # A chord: two known corners u, w of the face with only unmade vertices between them,
        # not already joined by an edge of the parent.
        n = len(face)
        for k in range(n):
            u = bm_vert(face[k])
            if u is None:
                continue
            run = []
            j = (k + 1) % n
            while bm_vert(face[j]) is None:
                run.append(face[j])
                j = (j + 1) % n
            w = bm_vert(face[j])
            if not run and any(w in e.verts for e in u.link_edges if parent in e.link_faces):
                continue
            coords = [tuple(positions[x]) for x in run]
            old = set(parent.verts)
            new_face, _ = bmesh.utils.face_split(parent, u, w, coords=coords)
            made = [v for v in new_face.verts if v not in old]
            for x in run:
                vert_of[x] = min(made, key=lambda v: (v.co - _vec(positions[x])).length)
            parent.select = new_face.select = True
            break
        else:
            raise RuntimeError(f"cannot cut the output face {face} out of its face")
    raise RuntimeError(f"cannot cut the output face {face} out of its face")


def _vec(p):
    from mathutils import Vector
    return Vector(tuple(p))


def corner_normals(mesh):
    """The normal of every corner (loop) of ``mesh``, custom or automatic: (loops, 3) float32."""
    if hasattr(mesh, "corner_normals"):  # Blender 4.1 and later
        return _get(mesh.corner_normals, "vector", np.float32, 3)
    mesh.calc_normals_split()
    return _get(mesh.loops, "normal", np.float32, 3)


def record_corner_normals(mesh):
    """Stores the normal of each corner of ``mesh`` (Object Mode) in a corner attribute that the
    BMesh operations carry (copied where corners stay, blended where edges are split)."""
    normals = corner_normals(mesh)
    attribute = mesh.attributes.get(CORNER_NORMAL_ATTRIBUTE)
    if attribute is None:
        attribute = mesh.attributes.new(CORNER_NORMAL_ATTRIBUTE, 'FLOAT_VECTOR', 'CORNER')
    attribute.data.foreach_set("vector", normals.ravel())


def restore_corner_normals(mesh):
    """Sets the custom normals of ``mesh`` (Object Mode) from the attribute that
    ``record_corner_normals`` made, and removes it."""
    attribute = mesh.attributes.get(CORNER_NORMAL_ATTRIBUTE)
    if attribute is None:
        return
    normals = _get(attribute.data, "vector", np.float32, 3).astype(np.float64)
    mesh.attributes.remove(attribute)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.where(length > 0, normals / np.where(length > 0, length, 1), 0)
    if hasattr(mesh, "use_auto_smooth"):  # before Blender 4.1 custom normals need it
        mesh.use_auto_smooth = True
    mesh.normals_split_custom_set(normals.tolist())
