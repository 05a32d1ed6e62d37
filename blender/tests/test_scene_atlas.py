"""One atlas for a scene, in Blender, headless:
  UV_UNWRAP=<uv_unwrap> blender -b --factory-startup --python-exit-code 1 --python test_scene_atlas.py -- uv_unwrap_seams.zip
1. The add-on's "one atlas for all selected objects" on three objects of different sizes: every UV in
   [0,1], one page, no flipped face, no crossing of UV borders and no overlap across the objects (their
   UVs together), the same texel density (UV area / 3D area) for all within 1%.
2. uv_unwrap --atlas --uv-set 1 on a glb that Blender exported (two meshes, each with its UV map): Blender
   imports the result with both UV maps, the first as it was, the second (the lightmap) in [0,1]."""
import json
import os
import subprocess
import sys
import tempfile

import bpy
import numpy as np

failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def empty_scene():
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    for m in list(bpy.data.meshes):
        bpy.data.meshes.remove(m)


def triangles(obj, layer_name=None):
    """(t, 3, 3) world-free positions and (t, 3, 2) UVs of the object's loop triangles."""
    mesh = obj.data
    mesh.calc_loop_triangles()
    loops = np.empty(3 * len(mesh.loop_triangles), dtype=np.int64)
    mesh.loop_triangles.foreach_get("loops", loops)
    verts = np.empty(3 * len(mesh.loop_triangles), dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", verts)
    co = np.empty(3 * len(mesh.vertices), dtype=np.float64)
    mesh.vertices.foreach_get("co", co)
    layer = mesh.uv_layers[layer_name] if layer_name else mesh.uv_layers.active
    uv = np.empty(2 * len(mesh.loops), dtype=np.float32)
    layer.data.foreach_get("uv", uv)
    return co.reshape(-1, 3)[verts.reshape(-1, 3)], uv.reshape(-1, 2).astype(np.float64)[loops.reshape(-1, 3)]


def signed_areas(t):
    e1, e2 = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
    return 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])


def overlap_fraction(uv_triangles, n=512):
    """Share of the covered centres of an n x n raster of [0,1]^2 that lie inside two or more triangles."""
    count = np.zeros((n, n), dtype=np.int32)
    for t in uv_triangles:
        lo = np.clip(np.floor(t.min(axis=0) * n - 0.5).astype(int), 0, n - 1)
        hi = np.clip(np.ceil(t.max(axis=0) * n - 0.5).astype(int), 0, n - 1)
        xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1), np.arange(lo[1], hi[1] + 1), indexing="ij")
        p = np.stack([(xs + 0.5) / n, (ys + 0.5) / n], axis=-1)
        inside = np.ones(xs.shape, dtype=bool)
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            inside &= (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0]) > 0
        count[xs[inside], ys[inside]] += 1
    covered = (count > 0).sum()
    return float((count > 1).sum()) / max(covered, 1)


def crossings(segments):
    """Pairs of UV border segments that cross properly."""
    s = np.array(segments, dtype=np.float64)
    if len(s) < 2:
        return 0
    p, q = s[:, 0], s[:, 1]

    def orient(a, b, c):
        return (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])

    P, Q, R, S = p[:, None], q[:, None], p[None, :], q[None, :]
    cross = (orient(P, Q, R) * orient(P, Q, S) < 0) & (orient(R, S, P) * orient(R, S, Q) < 0)
    return int(np.triu(cross, 1).sum())


def border_segments(positions, uv):
    """The UV sides of triangles whose 3D edge has no other triangle with the same UVs."""
    sides = {}
    for t in range(len(positions)):
        for k in range(3):
            a, b = tuple(positions[t][k]), tuple(positions[t][(k + 1) % 3])
            key = (min(a, b), max(a, b))
            ua, ub = tuple(uv[t][k]), tuple(uv[t][(k + 1) % 3])
            sides.setdefault(key, []).append((ua, ub) if a <= b else (ub, ua))
    out = []
    for s in sides.values():
        if len(s) == 2 and s[0] == s[1]:
            continue
        out.extend(s)
    return out


