"""The Tris to Quads (Petersen) add-on inside Blender, headless:

    PETERSEN_PYTHONPATH=DIR[:DIR...] blender -b --factory-startup \
        --python tests/blender/test_addon.py

PETERSEN_PYTHONPATH is put first on Blender's sys.path: where petersen's Python module is
(scripts/test points it at the module it installed). The meshes are made here: a torus with UVs, a
UV seam, two materials, a corner colour attribute and custom normals; a quad-dominant grid (quads,
pentagons and triangles); a triangulated grid with a hole. Prints one line per check and exits 1
at the first failure, 0 when every check passed.
"""

import math
import os
import pathlib
import re
import sys
import traceback

sys.path[:0] = [p for p in os.environ.get("PETERSEN_PYTHONPATH", "").split(os.pathsep) if p]
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "blender"))

import bmesh  # noqa: E402
import bpy  # noqa: E402
import numpy as np  # noqa: E402
from mathutils import Vector  # noqa: E402

import petersen  # noqa: E402
import petersen_quads  # noqa: E402

NO_LIMIT = math.pi  # Blender's 180 degrees: any face angle, any shape
PASSED = []


def check(name, condition, detail=""):
    if not condition:
        raise AssertionError(f"{name}: {detail}")
    PASSED.append(name)
    print(f"ok   {name}", flush=True)


# --- meshes ---------------------------------------------------------------------------------

def torus(nu=12, nv=8, R=3.0, r=1.0):
    """Positions, triangles, per-corner UVs (u wraps at a seam), vertex normals (tilted)."""
    V = []
    for i in range(nu):
        for j in range(nv):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            V.append(((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u),
                      r * math.sin(v)))
    F, UV = [], []
    for i in range(nu):
        for j in range(nv):
            a, b = i * nv + j, ((i + 1) % nu) * nv + j
            c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            corners_uv = {a: (i / nu, j / nv), b: ((i + 1) / nu, j / nv),
                          c: ((i + 1) / nu, (j + 1) / nv), d: (i / nu, (j + 1) / nv)}
            for tri in ((a, b, c), (a, c, d)):
                F.append(tri)
                UV.append([corners_uv[x] for x in tri])
    normals = []
    for x, y, z in V:
        ring = Vector((x, y, 0)).normalized() * R
        normals.append(((Vector((x, y, z)) - ring).normalized() + Vector((0.2, 0.1, 0.3)))
                       .normalized())
    return V, F, UV, normals


def quad_dominant(n=8):
    """An n by n grid of squares: a block of them split into triangles, two pentagons (a vertex
    added on the edge between two squares) and three triangles around a vertex added on an edge
    of a fourth pentagon's square."""
    V = [(float(x), float(y), 0.0) for x in range(n + 1) for y in range(n + 1)]

    def at(x, y):
        return x * (n + 1) + y

    F = []
    m1 = len(V)
    V.append((1.0, 0.5, 0.0))  # on the edge between squares (0,0) and (1,0)
    m2 = len(V)
    V.append((7.0, 6.5, 0.0))  # on the edge between squares (6,6) and (7,6)
    for x in range(n):
        for y in range(n):
            a, b, c, d = at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1)
            if (x, y) == (0, 0):
                F.append((a, b, m1, c, d))
            elif (x, y) == (1, 0):
                F.append((a, b, c, d, m1))
            elif (x, y) == (6, 6):
                F += [(a, b, m2), (a, m2, d), (m2, c, d)]
            elif (x, y) == (7, 6):
                F.append((a, b, c, d, m2))
            elif 2 <= x <= 4 and 2 <= y <= 5:
                F += [(a, b, c), (a, c, d)]
            else:
                F.append((a, b, c, d))
    return V, F


def grid_with_hole(n=10):
    """A flat n by n grid of squares split into triangles, without its 2 by 2 middle."""
    V = [(float(x), float(y) + 0.05 * x * x, 0.0) for x in range(n + 1) for y in range(n + 1)]
    F = []
    for x in range(n):
        for y in range(n):
            if n // 2 - 1 <= x <= n // 2 and n // 2 - 1 <= y <= n // 2:
                continue
            a, b = x * (n + 1) + y, (x + 1) * (n + 1) + y
            F += [(a, b, b + 1), (a, b + 1, a + 1)]
    return V, F


