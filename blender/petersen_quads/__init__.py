"""Tris to Quads (Petersen): joins the selected triangles of a mesh into quads with petersen's
certified maximum pairing, or its certified cheapest one by quad shape.

Edit Mode > Face > Tris to Quads (Petersen), beside Blender's own Tris to Quads, with the same
options where they mean the same. Needs petersen's Python module: bundled in the add-on zip that
scripts/blender-addon-zip makes, or installed in Blender's Python (docs/blender.md).
"""

import importlib.util
import math
import sys

import bmesh
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty

from . import convert

bl_info = {
    "name": "Tris to Quads (Petersen)",
    "author": "petersen",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Edit Mode > Face > Tris to Quads (Petersen)",
    "description": "Join triangles into quads: the most pairs possible (certified), or the "
                   "best-shaped quads among them",
    "category": "Mesh",
}


def load_petersen():
    """petersen's Python module and None, or None and what to do to install it.

    The copy bundled in this add-on is preferred (it matches the add-on); else one installed in
    Blender's Python.
    """
    problems = []
    if importlib.util.find_spec(".petersen", __name__) is not None:
        try:
            from . import petersen as module
            return module, None
        except ImportError as error:
            problems.append(f"the copy bundled in the add-on does not load ({error})")
    try:
        import petersen as module
        return module, None
    except ImportError as error:
        problems.append(f"no petersen module in Blender's Python ({error})")
    version = f"{sys.version_info.major}.{sys.version_info.minor}"
    return None, (
        f"petersen's Python module is missing for Blender's Python {version}: "
        + "; ".join(problems)
        + ". Install the add-on zip made by scripts/blender-addon-zip with this Python "
          "(see docs/blender.md)")


class MESH_OT_petersen_tris_to_quads(bpy.types.Operator):
    """Join the selected triangles into quads: the most pairs possible (certified), or the best-shaped of those (Quality)"""

    bl_idname = "mesh.petersen_tris_to_quads"
    bl_label = "Tris to Quads (Petersen)"
    bl_options = {'REGISTER', 'UNDO'}

    # Blender's Tris to Quads options, same names and units. Off by default (180 degrees): the
    # Quads objective weighs every quad's shape and flow itself, and a threshold only takes pairs
    # away from it (Blender's 40 degrees leave many of a model's own quads split).
    face_threshold: FloatProperty(
        name="Max Face Angle",
        description="Keep the edges whose two triangles' normals differ by more than this "
                    "(180 degrees: no limit)",
        subtype='ANGLE', min=0.0, max=math.pi, default=math.pi)
    shape_threshold: FloatProperty(
        name="Max Shape Angle",
        description="Make no quad with a corner further than this from a right angle "
                    "(180 degrees: any shape)",
        subtype='ANGLE', min=0.0, max=math.pi, default=math.pi)
    uvs: BoolProperty(name="Compare UVs", description="Keep the edges where a UV map is cut")
    vcols: BoolProperty(name="Compare Color Attributes",
                        description="Keep the edges where a corner colour changes")
    seam: BoolProperty(name="Compare Seam", description="Keep the edges marked as seams")
    sharp: BoolProperty(name="Compare Sharp", description="Keep the edges marked sharp")
    materials: BoolProperty(name="Compare Materials",
                            description="Keep the edges between different materials")
    # petersen's own.
    objective: EnumProperty(
        name="Objective",
        items=[('QUADS', "Quads",
                "The quads people keep: the least total of the quads' shape and edge flow, a "
                "triangle left where pairing it would break better quads: a certified optimum"),
               ('PAIRS', "Pairs", "As many pairs as the options allow: a certified maximum"),
               ('QUALITY', "Quality",
                "As many pairs, and among those pairings the least total deviation of the "
                "quads' worst corners from right angles: a certified optimum")],
        default='QUADS')
    all_quad: BoolProperty(
        name="All Quads",
        description="Turn the triangles left into quads too, by splitting edges (adds vertices; "
                    "a face beyond the selection on a split edge gets the vertex too)")

    @classmethod
    def poll(cls, context):
        return context.mode == 'EDIT_MESH'

    def execute(self, context):
        petersen, problem = load_petersen()
        if petersen is None:
            self.report({'ERROR'}, problem)
            return {'CANCELLED'}
        objects = _meshes_in_edit_mode(context)
        # First every object's pairing, so that a mesh petersen refuses leaves all unchanged.
        plans = []
        try:
            for obj in objects:
                obj.update_from_editmode()
                plan = self._pair(petersen, obj)
                if plan is not None:
                    plans.append(plan)
        except ValueError as error:
            for plan in plans:
                bpy.data.meshes.remove(plan[1])
            self.report({'ERROR'}, f"Tris to Quads (Petersen): {error}")
            return {'CANCELLED'}

        with_normals = [p[0] for p in plans if p[0].data.has_custom_normals]
        if with_normals:
            bpy.ops.object.mode_set(mode='OBJECT')
            for obj in with_normals:
                convert.record_corner_normals(obj.data)
            bpy.ops.object.mode_set(mode='EDIT')
        pairs = left = 0
        total_cost = 0.0
        certified = True
        try:
            for obj, mesh, selection, result, used in plans:
                bm = bmesh.from_edit_mesh(obj.data)
                pairs += convert.make_quads(bm, mesh, selection, result, used)
                bmesh.update_edit_mesh(obj.data)
                left += result.stats["triangles_left"]
                total_cost += result.stats.get("objective_total", 0.0)
                certified &= bool(result.stats.get(
                    "maximum_certified" if self.objective == 'PAIRS'
                    else "optimality_certified", False))
        except RuntimeError as error:
            # The mesh may be partly changed: finish as one undo step that restores it.
            self.report({'ERROR'}, f"Tris to Quads (Petersen): {error}; the mesh may be partly "
                                   "converted: Undo restores it")
            return {'FINISHED'}
        finally:
            for plan in plans:
                bpy.data.meshes.remove(plan[1])
            if with_normals:
                bpy.ops.object.mode_set(mode='OBJECT')
                for obj in with_normals:
                    convert.restore_corner_normals(obj.data)
                bpy.ops.object.mode_set(mode='EDIT')

        message = f"{pairs} pairs, {left} triangles left"
        if self.all_quad and left:
            message += " (turned into quads)"
        if self.objective == 'QUALITY' and pairs:
            message += (f"; worst corners {total_cost / pairs:.1f}\u00b0 from square on average, "
                        + ("the certified least" if certified else "NOT certified"))
        elif self.objective == 'QUADS':
            message += "; the certified least cost" if certified else "; NOT certified"
        else:
            message += "; a certified maximum" if certified else "; NOT certified"
        self.report({'INFO'}, message)
        return {'FINISHED'}

    def _pair(self, petersen, obj):
        """petersen's pairing of the selected triangles of one object, as (object, a copy of its
        mesh data, selection, result, vertices used); None when it has none selected.

        The copy: in Edit Mode a mesh's UV maps and attributes are the BMesh's, without data, so
        they are read from a copy of the mesh as update_from_editmode wrote it (the caller
        removes it)."""
        mesh = obj.data.copy()
        try:
            selection = convert.selected_triangles(mesh)
            if len(selection.faces) == 0:
                bpy.data.meshes.remove(mesh)
                return None
            keep = convert.delimited_edges(
                mesh, selection, seam=self.seam, sharp=self.sharp, materials=self.materials,
                uvs=self.uvs, vcols=self.vcols)
            result, used = convert.pair_triangles(
                petersen, mesh, selection, keep,
                objective=self.objective.lower(), face_threshold=self.face_threshold,
                shape_threshold=self.shape_threshold, all_quad=self.all_quad)
        except ValueError as error:
            bpy.data.meshes.remove(mesh)
            raise ValueError(f"{obj.name}: {convert.in_blender_terms(error, selection)}") from None
        except Exception:
            bpy.data.meshes.remove(mesh)
            raise
        return obj, mesh, selection, result, used


