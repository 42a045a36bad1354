"""Quads brought back: quad models exported triangulated, then converted back by petersen's add-on
and by Blender's own Tris to Quads, side by side in one Blender.

    PETERSEN_PYTHONPATH=DIR blender -b --factory-startup --python bench/quad_recovery.py \\
        -- [--scans] [--quick] MESH [MESH ...]

PETERSEN_PYTHONPATH as for tests/blender/test_addon.py. Each MESH (OFF, OBJ or PLY, gzip too, read
by petersen.read_mesh) becomes quad models the way users meet them:
- the model itself, when it has quads (a quad model as published);
- "ccN": Blender's Subdivision Surface modifier (Catmull-Clark) at level N = 1, 2 (--quick: 1 only),
  all quads;
- "cc1+tri": the level-1 model with 1 % of its edges collapsed (each collapse turns the two quads
  beside the edge into triangles of the model's own, as a quad-dominant artist mesh has them).
Each model is triangulated as exporters do, one diagonal per quad: a random one ("random") and the
shorter one ("short"); a larger polygon is fanned. Every operator then runs on a fresh copy with
all faces selected: Blender's mesh.tris_convert_to_quads with its defaults (40°, 40°) and with
both limits off (180°), and petersen's mesh.petersen_tris_to_quads with its defaults and with
objective PAIRS and QUALITY.
A row gives the share of the model's quads that come back (the same four vertices as one face),
its triangles left, and the operator's wall time.

--flow-weights=W,...: instead of the operators, petersen.quadrangulate's default with each edge-flow
weight (the module on the same triangulations), the trial behind the default weight of 0.

--scans: instead, each MESH as it is (a scan: nothing to recover): the share of regular interior
vertices (four edges, every face around it a quad), triangles left, and the quads' worst corner
(median, p95: petersen.quad_quality).
Prints Markdown tables.
"""

import math
import os
import pathlib
import sys
import time

sys.path[:0] = [p for p in os.environ.get("PETERSEN_PYTHONPATH", "").split(os.pathsep) if p]
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "blender"))

import bpy  # noqa: E402
import numpy as np  # noqa: E402

import petersen  # noqa: E402
import petersen_quads  # noqa: E402

OFF = math.pi
OPERATORS = [
    ("Blender, defaults (40°, 40°)", "blender", {"face_threshold": math.radians(40.0),
                                                "shape_threshold": math.radians(40.0)}),
    ("Blender, limits off", "blender", {"face_threshold": OFF, "shape_threshold": OFF}),
    ("petersen add-on, defaults", "petersen", {}),
    ("petersen, Pairs", "petersen", {"objective": 'PAIRS', "face_threshold": OFF,
                                     "shape_threshold": OFF}),
    ("petersen, Quality", "petersen", {"objective": 'QUALITY', "face_threshold": OFF,
                                       "shape_threshold": OFF}),
]


def clear():
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    for m in list(bpy.data.meshes):
        if m.users == 0:
            bpy.data.meshes.remove(m)


def make_object(name, V, faces):
    """A Blender mesh object of V and a list of faces (vertex index sequences), active."""
    clear()
    counts = np.array([len(f) for f in faces], np.int32)
    corners = np.concatenate([np.asarray(f, np.int32) for f in faces])
    me = bpy.data.meshes.new(name)
    me.vertices.add(len(V))
    me.vertices.foreach_set("co", np.asarray(V, np.float32).ravel())
    me.loops.add(len(corners))
    me.loops.foreach_set("vertex_index", corners)
    me.polygons.add(len(counts))
    me.polygons.foreach_set("loop_start", (np.cumsum(counts) - counts).astype(np.int32))
    me.polygons.foreach_set("loop_total", counts)
    me.update(calc_edges=True)
    obj = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    return obj


