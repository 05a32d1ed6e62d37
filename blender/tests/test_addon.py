"""The add-on in Blender, headless:
  blender -b --factory-startup --python-exit-code 1 --python test_addon.py -- uv_unwrap_seams.zip
Installs the zip through Blender's preferences, runs the operator on a
generated mesh (a UV sphere, quads and triangles, with marked seams and
sharp edges) in object and edit mode and on a mesh of CGAL's data set, and
checks: the UV map exists, no flipped face, no crossing UV borders, UVs in
[0,1], Blender's seams are the library's and the UV map's discontinuities,
marked seams kept, sharp edges not cut; a canceled run leaves the mesh as
it was."""
import os
import sys
import threading
import time
import traceback

import bpy
import numpy as np

failures = []


def empty_scene():
    """No object, no mesh left (read_factory_settings would also disable the add-on)."""
    if bpy.context.object is not None and bpy.context.object.mode != 'OBJECT':
        bpy.ops.object.mode_set(mode='OBJECT')
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    for m in list(bpy.data.meshes):
        bpy.data.meshes.remove(m)


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def loop_uvs(mesh, name=None):
    layer = mesh.uv_layers.get(name) if name else mesh.uv_layers.active
    uv = np.empty(2 * len(mesh.loops), dtype=np.float32)
    layer.data.foreach_get("uv", uv)
    return uv.reshape(-1, 2).astype(np.float64)


def edge_flags(mesh, name):
    flags = np.zeros(len(mesh.edges), dtype=bool)
    mesh.edges.foreach_get(name, flags)
    return flags


def snapshot(mesh):
    layers = {l.name: loop_uvs(mesh, l.name) for l in mesh.uv_layers}
    return layers, edge_flags(mesh, "use_seam").copy()


def uv_sides(mesh, uv):
    """{(a, b) with a < b: [(uv of a, uv of b), ...] per loop triangle side}."""
    mesh.calc_loop_triangles()
    sides = {}
    for t in mesh.loop_triangles:
        for k in range(3):
            la, lb = t.loops[k], t.loops[(k + 1) % 3]
            a, b = mesh.loops[la].vertex_index, mesh.loops[lb].vertex_index
            if a > b:
                a, b, la, lb = b, a, lb, la
            sides.setdefault((a, b), []).append((tuple(uv[la]), tuple(uv[lb])))
    return sides


def border_crossings(segments):
    """Pairs of UV segments that cross properly (sharing no end point)."""
    s = np.array(segments, dtype=np.float64)  # (B, 2, 2)
    if len(s) < 2:
        return 0
    p, q = s[:, 0], s[:, 1]

    def orient(a, b, c):
        return (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])

    P, Q = p[:, None], q[:, None]
    R, S = p[None, :], q[None, :]
    d1, d2 = orient(P, Q, R), orient(P, Q, S)
    d3, d4 = orient(R, S, P), orient(R, S, Q)
    cross = (d1 * d2 < 0) & (d3 * d4 < 0)
    return int(np.triu(cross, 1).sum())


def check_result(obj, label, marked=(), protected=(), library_seams=None):
    mesh = obj.data
    check(mesh.uv_layers.active is not None, f"{label}: a UV map exists")
    uv = loop_uvs(mesh)
    check(np.all(np.isfinite(uv)) and uv.min() >= 0 and uv.max() <= 1, f"{label}: UVs in [0,1]")
    mesh.calc_loop_triangles()
    loops = np.empty(3 * len(mesh.loop_triangles), dtype=np.int64)
    mesh.loop_triangles.foreach_get("loops", loops)
    c = uv[loops.reshape(-1, 3)]
    e1, e2 = c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]
    flipped = int(np.sum(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] <= 0))
    check(flipped == 0, f"{label}: 0 flipped faces ({flipped})")
    sides = uv_sides(mesh, uv)
    edge_index = {tuple(sorted(e.vertices)): e.index for e in mesh.edges}
    discontinuous, border = set(), []
    for key, s in sides.items():
        if len(s) == 2 and s[0] == s[1]:
            continue
        border.extend(s)
        if len(s) == 2:
            discontinuous.add(edge_index[key])
    crossings = border_crossings(border)
    check(crossings == 0, f"{label}: 0 crossing UV borders ({crossings} among {len(border)} border segments)")
    seams = set(np.flatnonzero(edge_flags(mesh, "use_seam")).tolist())
    check(seams == discontinuous, f"{label}: Blender's seams are the UV map's discontinuities "
                                  f"({len(seams)} seams, {len(discontinuous)} discontinuous edges)")
    if library_seams is not None:
        check(seams == library_seams, f"{label}: Blender's seams are the library's ({len(library_seams)})")
    check(set(marked) <= seams, f"{label}: the {len(marked)} marked seams are kept")
    check(not (set(protected) & seams), f"{label}: none of the {len(protected)} sharp edges is cut")
    return seams


