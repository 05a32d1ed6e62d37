# Blender's Smart UV Project with its defaults on one OBJ, written back as an OBJ with UVs:
#   blender -b --factory-startup --python scripts/blender_smart_uv_project.py -- IN.obj OUT.obj
# Prints "SMART_UV_SECONDS t" (the operator's time). Used by scripts/blender_smart_uv_comparison.sh.
import bpy, sys, time
src, dst = sys.argv[sys.argv.index('--') + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=src)
obj = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = obj
bpy.ops.object.mode_set(mode='EDIT')
bpy.ops.mesh.select_all(action='SELECT')
start = time.perf_counter()
bpy.ops.uv.smart_project()
seconds = time.perf_counter() - start
bpy.ops.object.mode_set(mode='OBJECT')
bpy.ops.wm.obj_export(filepath=dst, export_selected_objects=True, export_uv=True, export_normals=False,
                      export_materials=False)
print('SMART_UV_SECONDS', seconds)
