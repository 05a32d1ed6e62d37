"""Meshes and helpers shared by the tests of the uv_unwrap module."""
import math
import os

import numpy as np
import pytest


def spherical_cap(rings=12, segments=36, reach=0.92 * math.pi):
    """A cap of a unit sphere reaching `reach` from its pole: a disk too curved to flatten without seams."""
    V = [(0.0, 0.0, 1.0)]
    for k in range(rings):
        theta = reach * (k + 1) / rings
        for j in range(segments):
            phi = 2 * math.pi * j / segments
            V.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)))
    ring = lambda k, j: 1 + k * segments + j % segments
    F = []
    for j in range(segments):
        F.append((0, ring(0, j), ring(0, j + 1)))
        for k in range(rings - 1):
            F.append((ring(k, j), ring(k + 1, j), ring(k + 1, j + 1)))
            F.append((ring(k, j), ring(k + 1, j + 1), ring(k, j + 1)))
    return np.array(V, dtype=np.float64), np.array(F, dtype=np.int64)


def read_off(path):
    """Vertices and triangles of an OFF file (no repair)."""
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    assert tokens[0] == "OFF"
    n, m = int(tokens[1]), int(tokens[2])
    V = np.array(tokens[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    F, i = [], 4 + 3 * n
    for _ in range(m):
        k = int(tokens[i])
        F.append([int(t) for t in tokens[i + 1:i + 1 + k]])
        i += 1 + k
    return V, np.array(F, dtype=np.int64)


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        for p in V:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in F:
            f.write("3 %d %d %d\n" % tuple(t))


def data_mesh(name):
    """A mesh of CGAL's data set (libcgal-demo), extracted by CMake into build/data."""
    directory = os.environ.get("CGAL_DATA_DIR", "")
    path = os.path.join(directory, "meshes", name)
    if not directory or not os.path.exists(path):
        pytest.skip(f"CGAL's data set is not there ({path})")
    return read_off(path)


def corner_uvs(result):
    """(m, 3, 2): the UV of each corner of each face."""
    return result.uv[result.faces_uv]


def signed_areas(result):
    c = corner_uvs(result)
    e1, e2 = c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]
    return 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])


def edge_faces(F):
    """{(a, b) with a < b: [(face, corner of a, corner of b), ...]}."""
    edges = {}
    for j, t in enumerate(F):
        for k in range(3):
            a, b = int(t[k]), int(t[(k + 1) % 3])
            key = (min(a, b), max(a, b))
            ka, kb = (k, (k + 1) % 3) if a < b else ((k + 1) % 3, k)
            edges.setdefault(key, []).append((j, ka, kb))
    return edges


@pytest.fixture(scope="session")
def cap():
    return spherical_cap()
