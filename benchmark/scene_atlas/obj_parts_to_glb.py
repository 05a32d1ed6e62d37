#!/usr/bin/env python3
"""An OBJ's connected parts as a glTF scene: one mesh, node and primitive per part (faces joined by
shared vertices), POSITION and 32-bit indices, as a game model exported part by part would be.
Polygons are fanned into triangles. Used to measure uv_unwrap --atlas on a scene of many primitives.
  obj_parts_to_glb.py IN.obj OUT.glb"""
import json
import struct
import sys


def read_obj(path):
    points, faces = [], []
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == "v":
            points.append(tuple(float(x) for x in t[1:4]))
        elif t[0] == "f":
            ids = [int(c.split("/")[0]) for c in t[1:]]
            ids = [i - 1 if i > 0 else len(points) + i for i in ids]
            faces += [(ids[0], ids[k], ids[k + 1]) for k in range(1, len(ids) - 1)]
    return points, faces


def parts(points, faces):
    parent = list(range(len(points)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for a, b, c in faces:
        parent[find(b)] = find(a)
        parent[find(c)] = find(a)
    groups = {}
    for f in faces:
        groups.setdefault(find(f[0]), []).append(f)
    return list(groups.values())


def write_glb(path, points, groups):
    binary, views, accessors, meshes, nodes = bytearray(), [], [], [], []
    for g in groups:
        used = sorted({i for f in g for i in f})
        local = {v: k for k, v in enumerate(used)}
        xyz = [points[v] for v in used]
        offset = len(binary)
        for p in xyz:
            binary += struct.pack("<3f", *p)
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(binary) - offset, "target": 34962})
        lo = [min(p[k] for p in xyz) for k in range(3)]
        hi = [max(p[k] for p in xyz) for k in range(3)]
        # bounds of the float32 values, as the validator checks them
        lo = [struct.unpack("<f", struct.pack("<f", x))[0] for x in lo]
        hi = [struct.unpack("<f", struct.pack("<f", x))[0] for x in hi]
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126, "count": len(xyz), "type": "VEC3",
                          "min": lo, "max": hi})
        offset = len(binary)
        for f in g:
            binary += struct.pack("<3I", *(local[i] for i in f))
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(binary) - offset, "target": 34963})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": 3 * len(g), "type": "SCALAR"})
        meshes.append({"primitives": [{"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1,
                                       "mode": 4}]})
        nodes.append({"mesh": len(meshes) - 1, "name": "part_%d" % len(nodes)})
    doc = {"asset": {"version": "2.0", "generator": "obj_parts_to_glb.py"}, "scene": 0,
           "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
           "accessors": accessors, "bufferViews": views, "buffers": [{"byteLength": len(binary)}]}
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    with open(path, "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(binary)))
        out.write(struct.pack("<I4s", len(text), b"JSON") + text)
        out.write(struct.pack("<I4s", len(binary), b"BIN\0") + bytes(binary))


if __name__ == "__main__":
    points, faces = read_obj(sys.argv[1])
    groups = parts(points, faces)
    write_glb(sys.argv[2], points, groups)
    print("%s: %d faces in %d parts -> %s" % (sys.argv[1], len(faces), len(groups), sys.argv[2]))
