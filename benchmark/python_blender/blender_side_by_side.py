"""Blender's Smart UV Project (its defaults) against the add-on on the disk
meshes of the benchmark, inside Blender:

  blender -b --factory-startup --python blender_side_by_side.py -- ADDON.zip MESH_DIR OUT_DIR [MESH...]

For each mesh: imported from its OBJ, unwrapped by each method on a fresh
import, timed, its charts counted (faces joined across edges whose two sides
have the same UVs), and exported as OBJ with UVs (OUT_DIR/<mesh>_<method>.obj)
for uv_metrics.py, which measures E_d, E_s and overlaps independently. For the
add-on, the time is split into mesh in (Blender mesh to arrays), unwrap
(the library's time_seconds), Python (the rest of unwrap()'s wall time) and
mesh out (UVs and seams written), so that Blender's overhead is measured.
Writes OUT_DIR/blender.csv."""
import csv
import os
import sys
import time

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from smart_uv_project import export_obj as export, import_obj, smart_project  # noqa: E402

DISKS = ["bunnyhead", "hand1", "cat", "bimba", "bimba_i_f10000", "armadillo_i_f10000", "duck1", "planck1",
         "venus", "tooth", "circular_box_o_f20000", "face_f10000", "max_planck_i_f8000", "lion_o_f10000",
         "hand_1_i_f5000"]


def empty_scene():
    """No object, no mesh left (read_factory_settings would also disable the add-on)."""
    if bpy.context.object is not None and bpy.context.object.mode != 'OBJECT':
        bpy.ops.object.mode_set(mode='OBJECT')
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    for m in list(bpy.data.meshes):
        bpy.data.meshes.remove(m)


def charts(mesh):
    """Connected components of faces across edges whose two loops have the same UVs."""
    uv = np.empty(2 * len(mesh.loops), dtype=np.float32)
    mesh.uv_layers.active.data.foreach_get("uv", uv)
    uv = uv.reshape(-1, 2)
    parent = list(range(len(mesh.polygons)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    sides = {}
    for p in mesh.polygons:
        loops = list(p.loop_indices)
        for k, l in enumerate(loops):
            m = loops[(k + 1) % len(loops)]
            a, b = mesh.loops[l].vertex_index, mesh.loops[m].vertex_index
            key = (min(a, b), max(a, b))
            ends = {a: tuple(uv[l]), b: tuple(uv[m])}
            if key in sides:
                q, other = sides[key]
                if other == ends:
                    parent[root(p.index)] = root(q)
            else:
                sides[key] = (p.index, ends)
    return len({root(i) for i in range(len(parent))})


def fresh(path):
    empty_scene()
    return import_obj(path)


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    zip_path, mesh_dir, out_dir = args[:3]
    names = args[3:] or DISKS
    os.makedirs(out_dir, exist_ok=True)
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="uv_unwrap_seams")
    from uv_unwrap_seams.job import Job
    rows = []
    for name in names:
        path = os.path.join(mesh_dir, "optcuts", name + ".obj")
        if not os.path.exists(path):
            path = os.path.join(mesh_dir, "uvat", name + ".obj")
        obj = fresh(path)
        faces = len(obj.data.polygons)
        smart_s = smart_project()
        smart_charts = charts(obj.data)
        export(os.path.join(out_dir, name + "_smart_uv.obj"))

        obj = fresh(path)
        start = time.perf_counter()
        job = Job([obj], {})
        mesh_in = time.perf_counter() - start
        start = time.perf_counter()
        job.run()
        unwrap_wall = time.perf_counter() - start
        result = job.results[0]
        start = time.perf_counter()
        job.apply()
        mesh_out = time.perf_counter() - start
        unwrap_s = result.stats["time_seconds"]
        addon_charts = charts(obj.data)
        export(os.path.join(out_dir, name + "_addon.obj"))
        overhead = mesh_in + mesh_out + (unwrap_wall - unwrap_s)
        row = {"mesh": name, "faces": faces, "smart_s": smart_s, "smart_charts": smart_charts,
               "addon_s": mesh_in + unwrap_wall + mesh_out, "addon_charts": addon_charts,
               "addon_lib_charts": result.stats["charts"], "unwrap_s": unwrap_s, "mesh_in_s": mesh_in,
               "python_s": unwrap_wall - unwrap_s, "mesh_out_s": mesh_out,
               "overhead_pct": 100 * overhead / unwrap_s}
        rows.append(row)
        print("ROW " + ",".join(str(round(v, 4)) if isinstance(v, float) else str(v) for v in row.values()),
              flush=True)
    with open(os.path.join(out_dir, "blender.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


main()