def mesh_faces(me):
    """Vertex positions and faces (lists of vertex indices) of a Blender mesh."""
    V = np.empty(len(me.vertices) * 3, np.float32)
    me.vertices.foreach_get("co", V)
    counts = np.empty(len(me.polygons), np.int32)
    me.polygons.foreach_get("loop_total", counts)
    corner = np.empty(len(me.loops), np.int64)
    me.loops.foreach_get("vertex_index", corner)
    starts = np.cumsum(counts) - counts
    faces = [corner[s:s + c] for s, c in zip(starts, counts)]
    return V.reshape(-1, 3).astype(np.float64), faces


def catmull_clark(V, faces, levels):
    """Blender's Subdivision Surface (Catmull-Clark) of the mesh, applied."""
    obj = make_object("source", V, faces)
    modifier = obj.modifiers.new("subsurf", 'SUBSURF')
    modifier.levels = levels
    modifier.render_levels = levels
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    me = evaluated.to_mesh()
    result = mesh_faces(me)
    evaluated.to_mesh_clear()
    return result


def collapse_edges(V, faces, share, rng):
    """Collapses `share` of the quad edges, each far from the others (no face touches two), to its
    midpoint: the two quads beside it become triangles. Returns positions and faces."""
    V = V.copy()
    edges = {}
    for f, face in enumerate(faces):
        for k in range(len(face)):
            a, b = int(face[k]), int(face[(k + 1) % len(face)])
            edges.setdefault((min(a, b), max(a, b)), []).append(f)
    vertex_faces = {}
    for f, face in enumerate(faces):
        for v in face:
            vertex_faces.setdefault(int(v), []).append(f)
    candidates = [e for e, fs in edges.items() if len(fs) == 2]
    rng.shuffle(candidates)
    wanted = int(share * len(edges))
    touched = set()
    merge = {}
    for a, b in candidates:
        if len(merge) >= wanted:
            break
        around = set(vertex_faces[a]) | set(vertex_faces[b])
        if around & touched or any(len(faces[f]) != 4 for f in around):
            continue
        touched |= around
        merge[b] = a
        V[a] = (V[a] + V[b]) / 2
    out = []
    for face in faces:
        mapped = [merge.get(int(v), int(v)) for v in face]
        kept = [v for k, v in enumerate(mapped) if v != mapped[k - 1]]
        out.append(kept)
    return V, out


def triangulate(V, faces, rule, rng):
    """Every quad cut by one diagonal (rule "random" or "short"), every larger polygon fanned from
    its first corner, as exporters do; triangles kept. Returns the triangle mesh's faces and the
    set of the quads' vertex sets."""
    out, quads = [], set()
    for face in faces:
        if len(face) != 4:
            out += [[int(face[0]), int(face[k]), int(face[k + 1])] for k in range(1, len(face) - 1)]
            continue
        a, b, c, d = (int(v) for v in face)
        quads.add(frozenset((a, b, c, d)))
        if rule == "short":
            first = np.linalg.norm(V[a] - V[c]) <= np.linalg.norm(V[b] - V[d])
        else:
            first = rng.random() < 0.5
        out += [[a, b, c], [a, c, d]] if first else [[a, b, d], [b, c, d]]
    return out, quads


def run_operator(obj, kind, options):
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='SELECT')
    start = time.perf_counter()
    if kind == "blender":
        bpy.ops.mesh.tris_convert_to_quads(**options)
    else:
        bpy.ops.mesh.petersen_tris_to_quads(**options)
    seconds = time.perf_counter() - start
    bpy.ops.object.mode_set(mode='OBJECT')
    return mesh_faces(obj.data), seconds


def module_run(V, triangles, flow_weight):
    """petersen.quadrangulate's default with this edge-flow weight: its faces and seconds."""
    start = time.perf_counter()
    r = petersen.quadrangulate(V, np.array(triangles, np.int64), flow_weight=flow_weight)
    return list(r.quads) + list(r.triangles), time.perf_counter() - start