def make_object(name, V, F, uvs=None, normals=None, materials=None, colours=None, seams=(),
                sharps=()):
    """A new mesh object, active, in Object Mode. uvs and colours per corner (lists per face),
    normals per vertex (custom normals), materials per face (indices into two materials)."""
    if bpy.context.object and bpy.context.object.mode != 'OBJECT':
        bpy.ops.object.mode_set(mode='OBJECT')
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    me = bpy.data.meshes.new(name)
    me.from_pydata(V, [], F)
    if uvs is not None:
        layer = me.uv_layers.new(name="UVMap")
        for p, face_uv in zip(me.polygons, uvs):
            for li, uv in zip(p.loop_indices, face_uv):
                layer.data[li].uv = uv
    if colours is not None:
        attribute = me.color_attributes.new("Col", 'BYTE_COLOR', 'CORNER')
        for p, face_colours in zip(me.polygons, colours):
            for li, colour in zip(p.loop_indices, face_colours):
                attribute.data[li].color = colour
    if materials is not None:
        for k in range(2):
            me.materials.append(bpy.data.materials.new(f"{name}-{k}"))
        for p, m in zip(me.polygons, materials):
            p.material_index = m
    for e in me.edges:
        e.use_seam = tuple(sorted(e.vertices)) in seams
        e.use_edge_sharp = tuple(sorted(e.vertices)) in sharps
    if normals is not None:
        me.use_auto_smooth = True
        me.auto_smooth_angle = math.pi
        for p in me.polygons:
            p.use_smooth = True
        me.normals_split_custom_set([normals[lp.vertex_index] for lp in me.loops])
    me.update()
    obj = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    return obj


# --- reading a mesh back --------------------------------------------------------------------

def snapshot(obj):
    """Every face of obj as a tuple of corners, each (vertex, uv, colour, normal), with its
    material and selection; the seam edges. Reads the Edit Mode mesh."""
    if obj.mode == 'EDIT':
        obj.update_from_editmode()
    # In Edit Mode UV maps and attributes are the BMesh's, without data: read a copy.
    me = obj.data.copy()
    try:
        return _snapshot(me)
    finally:
        bpy.data.meshes.remove(me)


def _snapshot(me):
    me.calc_normals_split()
    uv = me.uv_layers.active.data if me.uv_layers else None
    col = me.color_attributes[0].data if len(me.color_attributes) else None
    faces = []
    for p in me.polygons:
        corners = []
        for li in p.loop_indices:
            lp = me.loops[li]
            corners.append((lp.vertex_index,
                            tuple(uv[li].uv) if uv else None,
                            tuple(round(c, 5) for c in col[li].color) if col else None,
                            tuple(lp.normal)))
        faces.append({"corners": tuple(corners), "material": p.material_index,
                      "select": p.select, "verts": frozenset(p.vertices)})
    seams = {frozenset(e.vertices) for e in me.edges if e.use_seam}
    sharps = {frozenset(e.vertices) for e in me.edges if e.use_edge_sharp}
    edges = {frozenset(e.vertices) for e in me.edges}
    positions = np.array([v.co for v in me.vertices])
    return {"faces": faces, "seams": seams, "sharps": sharps, "edges": edges, "V": positions}


def same_normal(a, b):
    """Equal within twice Blender's storage precision of custom normals (2.4e-3 radians)."""
    return Vector(a).angle(Vector(b), 0.0) < 5e-3


def run_operator(**options):
    """bpy.ops.mesh.petersen_tris_to_quads on the active object in Edit Mode."""
    return bpy.ops.mesh.petersen_tris_to_quads(**options)


def select_faces(obj, which):
    """Edit Mode with exactly the faces for which which(face_index, centre) is true selected."""
    if obj.mode != 'EDIT':
        bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_mode(type='FACE')
    bm = bmesh.from_edit_mesh(obj.data)
    for f in bm.faces:
        f.select_set(False)
    for f in bm.faces:
        if which(f.index, f.calc_center_median()):
            f.select_set(True)
    bm.select_flush_mode()
    bmesh.update_edit_mesh(obj.data)


