"""A picture made by Blender of its own Tris to Quads beside petersen's: docs/images/blender-quads.png
and docs/images/blender-recovery.png.

    PETERSEN_PYTHONPATH=DIR blender -b --factory-startup --python bench/blender_render_quads.py \
        -- MESH OUT.png [DEGREES]
    ... -- MODEL OUT.png --recover LEVELS

Reads MESH (petersen.read_mesh; a Y-up mesh such as the bunny is turned Z-up), converts every face
of one copy with Blender's mesh.tris_convert_to_quads and of another with petersen's operator
(objective QUALITY), both with face and shape limits of DEGREES (default 180: no limit), and
renders them side by side headless with Workbench: quads shaded from white (right angles) to blue
(worst corner 45 degrees or more from a right angle, petersen.quad_quality), the triangles left
orange, every edge drawn (a Wireframe modifier on a copy), a caption under each.
docs/images/blender-quads.png is bunny.off.gz of the shared meshes at 180 degrees.

--recover LEVELS: MODEL is made a quad model as bench/quad_recovery.py makes them (Blender's
Catmull-Clark at LEVELS), exported as triangles one shorter diagonal per quad, as exporters cut
them, and brought back by each operator at its defaults (Blender's 40-degree limits; petersen's
add-on: objective Quads, no limits); each caption gives the share of the model's quads that come
back. docs/images/blender-recovery.png is suzanne.obj of pmp-library/pmp-data at level 1.
"""

import math
import os
import pathlib
import struct
import sys
import types
import zlib

sys.path[:0] = [p for p in os.environ.get("PETERSEN_PYTHONPATH", "").split(os.pathsep) if p]
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "blender"))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import bmesh  # noqa: E402
import bpy  # noqa: E402
import numpy as np  # noqa: E402
from mathutils import Matrix, Vector  # noqa: E402

import petersen  # noqa: E402
import petersen_quads  # noqa: E402
from blender_side_by_side import make_object  # noqa: E402
from quad_recovery import catmull_clark, clear, triangulate  # noqa: E402

WIRE = (0.08, 0.08, 0.1, 1.0)
LEFT = (1.0, 0.45, 0.05, 1.0)


def convert(name, mesh, operator, angle):
    """A copy of mesh converted by operator (its default limits when angle is None); the object
    and its faces' vertex lists."""
    objects = [o for o in bpy.data.objects]
    obj = make_object(name, mesh, keep=objects)
    obj.data.transform(Matrix.Rotation(math.pi / 2, 4, 'X'))  # Y-up to Z-up
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='SELECT')
    operator(**({} if angle is None else {"face_threshold": angle, "shape_threshold": angle}))
    bm = bmesh.from_edit_mesh(obj.data)
    faces = [[v.index for v in f.verts] for f in bm.faces]
    bpy.ops.object.mode_set(mode='OBJECT')
    return obj, faces


def quad_model(path, levels):
    """MODEL's Catmull-Clark at levels, cut one shorter diagonal per quad: the triangle mesh (with
    V and F) and the set of the quads' vertex sets."""
    mesh = petersen.read_mesh(path)
    V, quads = catmull_clark(mesh.V, [list(f) for f in mesh.F], levels)
    clear()  # the subdivided object: only the two converted copies are drawn
    triangles, originals = triangulate(V, quads, "short", np.random.default_rng(1))
    return types.SimpleNamespace(V=V, F=np.array(triangles, np.int64)), originals


def captions(mesh, faces_theirs, faces_ours, originals):
    """The two captions: triangles left, and with a quad model the share of its quads back."""
    def told(faces):
        left = sum(len(f) == 3 for f in faces)
        if not originals:
            return f"{left:,} of {len(mesh.F):,} triangles left"
        back = sum(len(f) == 4 and frozenset(f) in originals for f in faces)
        return f"{100.0 * back / len(originals):.1f} % of the quads back"
    if originals:
        return (f"Blender's Tris to Quads: {told(faces_theirs)}",
                f"petersen: {told(faces_ours)}")
    return (f"Blender's Tris to Quads: {told(faces_theirs)}",
            f"petersen (Quality): {told(faces_ours)}")


def colour_faces(obj):
    """A corner colour attribute: quads by worst corner, triangles orange."""
    me = obj.data
    V = np.array([v.co for v in me.vertices], float)
    colours = me.color_attributes.new("shade", 'BYTE_COLOR', 'CORNER')
    for p in me.polygons:
        if p.loop_total == 4:
            cost = petersen.quad_quality(V, np.array([list(p.vertices)]))[0]
            t = min(cost / 45.0, 1.0)
            colour = (1.0 - 0.75 * t, 1.0 - 0.55 * t, 1.0 - 0.1 * t, 1.0)
        else:
            colour = LEFT
        for li in p.loop_indices:
            colours.data[li].color = colour