def recovery_rows(name, V, faces, rng, flow_weights=()):
    rows = []
    for rule in ("random", "short"):
        triangles, quads = triangulate(V, faces, rule, rng)
        own = sum(1 for f in faces if len(f) == 3)
        runs = [(label, kind, options) for label, kind, options in OPERATORS if not flow_weights]
        runs += [(f"petersen, flow weight {w:g}", "module", w) for w in flow_weights]
        for label, kind, options in runs:
            if kind == "module":
                out, seconds = module_run(V, triangles, options)
            else:
                obj = make_object(name, V, triangles)
                (_, out), seconds = run_operator(obj, kind, options)
            back = sum(1 for f in out if len(f) == 4 and frozenset(int(v) for v in f) in quads)
            left = sum(1 for f in out if len(f) == 3)
            rows.append(f"| {name} | {len(quads):,} + {own:,} | {rule} | {label} | "
                        f"{100.0 * back / len(quads):.2f} % | {left:,} | {seconds:.2f} |")
            print(rows[-1], flush=True)
    return rows


def regular_share(V, faces):
    """Of the interior vertices (every edge at them on two faces), those of four edges whose faces
    are all quads."""
    edges, vertex_faces = {}, {}
    for face in faces:
        for k in range(len(face)):
            a, b = int(face[k]), int(face[(k + 1) % len(face)])
            key = (min(a, b), max(a, b))
            edges[key] = edges.get(key, 0) + 1
            vertex_faces.setdefault(a, []).append(len(face))
    degree, interior = {}, {}
    for (a, b), n in edges.items():
        for v in (a, b):
            degree[v] = degree.get(v, 0) + 1
            interior[v] = interior.get(v, True) and n == 2
    inner = [v for v in degree if interior[v]]
    regular = sum(1 for v in inner if degree[v] == 4 and all(c == 4 for c in vertex_faces[v]))
    return regular / max(1, len(inner))


def scan_rows(name, V, faces):
    rows = []
    for label, kind, options in OPERATORS:
        obj = make_object(name, V, faces)
        (Vout, out), seconds = run_operator(obj, kind, options)
        quads = np.array([f for f in out if len(f) == 4], np.int64).reshape(-1, 4)
        cost = petersen.quad_quality(Vout, quads) if len(quads) else np.zeros(0)
        left = sum(1 for f in out if len(f) == 3)
        rows.append(f"| {name} | {label} | {100.0 * regular_share(Vout, out):.1f} % | "
                    f"{100.0 * left / len(faces):.2f} % | {np.median(cost):.1f}° | "
                    f"{np.percentile(cost, 95):.1f}° | {seconds:.2f} |")
        print(rows[-1], flush=True)
    return rows


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    scans, quick = "--scans" in args, "--quick" in args
    flow_weights = [float(w) for a in args if a.startswith("--flow-weights=")
                    for w in a.split("=", 1)[1].split(",")]
    paths = [a for a in args if not a.startswith("--")]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    petersen_quads.register()
    rng = np.random.default_rng(1)
    rows = []
    for path in paths:
        mesh = petersen.read_mesh(path)
        name = pathlib.Path(path).name.split(".")[0]
        faces = [list(f) for f in mesh.F]
        if scans:
            rows += scan_rows(name, np.asarray(mesh.V, np.float64), faces)
            continue
        if any(len(f) == 4 for f in faces):
            rows += recovery_rows(name, np.asarray(mesh.V, np.float64), faces, rng, flow_weights)
        for levels in (1,) if quick else (1, 2):
            V, quads = catmull_clark(mesh.V, faces, levels)
            rows += recovery_rows(f"{name}-cc{levels}", V, quads, rng, flow_weights)
            if levels == 1:
                Vc, mixed = collapse_edges(V, quads, 0.01, rng)
                rows += recovery_rows(f"{name}-cc1+tri", Vc, mixed, rng, flow_weights)
    print()
    if scans:
        print("| scan | operator | regular interior vertices | triangles left | worst corner, "
              "median | worst corner, p95 | seconds |")
        print("|---|---|---:|---:|---:|---:|---:|")
    else:
        print("| model | quads + own triangles | diagonal | operator | quads back | triangles left "
              "| seconds |")
        print("|---|---:|---|---|---:|---:|---:|")
    print("\n".join(rows))
    petersen_quads.unregister()


if __name__ == "__main__":
    try:
        main()
    except Exception:
        import traceback
        traceback.print_exc()
        sys.exit(1)