def _meshes_in_edit_mode(context):
    """The mesh objects in Edit Mode, one per mesh data."""
    objects = getattr(context, "objects_in_mode_unique_data", None)
    if objects is None:  # no screen (e.g. a script run in the background)
        objects = [o for o in context.view_layer.objects if o.mode == 'EDIT']
    unique = {}
    for o in objects:
        if o.type == 'MESH':
            unique.setdefault(o.data.name, o)
    return list(unique.values())


class _LayoutAfterTrisToQuads:
    """A menu layout that passes everything through and adds this add-on's entry right after
    Blender's own Tris to Quads."""

    def __init__(self, layout):
        object.__setattr__(self, "_layout", layout)
        object.__setattr__(self, "placed", False)

    def __getattr__(self, name):
        return getattr(self._layout, name)

    def __setattr__(self, name, value):
        setattr(self._layout, name, value)

    def operator(self, idname, *args, **kwargs):
        props = self._layout.operator(idname, *args, **kwargs)
        if idname == "mesh.tris_convert_to_quads":
            self._layout.operator(MESH_OT_petersen_tris_to_quads.bl_idname)
            object.__setattr__(self, "placed", True)
        return props


class _MenuWithLayout:
    """The menu as its draw function sees it, with another layout."""

    def __init__(self, menu, layout):
        self._menu, self.layout = menu, layout

    def __getattr__(self, name):
        return getattr(self._menu, name)


_faces_menu_draw = None


def _draw_faces_menu(menu, context):
    layout = _LayoutAfterTrisToQuads(menu.layout)
    _faces_menu_draw(_MenuWithLayout(menu, layout), context)
    if not layout.placed:  # a Blender whose menu has no Tris to Quads entry
        menu.layout.separator()
        menu.layout.operator(MESH_OT_petersen_tris_to_quads.bl_idname)


def register():
    global _faces_menu_draw
    bpy.utils.register_class(MESH_OT_petersen_tris_to_quads)
    menu = bpy.types.VIEW3D_MT_edit_mesh_faces
    if _faces_menu_draw is None:
        _faces_menu_draw = menu.draw
        menu.draw = _draw_faces_menu


def unregister():
    global _faces_menu_draw
    if _faces_menu_draw is not None:
        menu = bpy.types.VIEW3D_MT_edit_mesh_faces
        if menu.draw is _draw_faces_menu:
            menu.draw = _faces_menu_draw
        else:  # another add-on appended to the menu since: put the original back in its list
            funcs = getattr(menu.draw, "_draw_funcs", [])
            if _draw_faces_menu in funcs:
                funcs[funcs.index(_draw_faces_menu)] = _faces_menu_draw
        _faces_menu_draw = None
    bpy.utils.unregister_class(MESH_OT_petersen_tris_to_quads)