def uv_sphere():
    """A UV sphere whose constraints matter: the edges that an unconstrained
    run cuts are marked sharp (never to cut), and part of another meridian,
    which it leaves, is marked as seams (to keep)."""
    from uv_unwrap_seams.job import Job
    empty_scene()
    bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16, radius=1.0)
    obj = bpy.context.active_object
    mesh = obj.data
    free = Job([obj], {}, keep_seams=False, protect=None)
    free.run()
    sharp = sorted(set(free.arrays[0].edge_indices(free.results[0].seams).tolist()))
    co = np.array([v.co[:] for v in mesh.vertices])
    marked = []
    for e in mesh.edges:
        a, b = co[e.vertices[0]], co[e.vertices[1]]
        if e.index in sharp:
            e.use_edge_sharp = True
        elif abs(a[0]) < 1e-6 and abs(b[0]) < 1e-6 and a[1] < 0 and b[1] < 0 and a[2] > 0.3 and b[2] > 0.3:
            e.use_seam = True  # part of a meridian of the northern side that the free run does not cut
            marked.append(e.index)
    return obj, marked, sharp


def off_mesh(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    n, m = int(tokens[1]), int(tokens[2])
    V = np.array(tokens[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    faces, i = [], 4 + 3 * n
    for _ in range(m):
        k = int(tokens[i])
        faces.append([int(x) for x in tokens[i + 1:i + 1 + k]])
        i += 1 + k
    empty_scene()
    mesh = bpy.data.meshes.new(os.path.basename(path))
    mesh.from_pydata(V.tolist(), [], faces)
    obj = bpy.data.objects.new(mesh.name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    return obj


def main():
    zip_path = sys.argv[sys.argv.index("--") + 1]
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="uv_unwrap_seams")
    from uv_unwrap_seams import backend
    from uv_unwrap_seams.job import Job
    check(backend.module() is not None, "the add-on loads the module uv_unwrap (%s)" % backend.problem())
    check(hasattr(bpy.ops.uv, "unwrap_optimized_seams"), "the operator is registered")

    # a generated mesh, object mode, through the operator as a script calls it
    obj, marked, sharp = uv_sphere()
    check(len(marked) > 0 and len(sharp) > 0, "the sphere has %d marked seams (that an unconstrained run does "
          "not cut) and %d sharp edges (all those it cuts)" % (len(marked), len(sharp)))
    job = Job([obj], {}, keep_seams=True, protect="sharp_edge")
    job.run()
    library = set(job.arrays[0].edge_indices(job.results[0].seams).tolist())
    start = time.perf_counter()
    result = bpy.ops.uv.unwrap_optimized_seams()
    print("operator on the sphere: %.2f s" % (time.perf_counter() - start))
    check(result == {'FINISHED'}, "the operator finishes from a script")
    check_result(obj, "sphere", marked, sharp, library_seams=library)

    # edit mode, into a new UV map, with another seam cost
    obj, marked, sharp = uv_sphere()
    bpy.ops.object.mode_set(mode='EDIT')
    result = bpy.ops.uv.unwrap_optimized_seams(seam_cost=3.0, new_uv_map=True, uv_map_name="Optimized",
                                               margin=4.0, texture_size=512)
    check(result == {'FINISHED'} and bpy.context.mode == 'EDIT_MESH', "edit mode: finished, still in edit mode")
    bpy.ops.object.mode_set(mode='OBJECT')
    check("Optimized" in obj.data.uv_layers and obj.data.uv_layers.active.name == "Optimized",
          "edit mode: the new UV map is written and active")
    check_result(obj, "sphere, edit mode", marked, sharp)

    # two selected objects at once; edges protected by a boolean edge attribute instead of sharpness
    obj, marked, sharp = uv_sphere()
    bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, location=(3, 0, 0))
    other = bpy.context.active_object
    keep = obj.data.attributes.new("uv_keep", 'BOOLEAN', 'EDGE')
    flags = np.zeros(len(obj.data.edges), dtype=bool)
    flags[sharp] = True
    keep.data.foreach_set("value", flags)
    for e in obj.data.edges:
        e.use_edge_sharp = False
    obj.select_set(True)
    result = bpy.ops.uv.unwrap_optimized_seams(protect='ATTRIBUTE', protect_attribute="uv_keep")
    check(result == {'FINISHED'}, "two objects: the operator finishes")
    check_result(obj, "first of two, attribute", marked, sharp)
    check_result(other, "second of two")

    # an option of the table (the inner solver, an enum property) reaches the library
    from uv_unwrap_seams import job as job_module
    ran = []
    original_run = job_module.Job.run

    def recording_run(self):
        original_run(self)
        ran.append(self)

    job_module.Job.run = recording_run
    try:
        uv_sphere()  # the same sphere twice (a run marks its seams, which the next would keep)
        bpy.ops.uv.unwrap_optimized_seams()
        obj, marked, sharp = uv_sphere()
        bpy.ops.uv.unwrap_optimized_seams(inner_solver='PROXY_QUASI_NEWTON')
    finally:
        job_module.Job.run = original_run
    newton, proxy = ran[-2], ran[-1]
    check("inner_solver" not in newton.options and proxy.options.get("inner_solver") == "proxy-quasi-newton",
          "the inner_solver property becomes unwrap()'s keyword (%s, %s)" % (newton.options, proxy.options))
    p, n = proxy.results[0].stats, newton.results[0].stats
    check(p["newton_iterations"] > n["newton_iterations"] and p["factorizations"] != n["factorizations"],
          "proxy quasi-Newton: more iterations than Newton, other factorizations (%d, %d against %d, %d)"
          % (p["newton_iterations"], p["factorizations"], n["newton_iterations"], n["factorizations"]))
    check_result(obj, "sphere, proxy quasi-Newton", marked, sharp)

    # a mesh of CGAL's data set
    data = os.environ.get("CGAL_DATA_DIR", "")
    path = os.path.join(data, "meshes", "elephant.off")
    if os.path.exists(path):
        obj = off_mesh(path)
        job = Job([obj], {})
        job.run()
        library = set(job.arrays[0].edge_indices(job.results[0].seams).tolist())
        result = bpy.ops.uv.unwrap_optimized_seams()
        check(result == {'FINISHED'}, "elephant.off: the operator finishes")
        check_result(obj, "elephant.off", library_seams=library)
    else:
        print("skip  CGAL's data set not found (%s)" % path)

    # the uv_unwrap program, for a Blender whose Python cannot load the module: the same result
    if os.environ.get("UV_UNWRAP"):
        obj, marked, sharp = uv_sphere()
        by_module = Job([obj], {"seam_cost": 1.5, "box": False}, protect="sharp_edge")
        by_module.run()
        os.environ["UV_UNWRAP_SEAMS_BACKEND"] = "uv_unwrap"
        try:
            by_program = Job([obj], {"seam_cost": 1.5, "box": False}, protect="sharp_edge")
            check(by_program.backend.startswith("program"), "the program is used when forced (%s)" % by_program.backend)
            by_program.run()
            a, b = by_module.results[0], by_program.results[0]
            check(np.array_equal(a.seams, b.seams) and np.array_equal(a.uv[a.faces_uv], b.uv[b.faces_uv])
                  and a.stats["distortion"] == b.stats["distortion"],
                  "the program gives the module's result (seams, UVs of every corner, E_d)")
            result = bpy.ops.uv.unwrap_optimized_seams()
            check(result == {'FINISHED'}, "the operator finishes on the program")
            check_result(obj, "sphere, uv_unwrap program", marked, sharp)
            # the table's options through the program's flags: the same as through the module
            options = {"inner_solver": "proxy-quasi-newton", "box_stiffness": 12.0, "allow_overlaps": False}
            by_flags = Job([obj], options, protect="sharp_edge")
            by_flags.run()
            os.environ.pop("UV_UNWRAP_SEAMS_BACKEND")
            by_keywords = Job([obj], options, protect="sharp_edge")
            by_keywords.run()
            os.environ["UV_UNWRAP_SEAMS_BACKEND"] = "uv_unwrap"
            a, b = by_keywords.results[0], by_flags.results[0]
            check(all(a.stats[k] == b.stats[k] for k in ("factorizations", "newton_iterations", "distortion")),
                  "inner_solver and box_stiffness as the program's flags: the module's result")
            canceled = Job([obj], {})
            canceled.cancel()
            canceled.run()
            check(canceled.cancelled and not canceled.succeeded(), "the program is stopped by a cancel")
        finally:
            del os.environ["UV_UNWRAP_SEAMS_BACKEND"]
    else:
        print("skip  UV_UNWRAP is not set: the program fallback is not tested")

    # cancel: a run stopped at its first progress report writes nothing
    obj, marked, sharp = uv_sphere()
    before = snapshot(obj.data)
    job = Job([obj], {})
    job.cancel()
    job.run()
    check(job.cancelled and not job.succeeded(), "a canceled job ends canceled")
    # and one canceled from another thread while it runs
    job = Job([obj], {})
    job.start()
    while job.running() and not job.phase:
        time.sleep(0.001)
    job.cancel()
    job._thread.join()
    check(job.cancelled, "a job canceled while running ends canceled (phase %s)" % job.phase)
    after = snapshot(obj.data)
    check(before[0].keys() == after[0].keys() and all(np.array_equal(before[0][k], after[0][k]) for k in before[0])
          and np.array_equal(before[1], after[1]), "cancel leaves the UV maps and seams untouched")


try:
    main()
except Exception:
    traceback.print_exc()
    failures.append("exception")
print("%d failures" % len(failures))
if failures:
    sys.exit(1)
