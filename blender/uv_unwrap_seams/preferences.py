"""The add-on's preferences: the uv_unwrap program, for a Blender whose
Python cannot load the module (see backend.py)."""
import bpy
from bpy.props import StringProperty

from . import backend


class UnwrapSeamsPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    uv_unwrap_program: StringProperty(
        name="uv_unwrap program", subtype='FILE_PATH', default="",
        description="Used when Blender's Python cannot load the module uv_unwrap (empty: UV_UNWRAP, then the PATH)")

    def draw(self, context):
        layout = self.layout
        if backend.module() is not None:
            layout.label(text="Runs on the Python module uv_unwrap (%s)" % backend.module().__file__)
        else:
            layout.label(text=backend.problem() or "", icon='ERROR')
        layout.prop(self, "uv_unwrap_program")
