"""The add-on's modal path, in a window (under a virtual X server):
  xvfb-run blender --factory-startup --enable-event-simulate --python test_addon_modal.py -- uv_unwrap_seams.zip
From the menu (INVOKE_DEFAULT in the 3D view) the operator returns at once
and runs on a worker thread while Blender's event loop goes on; when it ends
the UVs and seams are written, and one undo restores the mesh as it was; Esc
(a simulated key press) cancels it and leaves the mesh untouched. Exits with
status 1 on a failure."""
import sys
import time
import traceback

import bpy
import numpy as np

failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)


def state(obj):
    mesh = obj.data
    uv = np.empty(2 * len(mesh.loops), dtype=np.float32)
    mesh.uv_layers.active.data.foreach_get("uv", uv)
    seams = np.zeros(len(mesh.edges), dtype=bool)
    mesh.edges.foreach_get("use_seam", seams)
    return uv, seams


def view3d_context():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == 'VIEW_3D')
    region = next(r for r in area.regions if r.type == 'WINDOW')
    return window, dict(window=window, screen=window.screen, area=area, region=region)


def sphere(segments, rings):
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=segments, ring_count=rings)
    return bpy.context.active_object


def steps():
    """The test as a generator: each yield gives Blender's event loop back for that many seconds."""
    from uv_unwrap_seams import operator
    window, override = view3d_context()

    obj = sphere(32, 16)
    name = obj.name  # undo replaces the Python objects: look it up again by name
    bpy.ops.ed.undo_push(message="sphere")
    before = state(obj)
    with bpy.context.temp_override(**override):
        result = bpy.ops.uv.unwrap_optimized_seams('INVOKE_DEFAULT')
    check(result == {'RUNNING_MODAL'}, "from the menu it returns at once, running modally (%s)" % result)
    check(operator.running_job() is not None, "its job runs on a worker thread")
    start = time.monotonic()
    while operator.running_job() is not None and time.monotonic() - start < 120:
        yield 0.05  # Blender's event loop runs meanwhile
    check(operator.running_job() is None, "it ends (%.1f s)" % (time.monotonic() - start))
    obj = bpy.data.objects[name]
    after = state(obj)
    check(after[1].any() and not np.array_equal(before[0], after[0]), "the UVs and seams are written")
    check(after[0].min() >= 0 and after[0].max() <= 1, "UVs in [0,1]")
    with bpy.context.temp_override(**override):
        bpy.ops.ed.undo()
    yield 0.2
    undone = state(bpy.data.objects[name])
    check(np.array_equal(before[0], undone[0]) and np.array_equal(before[1], undone[1]),
          "one undo restores the UVs and seams")

    # Esc while it runs: a mesh large enough to take a few seconds
    obj = sphere(128, 64)
    name = obj.name
    before = state(obj)
    with bpy.context.temp_override(**override):
        result = bpy.ops.uv.unwrap_optimized_seams('INVOKE_DEFAULT')
    check(result == {'RUNNING_MODAL'}, "the large sphere runs modally")
    job = operator.running_job()
    while job is not None and not job.phase:
        yield 0.05
    window.event_simulate(type='ESC', value='PRESS')
    window.event_simulate(type='ESC', value='RELEASE')
    start = time.monotonic()
    while operator.running_job() is not None and time.monotonic() - start < 60:
        yield 0.05
    check(operator.running_job() is None and job.cancelled, "Esc cancels it (in %.2f s, at phase %s)"
          % (time.monotonic() - start, job.phase))
    after = state(bpy.data.objects[name])
    check(np.array_equal(before[0], after[0]) and np.array_equal(before[1], after[1]),
          "after Esc the UVs and seams are untouched")


def main():
    zip_path = sys.argv[sys.argv.index("--") + 1]
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="uv_unwrap_seams")
    run = steps()

    def tick():
        try:
            return next(run)
        except StopIteration:
            pass
        except Exception:
            traceback.print_exc()
            failures.append("exception")
        print("%d failures" % len(failures), flush=True)
        sys.stdout.flush()
        import os
        os._exit(1 if failures else 0)

    bpy.app.timers.register(tick, first_interval=0.5)


main()
