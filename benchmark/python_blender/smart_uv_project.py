"""Blender's Smart UV Project with its defaults, shared by blender_side_by_side.py and, run as a
script, one OBJ in and out (scripts/blender_smart_uv_comparison.sh):

  blender -b --factory-startup --python smart_uv_project.py -- IN.obj OUT.obj

Prints "SMART_UV_SECONDS t" (the operator's time)."""
import sys
import time

import bpy


def import_obj(path):
    """Imports `path` and makes its object the active one."""
    bpy.ops.wm.obj_import(filepath=path)
    obj = bpy.context.selected_objects[0]
    bpy.context.view_layer.objects.active = obj
    return obj


def smart_project():
    """Smart UV Project on every face of the active object; returns the operator's time in seconds."""
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='SELECT')
    start = time.perf_counter()
    bpy.ops.uv.smart_project()
    seconds = time.perf_counter() - start
    bpy.ops.object.mode_set(mode='OBJECT')
    return seconds


def export_obj(path):
    """The selected objects as OBJ with UVs (no normals, no materials), for uv_metrics.py."""
    bpy.ops.wm.obj_export(filepath=path, export_selected_objects=True, export_uv=True, export_normals=False,
                          export_materials=False, apply_modifiers=False)


if __name__ == "__main__":
    src, dst = sys.argv[sys.argv.index('--') + 1:][:2]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import_obj(src)
    seconds = smart_project()
    export_obj(dst)
    print('SMART_UV_SECONDS', seconds)