def add_wire(obj, thickness):
    wire = obj.copy()
    wire.data = obj.data.copy()
    bpy.context.scene.collection.objects.link(wire)
    for c in wire.data.color_attributes["shade"].data:
        c.color = WIRE
    modifier = wire.modifiers.new("edges", 'WIREFRAME')
    modifier.thickness = thickness
    modifier.use_replace = True


def add_caption(text, location, size):
    curve = bpy.data.curves.new("caption", 'FONT')
    curve.body = text
    curve.size = size
    curve.align_x = 'CENTER'
    caption = bpy.data.objects.new("caption", curve)
    bpy.context.scene.collection.objects.link(caption)
    caption.location = location
    caption.rotation_euler = (math.pi / 2, 0, 0)  # facing the camera, which looks along +Y
    caption.color = WIRE


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    source, target = args[0], os.path.abspath(args[1])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    petersen_quads.register()
    if "--recover" in args:
        mesh, originals = quad_model(source, int(args[args.index("--recover") + 1]))
        theirs, their_faces = convert("blender", mesh, bpy.ops.mesh.tris_convert_to_quads, None)
        ours, our_faces = convert("petersen", mesh, bpy.ops.mesh.petersen_tris_to_quads, None)
    else:
        angle = math.radians(float(args[2]) if len(args) > 2 else 180.0)
        mesh, originals = petersen.read_mesh(source), set()
        theirs, their_faces = convert("blender", mesh, bpy.ops.mesh.tris_convert_to_quads, angle)
        ours, our_faces = convert(
            "petersen", mesh,
            lambda **o: bpy.ops.mesh.petersen_tris_to_quads(objective='QUALITY', **o), angle)
    their_caption, our_caption = captions(mesh, their_faces, our_faces, originals)

    corners = np.array([v.co for v in ours.data.vertices])
    low, high = corners.min(axis=0), corners.max(axis=0)
    width, height = high[0] - low[0], high[2] - low[2]
    size = float(np.linalg.norm(high - low))
    gap = 0.08 * width
    theirs.location.x = -(width + gap) / 2
    ours.location.x = (width + gap) / 2
    centre = Vector(((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2))
    for obj in (theirs, ours):
        obj.location -= Vector((centre.x, 0, 0))
        colour_faces(obj)
        add_wire(obj, size * 0.0011)
    below = low[2] - 0.09 * height
    add_caption(their_caption, (-(width + gap) / 2, low[1], below), 0.04 * width)
    add_caption(our_caption, ((width + gap) / 2, low[1], below), 0.04 * width)

    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    bpy.context.scene.collection.objects.link(camera)
    camera.location = (0.0, low[1] - 3 * size, (low[2] + high[2]) / 2 - 0.06 * height)
    camera.rotation_euler = (math.pi / 2, 0, 0)  # looking along +Y
    camera.data.type = 'ORTHO'
    camera.data.ortho_scale = 2 * width + 2 * gap

    scene = bpy.context.scene
    scene.camera = camera
    scene.render.engine = 'BLENDER_WORKBENCH'
    scene.render.resolution_x, scene.render.resolution_y = 900, 470
    scene.display.render_aa = 'FXAA'  # fewer blended colours: a smaller PNG
    scene.view_settings.view_transform = 'Standard'  # white stays white
    scene.render.image_settings.color_mode = 'RGB'
    scene.render.image_settings.compression = 100
    scene.render.filepath = target
    shading = scene.display.shading
    shading.light = 'STUDIO'
    shading.color_type = 'VERTEX'
    scene.world = bpy.data.worlds.new("world")
    scene.world.color = (1.0, 1.0, 1.0)
    bpy.ops.render.render(write_still=True)
    shrink_png(target)
    print(f"wrote {target}: {their_caption}; {our_caption}")


def shrink_png(path, levels=24):
    """Rewrites the PNG at path with each channel rounded to one of ``levels`` values and every
    row filtered by its left neighbour ("Sub"): a third of the size, the difference hard to see."""
    image = bpy.data.images.load(path)
    width, height = image.size
    pixels = np.array(image.pixels[:], np.float32).reshape(height, width, -1)[::-1, :, :3]
    bpy.data.images.remove(image)
    rgb = (np.round(pixels * (levels - 1)) * (255 / (levels - 1))).astype(np.uint8)
    sub = rgb.astype(np.int16)
    sub[:, 1:] -= rgb[:, :-1]
    rows = np.concatenate([np.ones((height, 1), np.uint8),
                           (sub % 256).astype(np.uint8).reshape(height, -1)], axis=1)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
                  + chunk(b"IDAT", zlib.compress(rows.tobytes(), 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    try:
        main()
    except Exception:
        import traceback
        traceback.print_exc()
        sys.exit(1)
