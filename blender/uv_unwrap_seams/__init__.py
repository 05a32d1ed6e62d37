"""Unwrap with optimized seams: seams and UV map found together (the
Ambrosio-Tortorelli method of the CGAL cut-parameterization package),
through its Python module uv_unwrap (or its uv_unwrap program)."""

bl_info = {
    "name": "Unwrap with optimized seams",
    "author": "CGAL cut parameterization contributors",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "3D Viewport: UV (edit mode), Object (object mode); UV Editor: UV > Unwrap",
    "description": "Short, hidden seams and a flip-free, overlap-free texture atlas, optimized together",
    "category": "UV",
}

if "bpy" in locals():  # reloaded by Blender: reload the parts too
    import importlib
    from . import options, uv_unwrap_cli, backend, mesh_arrays, job, operator, preferences
    for part in (options, uv_unwrap_cli, backend, mesh_arrays, job, operator, preferences):
        importlib.reload(part)

import bpy  # noqa: E402

from .operator import UV_OT_unwrap_optimized_seams, menu_entry  # noqa: E402
from .preferences import UnwrapSeamsPreferences  # noqa: E402



def _object_menu(self, context):
    self.layout.operator(UV_OT_unwrap_optimized_seams.bl_idname)


def register():
    bpy.utils.register_class(UnwrapSeamsPreferences)
    bpy.utils.register_class(UV_OT_unwrap_optimized_seams)
    bpy.types.VIEW3D_MT_uv_map.append(menu_entry)
    if hasattr(bpy.types, "IMAGE_MT_uvs_unwrap"):
        bpy.types.IMAGE_MT_uvs_unwrap.append(menu_entry)
    bpy.types.VIEW3D_MT_object.append(_object_menu)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(_object_menu)
    if hasattr(bpy.types, "IMAGE_MT_uvs_unwrap"):
        bpy.types.IMAGE_MT_uvs_unwrap.remove(menu_entry)
    bpy.types.VIEW3D_MT_uv_map.remove(menu_entry)
    bpy.utils.unregister_class(UV_OT_unwrap_optimized_seams)
    bpy.utils.unregister_class(UnwrapSeamsPreferences)