def module_result(before, options, keep_edges=None):
    """petersen's module on the selected triangles of a snapshot, with the operator's options."""
    tris = [f for f in before["faces"] if f["select"] and len(f["corners"]) == 3]
    F = np.array([[c[0] for c in f["corners"]] for f in tris])

    def limit(name):
        degrees = math.degrees(options.get(name, math.pi))  # the operator's default: no limit
        return None if degrees >= 180 else degrees

    return petersen.quadrangulate(
        before["V"], F, objective=options.get("objective", "QUADS").lower(),
        sharp_angle=limit("face_threshold"), max_corner_deviation=limit("shape_threshold"),
        keep_edges=keep_edges)


def pairs_made(before, after):
    """The quads of after that are not in before, each with the two triangles of before that
    make it (its removed edge is their shared edge)."""
    old = {f["verts"]: f for f in before["faces"]}
    made = []
    for f in after["faces"]:
        if f["verts"] in old or len(f["corners"]) != 4:
            continue
        parts = [old[f["verts"] - {v}] for v in f["verts"] if (f["verts"] - {v}) in old]
        made.append((f, parts))
    return made


def carried(quad, parts):
    """Whether each corner of quad has the UV, colour and normal its triangle corner had."""
    for vertex, uv, colour, normal in quad["corners"]:
        options = [c for t in parts for c in t["corners"] if c[0] == vertex]
        if not any(c[1] == uv and c[2] == colour and same_normal(c[3], normal)
                   for c in options):
            return False, (vertex, uv, colour, normal, options)
    return True, None


def delimiting_edges_bmesh(obj, seam=False, sharp=False, materials=False, uvs=False):
    """The edges no quad may remove, found one edge at a time with bmesh: a second reckoning of
    what the add-on computes with numpy."""
    bm = bmesh.from_edit_mesh(obj.data)
    uv = bm.loops.layers.uv.active
    keep = []
    for e in bm.edges:
        faces = [f for f in e.link_faces if f.select and len(f.verts) == 3]
        if len(faces) != 2 or len(e.link_faces) != 2:
            continue
        fa, fb = faces
        cut = ((seam and e.seam) or (sharp and not e.smooth)
               or (materials and fa.material_index != fb.material_index))
        if uvs and uv is not None:
            for v in e.verts:
                la = next(lp for lp in fa.loops if lp.vert == v)
                lb = next(lp for lp in fb.loops if lp.vert == v)
                cut |= tuple(la[uv].uv) != tuple(lb[uv].uv)
        if cut:
            keep.append(sorted(v.index for v in e.verts))
    return np.array(keep, np.int64).reshape(-1, 2)


# --- the checks -----------------------------------------------------------------------------

def test_registered_as_one_undo_step_in_the_face_menu():
    op = bpy.types.MESH_OT_petersen_tris_to_quads
    check("operator registered with REGISTER and UNDO",
          hasattr(bpy.ops.mesh, "petersen_tris_to_quads")
          and {'REGISTER', 'UNDO'} <= set(op.bl_options), op.bl_options)
    ours = {p.identifier: p for p in
            bpy.ops.mesh.petersen_tris_to_quads.get_rna_type().properties}
    blenders = {p.identifier: p for p in
                bpy.ops.mesh.tris_convert_to_quads.get_rna_type().properties}
    shared = ("face_threshold", "shape_threshold", "uvs", "vcols", "seam", "sharp", "materials")
    check("Blender's Tris to Quads options, same names and types",
          all(name in ours and name in blenders and ours[name].type == blenders[name].type
              for name in shared),
          [n for n in shared if n not in ours or n not in blenders])
    # The comparisons keep Blender's defaults; the two angle limits are off (180 degrees): the
    # Quads objective weighs every quad itself, and a limit only takes pairs away from it.
    check("Blender's defaults, but the angle limits off",
          all(ours[n].default == blenders[n].default for n in shared if "threshold" not in n)
          and all(abs(ours[n].default - math.pi) < 1e-6 for n in shared if "threshold" in n),
          {n: (ours[n].default, blenders[n].default) for n in shared})
    check("the Quads objective by default", ours["objective"].default == 'QUADS',
          ours["objective"].default)

    class Recorder:
        def __init__(self):
            self.calls = []

        def __getattr__(self, name):
            def record(*args, **kwargs):
                self.calls.append((name, args[0] if args else None))
                return type("Props", (), {})()
            return record

    layout = Recorder()
    menu = type("Menu", (), {"layout": layout})()
    bpy.types.VIEW3D_MT_edit_mesh_faces.draw(menu, bpy.context)
    ids = [arg for name, arg in layout.calls if name == "operator"]
    at = ids.index("mesh.tris_convert_to_quads")
    check("Face menu: right after Blender's Tris to Quads",
          ids[at + 1] == "mesh.petersen_tris_to_quads", ids)


