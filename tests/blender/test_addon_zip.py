"""The add-on zip of scripts/blender-addon-zip, installed as a user installs it, in headless
Blender:

    BLENDER_USER_SCRIPTS=$(mktemp -d) blender -b --factory-startup \
        --python tests/blender/test_addon_zip.py -- out/petersen_quads-....zip

Installs the zip into BLENDER_USER_SCRIPTS (required, so that no real user's add-ons are
touched), enables it, and checks that the operator runs with the module bundled in the zip.
Exits 1 on failure.
"""

import os
import sys
import traceback

import bmesh
import bpy


def main():
    zip_path = os.path.abspath(sys.argv[sys.argv.index("--") + 1])
    scripts = os.environ.get("BLENDER_USER_SCRIPTS")
    if not scripts:
        raise SystemExit("set BLENDER_USER_SCRIPTS to a scratch folder: the zip is installed there")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="petersen_quads")
    import petersen_quads
    module, problem = petersen_quads.load_petersen()
    assert module is not None, problem
    assert module.__name__ == "petersen_quads.petersen", module.__name__
    assert os.path.realpath(module.__file__).startswith(os.path.realpath(scripts)), module.__file__
    print(f"ok   the zip installs and its bundled module loads ({module.__file__})")

    bpy.ops.mesh.primitive_cube_add()
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='SELECT')
    bpy.ops.mesh.quads_convert_to_tris()
    assert bpy.ops.mesh.petersen_tris_to_quads() == {'FINISHED'}
    faces = bmesh.from_edit_mesh(bpy.context.object.data).faces
    assert sorted(len(f.verts) for f in faces) == [4] * 6, [len(f.verts) for f in faces]
    print("ok   the installed operator turns a triangulated cube back into 6 quads")
    bpy.ops.preferences.addon_disable(module="petersen_quads")


try:
    main()
except Exception:
    traceback.print_exc()
    print("FAILED", flush=True)
    sys.exit(1)
print("2 passed, 0 failed", flush=True)
