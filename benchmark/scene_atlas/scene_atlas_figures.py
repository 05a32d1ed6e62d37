#!/usr/bin/env python3
"""The figures of a uv_unwrap --atlas run, from what it wrote: the texel density of every mesh (texels per
unit of 3D length: page side * sqrt(UV area / 3D area); OBJ outputs, and each primitive of glb outputs) and
its spread, with the pages' measures of the statistics (combined UVs: flips, crossings, overlap, coverage).
  scene_atlas_figures.py STATS.jsonl PAGE_SIDE [UV_SET]"""
import json
import math
import struct
import sys


def area3(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * math.sqrt(sum(x * x for x in n))


def area2(a, b, c):
    return 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def obj_meshes(path):
    v, vt, a3, a2 = [], [], 0.0, 0.0
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == "v":
            v.append([float(x) for x in t[1:4]])
        elif t[0] == "vt":
            vt.append([float(x) for x in t[1:3]])
        elif t[0] == "f":
            c = [x.split("/") for x in t[1:4]]
            a3 += area3(*(v[int(x[0]) - 1] for x in c))
            a2 += area2(*(vt[int(x[1]) - 1] for x in c))
    return [(path, a3, a2)]


def glb_meshes(path, uv_set):
    data = open(path, "rb").read()
    length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + length])
    binary = data[20 + length + 8:]

    def read(index, n):
        a = doc["accessors"][index]
        view = doc["bufferViews"][a["bufferView"]]
        offset = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        fmt = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}[a["componentType"]]
        size = struct.calcsize(fmt)
        stride = view.get("byteStride", size * n)
        return [struct.unpack_from("<%d%s" % (n, fmt), binary, offset + i * stride) for i in range(a["count"])]
    out = []
    for m, mesh in enumerate(doc["meshes"]):
        for p, prim in enumerate(mesh["primitives"]):
            xyz = read(prim["attributes"]["POSITION"], 3)
            uv = read(prim["attributes"]["TEXCOORD_%d" % uv_set], 2)
            idx = [i[0] for i in read(prim["indices"], 1)]
            a3 = sum(area3(*(xyz[i] for i in idx[k:k + 3])) for k in range(0, len(idx), 3))
            a2 = sum(area2(*(uv[i] for i in idx[k:k + 3])) for k in range(0, len(idx), 3))
            out.append(("%s mesh %d primitive %d" % (path, m, p), a3, a2))
    return out


def main():
    stats = [json.loads(line) for line in open(sys.argv[1])]
    side = float(sys.argv[2])
    uv_set = int(sys.argv[3]) if len(sys.argv) > 3 else 0
    densities = []
    for s in stats:
        path = s["output"]
        meshes = obj_meshes(path) if path.endswith(".obj") else glb_meshes(path, uv_set)
        densities += [side * math.sqrt(a2 / a3) for _, a3, a2 in meshes]
    a = stats[0]["atlas"]
    print("%d inputs, %d meshes, %d faces; %d pages, %.6g texels per unit (reported)"
          % (len(stats), len(densities), sum(s["faces"] for s in stats), a["page_count"], a["texels_per_unit"]))
    print("density of the meshes: min %.6g max %.6g, spread %.4f %%"
          % (min(densities), max(densities), 100 * (max(densities) / min(densities) - 1)))
    for p in a["page_measures"]:
        print("page %(page)d: %(meshes)d meshes, %(faces)d faces, coverage %(uv_coverage).4f, flipped %(flipped_faces)d, "
              "crossings %(border_crossings)d, overlap %(overlap_area)g" % p)


main()
