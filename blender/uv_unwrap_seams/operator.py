"""UV > Unwrap with optimized seams: the operator, its options (the redo
panel) and its two ways of running: invoke() (from the menu: a modal
operator, the work on a worker thread, progress in the status bar, Esc
cancels) and execute() (from a script, `blender -b`, or the redo panel:
to completion before it returns). Either way the mesh is written once at
the end, as one undo step, and left as it was on cancel or failure."""
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from . import options as option_table
from .job import Job


_running = []  # the job of the modal operator while it runs


def running_job():
    """The job of the operator running modally (from the menu), or None."""
    return _running[0] if _running else None


def _mesh_objects(context):
    return [o for o in context.selected_objects if o.type == 'MESH' and len(o.data.polygons) > 0]


class UV_OT_unwrap_optimized_seams(bpy.types.Operator):
    """Cut the selected meshes along short, hidden seams and unwrap them into a texture atlas without overlaps"""
    bl_idname = "uv.unwrap_optimized_seams"
    bl_label = "Unwrap with optimized seams"
    bl_options = {'REGISTER', 'UNDO'}

    # the method's options: added from the option table below (options.py)
    hide_seams: FloatProperty(name="Hide seams", default=0.0, min=0.0, soft_max=10.0,
                              description="Move seams to where the surface is least visible (0: off)")
    show_advanced: BoolProperty(name="Advanced", default=False, description="Show the method's other options")
    keep_seams: BoolProperty(name="Keep marked seams", default=True,
                             description="The seams already marked stay seams")
    protect: EnumProperty(name="Never cut", default='sharp_edge',
                          items=[('sharp_edge', "Sharp edges", "Edges marked sharp are never cut"),
                                 ('ATTRIBUTE', "Edge attribute", "Edges whose boolean attribute is set"),
                                 ('NONE', "Nothing", "Any edge may be cut")])
    protect_attribute: StringProperty(name="Attribute", default="uv_keep",
                                      description="Boolean edge attribute of the edges never to cut")
    new_uv_map: BoolProperty(name="New UV map", default=False,
                             description="Write a new UV map instead of the active one")
    uv_map_name: StringProperty(name="UV map name", default="OptimizedSeams")
    one_atlas: BoolProperty(name="One atlas for all selected objects", default=False,
                            description="Pack the charts of every selected object into one shared atlas at one "
                                        "texel density (a lightmap), instead of one atlas per object")

    # -- options
    def _options(self):
        options = option_table.keywords(self)
        if not self.one_atlas:
            options.pop("texels_per_unit", None)  # a scene atlas's density
            options.pop("stacking_tolerance", None)  # a scene atlas's sharing of texels
        if self.hide_seams:
            options["hide_seams"] = self.hide_seams
        return options

    def _job(self, context):
        protect = {'sharp_edge': "sharp_edge", 'ATTRIBUTE': self.protect_attribute, 'NONE': None}[self.protect]
        preferences = context.preferences.addons[__package__].preferences
        return Job(_mesh_objects(context), self._options(), keep_seams=self.keep_seams, protect=protect,
                   uv_map_name=self.uv_map_name if self.new_uv_map else None,
                   program=bpy.path.abspath(preferences.uv_unwrap_program), one_atlas=self.one_atlas)

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.prop(self, "preset", expand=True)  # the option table's row: default | fast, as toggle buttons
        layout.prop(self, "seam_cost")
        option_table.draw_row(layout, self, option_table.BY_KEYWORD["max_distortion"])
        layout.prop(self, "hide_seams")
        layout.prop(self, "margin")
        layout.prop(self, "texture_size")
        layout.prop(self, "one_atlas")
        if self.one_atlas:
            layout.prop(self, "texels_per_unit")
            option_table.draw_row(layout, self, option_table.BY_KEYWORD["stacking_tolerance"])
        layout.prop(self, "box")
        if self.box == 'TIGHT':
            layout.prop(self, "box_aspect")
        layout.prop(self, "keep_seams")
        layout.prop(self, "protect")
        if self.protect == 'ATTRIBUTE':
            layout.prop(self, "protect_attribute")
        layout.prop(self, "new_uv_map")
        if self.new_uv_map:
            layout.prop(self, "uv_map_name")
        layout.prop(self, "show_advanced")
        if self.show_advanced:
            box = layout.box()
            for row in option_table.advanced_rows():
                option_table.draw_row(box, self, row)

    @classmethod
    def poll(cls, context):
        return any(o.type == 'MESH' for o in context.selected_objects)

    # -- edit mode: the mesh data is read and written in object mode
    def _leave_edit_mode(self, context):
        self._was_edit = context.mode == 'EDIT_MESH'
        if self._was_edit:
            bpy.ops.object.mode_set(mode='OBJECT')

    def _restore_mode(self):
        if getattr(self, "_was_edit", False):
            bpy.ops.object.mode_set(mode='EDIT')

    def _finish(self, context, job):
        if job.cancelled:
            self._restore_mode()
            self.report({'INFO'}, "Unwrap canceled: the meshes are unchanged")
            return {'CANCELLED'}
        if not job.succeeded():
            self._restore_mode()
            self.report({'ERROR'}, "Unwrap failed: %s" % job.error)
            return {'CANCELLED'}
        job.apply()
        self._restore_mode()
        for w in job.warnings():
            self.report({'WARNING'}, w)
        self.report({'INFO'}, job.summary())
        return {'FINISHED'}

    # -- from a script or the redo panel: to completion
    def execute(self, context):
        if not _mesh_objects(context):
            self.report({'ERROR'}, "No selected mesh object with faces")
            return {'CANCELLED'}
        self._leave_edit_mode(context)
        try:
            job = self._job(context)
        except RuntimeError as e:
            self._restore_mode()
            self.report({'ERROR'}, str(e))
            return {'CANCELLED'}
        job.run()
        return self._finish(context, job)

    # -- from the menu: modal, on a worker thread
    def invoke(self, context, event):
        if not _mesh_objects(context):
            self.report({'ERROR'}, "No selected mesh object with faces")
            return {'CANCELLED'}
        self._leave_edit_mode(context)
        try:
            self._job_running = self._job(context)
        except RuntimeError as e:
            self._restore_mode()
            self.report({'ERROR'}, str(e))
            return {'CANCELLED'}
        self._job_running.start()
        _running[:] = [self._job_running]
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        wm.progress_begin(0, 100)
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        job = self._job_running
        if event.type == 'ESC':
            job.cancel()
        if event.type == 'TIMER':
            if job.running():
                context.workspace.status_text_set(job.status())
                context.window_manager.progress_update(int(100 * job.current / max(1, len(job.objects))))
                return {'RUNNING_MODAL'}
            self._end(context)
            return self._finish(context, job)
        # the view can still be turned and zoomed; editing waits for the result
        if event.type in {'MIDDLEMOUSE', 'WHEELUPMOUSE', 'WHEELDOWNMOUSE', 'TRACKPADPAN', 'TRACKPADZOOM',
                          'MOUSEMOVE', 'INBETWEEN_MOUSEMOVE'}:
            return {'PASS_THROUGH'}
        return {'RUNNING_MODAL'}

    def _end(self, context):
        _running.clear()
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)


option_table.add_properties(UV_OT_unwrap_optimized_seams)


def menu_entry(self, context):
    self.layout.separator()
    self.layout.operator(UV_OT_unwrap_optimized_seams.bl_idname)
