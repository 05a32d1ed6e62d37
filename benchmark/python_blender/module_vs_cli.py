"""unwrap() (the Python module) against uv_unwrap (the command line) on the
benchmark meshes, with the same (default) options: E_d and E_s of both, the
unwrap time (the library's time_seconds) and the Python overhead: the wall
time of unwrap() (arrays in, input checks, mesh built, results out as numpy
arrays and statistics) minus the library's time.

  /usr/bin/python3 module_vs_cli.py UV_UNWRAP MESH_DIR OUT.csv [MESH...]
(PYTHONPATH: the folder of the built module, build/python). Each mesh's OBJ
is read with numpy (no repair needed on these meshes: the check below
compares vertex and face counts with uv_unwrap's)."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import uv_unwrap

MESHES = ["bunnyhead", "hand1", "cat", "bimba", "bimba_i_f10000", "armadillo_i_f10000", "duck1", "planck1",
          "venus", "tooth", "circular_box_o_f20000", "face_f10000", "max_planck_i_f8000", "lion_o_f10000",
          "hand_1_i_f5000", "bunny", "cow_head", "sphere_f1522", "torus"]


def read_obj(path):
    V, F = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                V.append(line.split()[1:4])
            elif line.startswith("f "):
                F.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
    return np.array(V, dtype=np.float64), np.array(F, dtype=np.int64)


def find(mesh_dir, name):
    for sub in ("optcuts", "uvat"):
        path = os.path.join(mesh_dir, sub, name + ".obj")
        if os.path.exists(path):
            return path
    raise FileNotFoundError(name)


def main():
    program, mesh_dir, out = sys.argv[1:4]
    names = sys.argv[4:] or MESHES
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            path = find(mesh_dir, name)
            stats_file = os.path.join(tmp, "stats.json")
            subprocess.run([program, path, "-q", "-o", os.path.join(tmp, "out.obj"), "--stats", stats_file],
                           check=True)
            cli = json.load(open(stats_file))
            V, F = read_obj(path)
            start = time.perf_counter()
            r = uv_unwrap.unwrap(V, F)
            wall = time.perf_counter() - start
            py = r.stats
            assert (py["vertices"], py["faces"]) == (cli["vertices"], cli["faces"]), name
            row = {"mesh": name, "faces": len(F),
                   "cli_E_d": cli["distortion"], "py_E_d": py["distortion"],
                   "cli_E_s": cli["seam_length"], "py_E_s": py["seam_length"],
                   "same": py["distortion"] == cli["distortion"] and py["seam_length"] == cli["seam_length"],
                   "cli_unwrap_s": cli["time_seconds"], "py_unwrap_s": py["time_seconds"],
                   "py_wall_s": wall, "py_overhead_s": wall - py["time_seconds"],
                   "py_overhead_pct": 100 * (wall - py["time_seconds"]) / py["time_seconds"]}
            rows.append(row)
            print(",".join(str(round(v, 4)) if isinstance(v, float) else str(v) for v in row.values()), flush=True)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
