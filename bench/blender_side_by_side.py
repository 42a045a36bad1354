"""petersen's Tris to Quads beside Blender's own, in the same Blender, on the same meshes.

    PETERSEN_PYTHONPATH=DIR blender -b --factory-startup --python bench/blender_side_by_side.py \
        -- MESH [MESH ...]

MESH: OFF, OBJ or PLY, gzip-compressed too (read with petersen.read_mesh, since Blender 3.4 has no
OFF importer, and made into a Blender mesh from the arrays). PETERSEN_PYTHONPATH as for
tests/blender/test_addon.py. For each mesh and each setting of the two angle limits (Blender's
defaults, 40 degrees each, and no limit, 180 degrees), runs on a fresh copy with every face
selected: Blender's mesh.tris_convert_to_quads, petersen's operator with objective PAIRS and with
QUALITY. Each row: pairs made, triangles left, the quads' worst-corner deviation from 90 degrees
(median and 95th percentile, petersen.quad_quality, the same measure for both), and the
operator's wall time (the bpy.ops call, Edit Mode conversion of the whole mesh included for both).
Prints a Markdown table.
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

SETTINGS = {"defaults (40°, 40°)": math.radians(40.0), "no limit (180°, 180°)": math.pi}


def make_object(name, mesh, keep=()):
    """A Blender mesh object of petersen's Mesh, active, in Object Mode; every other object but
    those of keep removed."""
    for o in list(bpy.data.objects):
        if o not in keep:
            bpy.data.objects.remove(o)
    for m in list(bpy.data.meshes):
        if m.users == 0:
            bpy.data.meshes.remove(m)
    faces = mesh.F if isinstance(mesh.F, np.ndarray) else None
    counts = (np.full(len(faces), faces.shape[1]) if faces is not None
              else np.array([len(f) for f in mesh.F]))
    corners = faces.ravel() if faces is not None else np.concatenate(mesh.F)
    me = bpy.data.meshes.new(name)
    me.vertices.add(len(mesh.V))
    me.vertices.foreach_set("co", mesh.V.astype(np.float32).ravel())
    me.loops.add(len(corners))
    me.loops.foreach_set("vertex_index", corners.astype(np.int32))
    me.polygons.add(len(counts))
    me.polygons.foreach_set("loop_start", (np.cumsum(counts) - counts).astype(np.int32))
    me.polygons.foreach_set("loop_total", counts.astype(np.int32))
    me.update(calc_edges=True)
    obj = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    return obj


def figures(obj):
    """Faces by corner count and the quads' worst-corner figures, from the Edit Mode mesh."""
    obj.update_from_editmode()
    me = obj.data
    counts = np.empty(len(me.polygons), np.int32)
    me.polygons.foreach_get("loop_total", counts)
    starts = np.empty(len(me.polygons), np.int64)
    me.polygons.foreach_get("loop_start", starts)
    corner = np.empty(len(me.loops), np.int64)
    me.loops.foreach_get("vertex_index", corner)
    V = np.empty(len(me.vertices) * 3, np.float32)
    me.vertices.foreach_get("co", V)
    quads = corner[starts[counts == 4, None] + np.arange(4)]
    cost = petersen.quad_quality(V.reshape(-1, 3).astype(np.float64), quads)
    return {"triangles": int((counts == 3).sum()), "quads": len(quads),
            "median": float(np.median(cost)) if len(cost) else float("nan"),
            "p95": float(np.percentile(cost, 95)) if len(cost) else float("nan")}


def run(mesh, name, method, angle):
    obj = make_object(name, mesh)
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='SELECT')
    before = figures(obj)
    start = time.perf_counter()
    if method == "blender":
        bpy.ops.mesh.tris_convert_to_quads(face_threshold=angle, shape_threshold=angle)
    else:
        bpy.ops.mesh.petersen_tris_to_quads(face_threshold=angle, shape_threshold=angle,
                                            objective=method)
    seconds = time.perf_counter() - start
    after = figures(obj)
    bpy.ops.object.mode_set(mode='OBJECT')
    return {"pairs": after["quads"] - before["quads"], "left": after["triangles"],
            "median": after["median"], "p95": after["p95"], "seconds": seconds}


def main():
    paths = sys.argv[sys.argv.index("--") + 1:]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    petersen_quads.register()
    rows = []
    for path in paths:
        mesh = petersen.read_mesh(path)
        name = pathlib.Path(path).name.split(".")[0]
        triangles = int(sum(1 for f in mesh.F if len(f) == 3))
        for setting, angle in SETTINGS.items():
            for method, label in (("blender", "Blender's Tris to Quads"),
                                  ("PAIRS", "petersen, Pairs"), ("QUALITY", "petersen, Quality")):
                r = run(mesh, name, method, angle)
                row = (f"| {name} ({triangles:,} triangles) | {setting} | {label} | "
                       f"{r['pairs']:,} | {r['left']:,} | {r['median']:.1f}° | {r['p95']:.1f}° | "
                       f"{r['seconds']:.2f} |")
                print(row, flush=True)
                rows.append(row)
    print()
    print("| mesh | angle limits | operator | pairs | triangles left | worst corner, median "
          "| worst corner, p95 | seconds |")
    print("|---|---|---|---:|---:|---:|---:|---:|")
    print("\n".join(rows))
    petersen_quads.unregister()


if __name__ == "__main__":
    try:
        main()
    except Exception:
        import traceback
        traceback.print_exc()
        sys.exit(1)