def test_textured_torus():
    V, F, UV, normals = torus()
    nu = 12
    # Materials by halves, and the two triangles of each square of column 5 apart; seams on
    # the diagonals of column 3: borders a pair could otherwise cross.
    materials = [(k // 2 // 8 >= nu // 2) ^ (k // 2 // 8 == 5 and k % 2) for k in range(len(F))]
    colours = [[(1.0, 0.5, 0.25, 1.0) if x // 8 < nu // 3 else (0.0, 0.5, 1.0, 1.0) for x in f]
               for f in F]
    # The UV seam: where u wraps (corners of the last column take u = 1, the first u = 0).
    seams = {tuple(sorted((j, (j + 1) % 8))) for j in range(8)}
    seams |= {tuple(sorted((F[k][0], F[k][2]))) for k in range(len(F)) if k // 2 // 8 == 3}
    sharps = {tuple(sorted((F[k][0], F[k][2]))) for k in range(len(F)) if k // 2 // 8 == 7}
    sharps |= {tuple(sorted((j, j + 1))) for j in range(5 * 8, 5 * 8 + 7)}
    obj = make_object("torus", V, F, uvs=UV, normals=normals, materials=materials,
                      colours=colours, seams=seams, sharps=sharps)
    select_faces(obj, lambda i, c: True)
    before = snapshot(obj)
    for options in ({"face_threshold": NO_LIMIT, "shape_threshold": NO_LIMIT},
                    {"seam": True, "sharp": True, "materials": True, "uvs": True,
                     "vcols": True, "face_threshold": NO_LIMIT, "shape_threshold": NO_LIMIT},
                    {"objective": 'QUALITY', "seam": True, "materials": True,
                     "face_threshold": math.radians(40), "shape_threshold": math.radians(40)},
                    {}):
        label = ", ".join(f"{k}={v if not isinstance(v, float) else round(math.degrees(v))}"
                          for k, v in options.items()) or "Blender's defaults"
        obj = make_object("torus", V, F, uvs=UV, normals=normals, materials=materials,
                          colours=colours, seams=seams, sharps=sharps)
        select_faces(obj, lambda i, c: True)
        keep = delimiting_edges_bmesh(obj, seam=options.get("seam", False),
                                      sharp=options.get("sharp", False),
                                      materials=options.get("materials", False),
                                      uvs=options.get("uvs", False))
        if options.get("vcols"):
            keep = np.concatenate([keep, _colour_borders(obj)])
        expected = module_result(before, options, keep if len(keep) else None)
        run_operator(**options)
        after = snapshot(obj)
        made = pairs_made(before, after)
        check(f"torus [{label}]: pairs equal the module's ({len(made)})",
              len(made) == expected.stats["pairs"]
              and all(len(p) == 2 for _, p in made),
              (len(made), expected.stats["pairs"]))
        if options.get("objective") == 'QUALITY':
            quads = np.array([[c[0] for c in f["corners"]] for f, _ in made])
            cost = petersen.quad_quality(after["V"], quads).sum()
            check(f"torus [{label}]: the quads' total cost is the module's certified optimum",
                  expected.stats["optimality_certified"]
                  and abs(cost - expected.stats["objective_total"]) < 1e-3 * len(quads),
                  (cost, expected.stats["objective_total"]))
        bad = [carried(q, p)[1] for q, p in made if not carried(q, p)[0]]
        check(f"torus [{label}]: UVs, colours, custom normals carried to every quad corner",
              not bad, bad[:2])
        check(f"torus [{label}]: materials carried",
              all(q["material"] in {t["material"] for t in p} for q, p in made))
        check(f"torus [{label}]: seam and sharp marks of the edges that stay are kept",
              after["seams"] == {s for s in before["seams"] if s in after["edges"]}
              and after["sharps"] == {s for s in before["sharps"] if s in after["edges"]})
        if options.get("seam"):
            removed = [frozenset(p[0]["verts"] & p[1]["verts"]) for _, p in made]

            def continuous(parts, edge, slot):
                return all(len({c[slot] for t in parts for c in t["corners"] if c[0] == v}) == 1
                           for v in edge)

            check(f"torus [{label}]: no pair across a seam, a sharp edge, a material, a UV or "
                  "colour border",
                  not any(r in before["seams"] for r in removed)
                  and not (options.get("sharp") and any(r in before["sharps"] for r in removed))
                  and all(p[0]["material"] == p[1]["material"] for _, p in made)
                  and all(continuous(p, r, 1) and continuous(p, r, 2)
                          for (_, p), r in zip(made, removed)))
        compare_with_blenders_own(V, F, options, len(made),
                                  lambda: make_object("torus", V, F, uvs=UV, normals=normals,
                                                      materials=materials, colours=colours,
                                                      seams=seams, sharps=sharps), label)


def _colour_borders(obj):
    bm = bmesh.from_edit_mesh(obj.data)
    col = bm.loops.layers.color.active
    keep = []
    for e in bm.edges:
        if len(e.link_faces) != 2:
            continue
        fa, fb = e.link_faces
        for v in e.verts:
            la = next(lp for lp in fa.loops if lp.vert == v)
            lb = next(lp for lp in fb.loops if lp.vert == v)
            if tuple(la[col]) != tuple(lb[col]):
                keep.append(sorted(x.index for x in e.verts))
                break
    return np.array(keep, np.int64).reshape(-1, 2)


def compare_with_blenders_own(V, F, options, ours, make, label):
    obj = make()
    select_faces(obj, lambda i, c: True)
    bm = bmesh.from_edit_mesh(obj.data)
    faces = len(bm.faces)
    if options.get("objective", "QUADS") == "QUADS":
        return  # not a maximum: it leaves a triangle where a quad would cost more (the bench's)
    bpy.ops.mesh.tris_convert_to_quads(**{k: v for k, v in options.items() if k != "objective"})
    bm = bmesh.from_edit_mesh(obj.data)
    theirs = faces - len(bm.faces)
    check(f"{label}: Blender's own Tris to Quads pairs no more ({theirs} <= {ours})",
          theirs <= ours, (theirs, ours))


def test_partial_selection_and_undo():
    V, F, UV, normals = torus()
    obj = make_object("torus", V, F, uvs=UV, normals=normals)
    select_faces(obj, lambda i, c: c.x > 0.3)
    before = snapshot(obj)
    unselected = {f["corners"] for f in before["faces"] if not f["select"]}
    bpy.ops.ed.undo_push(message="before Tris to Quads (Petersen)")
    # undo=True: pushes the operator's undo step as a click in the menu does (a script's
    # bpy.ops call pushes none by default).
    bpy.ops.mesh.petersen_tris_to_quads('EXEC_DEFAULT', True, face_threshold=NO_LIMIT,
                                        shape_threshold=NO_LIMIT)
    after = snapshot(obj)
    kept = {f["corners"] for f in after["faces"]}

    def close(a, b):
        return all(x[:3] == y[:3] and same_normal(x[3], y[3]) for x, y in zip(a, b))

    missing = [f for f in unselected if f not in kept
               and not any(close(f, g) for g in kept if len(g) == len(f))]
    check("partial selection: unselected faces untouched (corners, UVs, normals)", not missing,
          missing[:2])
    made = pairs_made(before, after)
    check("partial selection: quads only from selected triangles",
          all(t["select"] for _, p in made for t in p) and made)
    selected_after = {f["verts"] for f in after["faces"] if f["select"]}
    check("partial selection: the quads and the triangles left are selected, nothing else",
          {q["verts"] for q, _ in made} <= selected_after
          and not any(f["verts"] in selected_after for f in before["faces"] if not f["select"]))
    bpy.ops.ed.undo()
    obj = bpy.data.objects["torus"]
    undone = snapshot(obj)
    restored = {f["corners"] for f in undone["faces"]}
    lost = [f for f in before["faces"] if f["corners"] not in restored
            and not any(close(f["corners"], g) for g in restored if len(g) == len(f["corners"]))]
    check("one undo step restores the mesh (faces, UVs, custom normals)",
          len(undone["faces"]) == len(before["faces"]) and not lost,
          (len(undone["faces"]), len(before["faces"]), lost[:1]))


def test_quad_dominant():
    V, F = quad_dominant()
    obj = make_object("quads", V, F)
    select_faces(obj, lambda i, c: True)
    before = snapshot(obj)
    options = {"face_threshold": NO_LIMIT, "shape_threshold": NO_LIMIT}
    expected = module_result(before, options)
    run_operator(**options)
    after = snapshot(obj)
    made = pairs_made(before, after)
    triangles = sum(len(f["corners"]) == 3 for f in before["faces"])
    check(f"quad-dominant: pairs equal the module's ({len(made)} of {triangles} triangles)",
          len(made) == expected.stats["pairs"], (len(made), expected.stats["pairs"]))
    polygons = {f["corners"] for f in before["faces"] if len(f["corners"]) != 3}
    check("quad-dominant: quads and pentagons kept as they were",
          polygons <= {f["corners"] for f in after["faces"]})
    compare_with_blenders_own(V, F, options, len(made), lambda: make_object("quads", V, F),
                              "quad-dominant")

    obj = make_object("quads", V, F)
    select_faces(obj, lambda i, c: True)
    run_operator(all_quad=True, **options)
    after = snapshot(obj)
    check("quad-dominant, all_quad: no triangle left",
          not any(len(f["corners"]) == 3 for f in after["faces"]))
    check_no_gap(before, after, "quad-dominant, all_quad")


def check_no_gap(before, after, label):
    """Every edge has one or two faces, and the boundary is as long as before (a vertex added on
    one side of an edge only would leave a slit)."""
    def boundary_length(snap):
        count = {}
        for f in snap["faces"]:
            vs = [c[0] for c in f["corners"]]
            for a, b in zip(vs, vs[1:] + vs[:1]):
                count[frozenset((a, b))] = count.get(frozenset((a, b)), 0) + 1
        if any(n > 2 for n in count.values()):
            return None
        return sum(np.linalg.norm(snap["V"][min(e)] - snap["V"][max(e)])
                   for e, n in count.items() if n == 1)
    lb, la = boundary_length(before), boundary_length(after)
    check(f"{label}: no slit (boundary length {la:.3f} as before)",
          la is not None and abs(la - lb) < 1e-6, (la, lb))


def test_grid_with_hole():
    V, F = grid_with_hole()
    obj = make_object("holed", V, F)
    select_faces(obj, lambda i, c: True)
    before = snapshot(obj)
    for options in ({"face_threshold": NO_LIMIT, "shape_threshold": NO_LIMIT}, {},
                    {"objective": 'QUALITY'}):
        label = "open grid " + ("[no limits]" if options.get("face_threshold") else
                                f"[{options.get('objective', 'defaults')}]")
        obj = make_object("holed", V, F)
        select_faces(obj, lambda i, c: True)
        expected = module_result(before, options)
        run_operator(**options)
        after = snapshot(obj)
        made = pairs_made(before, after)
        check(f"{label}: pairs equal the module's ({len(made)})",
              len(made) == expected.stats["pairs"], (len(made), expected.stats["pairs"]))
        compare_with_blenders_own(V, F, options, len(made), lambda: make_object("holed", V, F),
                                  label)
    # A selection with an odd number of triangles: all_quad splits an edge on the selection's
    # border, and the face beyond gets the vertex too.
    obj = make_object("holed", V, F)
    select_faces(obj, lambda i, c: c.x < 3.5 and i != 0)
    before = snapshot(obj)
    run_operator(all_quad=True, face_threshold=NO_LIMIT, shape_threshold=NO_LIMIT)
    after = snapshot(obj)
    selected = [f for f in after["faces"] if f["select"]]
    check("open grid, all_quad on a part: the selection is all quads",
          all(len(f["corners"]) == 4 for f in selected) and selected)
    check_no_gap(before, after, "open grid, all_quad on a part")


def test_closed_sphere_all_paired():
    """An icosphere with its vertices moved a little (the same each run): petersen pairs every
    triangle, as a closed triangle mesh allows; Blender's greedy pairing leaves some."""
    def make():
        if bpy.context.object and bpy.context.object.mode != 'OBJECT':
            bpy.ops.object.mode_set(mode='OBJECT')
        for o in list(bpy.data.objects):
            bpy.data.objects.remove(o)
        bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=3)
        obj = bpy.context.active_object
        for v in obj.data.vertices:
            v.co *= 1.0 + 0.08 * math.sin(12.9898 * v.index + 78.233 * v.co.z)
        return obj

    obj = make()
    select_faces(obj, lambda i, c: True)
    before = snapshot(obj)
    run_operator(face_threshold=NO_LIMIT, shape_threshold=NO_LIMIT)
    made = pairs_made(before, snapshot(obj))
    check(f"icosphere: every one of {len(before['faces'])} triangles paired",
          2 * len(made) == len(before["faces"]), len(made))
    compare_with_blenders_own(None, None, {"face_threshold": NO_LIMIT,
                                           "shape_threshold": NO_LIMIT},
                              len(made), make, "icosphere")


def test_all_quad_where_no_pair_is_allowed():
    """All Quads where a tight shape limit lets no pair through, on a closed sphere with some
    triangles left out of the selection: every selected triangle still becomes quads (the fewest
    edges split, the faces beyond the selection sharing a split edge get its vertex), no gap."""
    if bpy.context.object and bpy.context.object.mode != 'OBJECT':
        bpy.ops.object.mode_set(mode='OBJECT')
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=3)
    obj = bpy.context.active_object
    select_faces(obj, lambda i, c: i % 7 != 0)
    before = snapshot(obj)
    result = run_operator(all_quad=True, shape_threshold=math.radians(5))
    after = snapshot(obj)
    selected = [f for f in after["faces"] if f["select"]]
    check("All Quads with no pair allowed: finished, the selection all quads",
          result == {'FINISHED'} and selected
          and all(len(f["corners"]) == 4 for f in selected), result)
    check_no_gap(before, after, "All Quads with no pair allowed")


def test_missing_module_is_a_clear_error():
    V, F = grid_with_hole(4)
    obj = make_object("missing", V, F)
    select_faces(obj, lambda i, c: True)
    saved = sys.modules.get("petersen")
    sys.modules["petersen"] = None  # import petersen now fails
    try:
        try:
            result = run_operator()
            message = ""
        except RuntimeError as error:
            result, message = {'CANCELLED'}, str(error)
    finally:
        sys.modules["petersen"] = saved
    check("without petersen: cancelled, saying how to install it",
          result == {'CANCELLED'} and "blender-addon-zip" in message, message)


def main():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    petersen_quads.register()
    try:
        for test in (test_registered_as_one_undo_step_in_the_face_menu, test_textured_torus,
                     test_partial_selection_and_undo, test_quad_dominant, test_grid_with_hole,
                     test_closed_sphere_all_paired, test_all_quad_where_no_pair_is_allowed,
                     test_missing_module_is_a_clear_error):
            test()
    except Exception:
        traceback.print_exc()
        print(f"FAILED after {len(PASSED)} checks passed", flush=True)
        sys.exit(1)
    finally:
        petersen_quads.unregister()
    print(f"{len(PASSED)} passed, 0 failed", flush=True)
    sys.exit(0)


main()