def one_atlas_operator():
    empty_scene()
    bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, radius=1.0, location=(0, 0, 0))
    bpy.ops.mesh.primitive_torus_add(major_radius=2.0, minor_radius=0.5, location=(5, 0, 0))
    bpy.ops.mesh.primitive_cylinder_add(vertices=16, radius=0.5, depth=3.0, location=(-5, 0, 0))
    objects = list(bpy.data.objects)
    for o in objects:
        o.select_set(True)
    result = bpy.ops.uv.unwrap_optimized_seams(one_atlas=True, margin=2.0, texture_size=512)
    check(result == {'FINISHED'}, "one atlas: the operator finishes")
    all_uv, segments, density = [], [], []
    for o in objects:
        positions, uv = triangles(o)
        check(uv.min() >= 0 and uv.max() <= 1, "%s: UVs in [0,1]" % o.name)
        flipped = int((signed_areas(uv) <= 0).sum())
        check(flipped == 0, "%s: 0 flipped faces (%d)" % (o.name, flipped))
        e1, e2 = positions[:, 1] - positions[:, 0], positions[:, 2] - positions[:, 0]
        area_3d = 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1).sum()
        density.append(np.sqrt(np.abs(signed_areas(uv)).sum() / area_3d))
        all_uv.extend(uv)
        segments.extend(border_segments(positions, uv))
    spread = max(density) / min(density) - 1
    check(spread < 0.01, "one atlas: the texel density is the same for the %d objects within 1%% (%.4f%%)"
          % (len(objects), 100 * spread))
    n = crossings(segments)
    check(n == 0, "one atlas: 0 crossings among the %d border segments of all objects (%d)" % (len(segments), n))
    overlap = overlap_fraction(np.array(all_uv))
    check(overlap == 0, "one atlas: no texel covered by two objects or charts (%.5f)" % overlap)
    coverage = sum(abs(signed_areas(np.array(all_uv))))
    print("one atlas of %d objects: coverage %.3f" % (len(objects), coverage))


def gltf_uv_set(program):
    empty_scene()
    bpy.ops.mesh.primitive_cube_add(size=2.0, location=(0, 0, 0))
    bpy.ops.mesh.primitive_uv_sphere_add(segments=16, ring_count=8, radius=1.0, location=(4, 0, 0))
    for o in bpy.data.objects:
        check(len(o.data.uv_layers) == 1, "%s has Blender's own UV map before the export" % o.name)
    before = {o.name: triangles(o)[1] for o in bpy.data.objects}
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, "scene.glb")
        bpy.ops.export_scene.gltf(filepath=scene, export_format='GLB')
        out = os.path.join(tmp, "out")
        run = subprocess.run([program, scene, "--atlas", "--uv-set", "1", "--output-dir", out, "--jsonl",
                              os.path.join(tmp, "stats.jsonl"), "-q"], capture_output=True, text=True)
        check(run.returncode == 0, "uv_unwrap --atlas --uv-set 1 on Blender's glb (%s)" % run.stderr.strip())
        stats = [json.loads(line) for line in open(os.path.join(tmp, "stats.jsonl"))]
        check(len(stats) == 1 and stats[0]["atlas"]["page_count"] == 1 and len(stats[0]["atlas"]["pages"]) == 2,
              "the statistics give the page of each of the 2 meshes")
        empty_scene()
        if not hasattr(np, "bool"):  # Debian's Blender 3.4 importer uses np.bool, gone from numpy 1.24
            np.bool = bool
        bpy.ops.import_scene.gltf(filepath=os.path.join(out, "scene_uv.glb"))
    meshes = [o for o in bpy.data.objects if o.type == 'MESH']
    check(len(meshes) == 2, "Blender imports the 2 meshes of the result")
    for o in meshes:
        layers = o.data.uv_layers
        check(len(layers) == 2, "%s: 2 UV maps after the import (%s)" % (o.name, [l.name for l in layers]))
        if len(layers) != 2:
            continue
        _, first = triangles(o, layers[0].name)
        name = o.name.split(".")[0]
        distinct = lambda uv: {tuple(p) for p in np.round(uv.reshape(-1, 2), 4)}
        check(name in before and distinct(first) == distinct(before[name]),
              "%s: the material's UV map is kept (its distinct UVs)" % o.name)
        _, second = triangles(o, layers[1].name)
        check(second.min() >= 0 and second.max() <= 1 and not np.allclose(second, first),
              "%s: the lightmap UV map is in [0,1] and differs from the first" % o.name)


def main():
    zip_path = sys.argv[sys.argv.index("--") + 1]
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="uv_unwrap_seams")
    one_atlas_operator()
    program = os.environ.get("UV_UNWRAP", "")
    check(os.path.isfile(program), "UV_UNWRAP names the uv_unwrap program (%r)" % program)
    if os.path.isfile(program):
        gltf_uv_set(program)
    print("%d failures" % len(failures))
    sys.exit(1 if failures else 0)


main()
