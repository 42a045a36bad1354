"""Blender's Tris to Quads on one mesh, timed, for the quality table (bench/quality_table.sh).

Run headless: blender -b --factory-startup --python bench/blender_tris_to_quads.py -- IN.obj OUT.obj MODE
MODE is "default" (the operator's defaults: face and shape thresholds 40 degrees, no seam, sharp,
UV, colour or material comparison) or "off" (both thresholds at 180 degrees: every pair allowed).
Times bmesh.ops.join_triangles alone, the operator's work (import and export are not timed), and
prints one line "blender MODE SECONDS"; OUT is read back by petersen_quality_bench, which applies
the same quality measure to every method.
"""

import math
import sys
import time

import bmesh
import bpy

args = sys.argv[sys.argv.index("--") + 1 :]
source, target, mode = args
degrees = {"default": 40.0, "off": 180.0}[mode]

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=source)
obj = bpy.context.selected_objects[0]
bm = bmesh.new()
bm.from_mesh(obj.data)
start = time.perf_counter()
bmesh.ops.join_triangles(
    bm,
    faces=bm.faces[:],
    cmp_seam=False,
    cmp_sharp=False,
    cmp_uvs=False,
    cmp_vcols=False,
    cmp_materials=False,
    angle_face_threshold=math.radians(degrees),
    angle_shape_threshold=math.radians(degrees),
)
seconds = time.perf_counter() - start
bm.to_mesh(obj.data)
bm.free()
bpy.ops.wm.obj_export(
    filepath=target,
    export_uv=False,
    export_normals=False,
    export_materials=False,
    apply_modifiers=False,
)
print(f"blender {mode} {seconds:.4f}", flush=True)
