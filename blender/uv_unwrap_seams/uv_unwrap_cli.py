"""unwrap() through the uv_unwrap program, for a Blender whose Python cannot
load the module: the mesh goes out as an OFF file (17 digits: the same
numbers), the seams to keep and the edges never to cut as selection files;
the result comes back from the OBJ (uv_unwrap keeps the vertices and faces
of a mesh that needs no repair), the --save-seams file and the --stats JSON.
The progress lines of its standard error drive the progress callback; a
callback returning False ends the program. Same result as the module
(the same run, tools/unwrap_run.h), without face_weights; `threads` is
ignored (the program uses every core: the result is the same)."""
import json
import os
import re
import subprocess
import tempfile

import numpy as np

from . import options as option_table


class UnwrapError(RuntimeError):
    def __init__(self, message, name):
        super().__init__(message)
        self.name = name


class Cancelled(UnwrapError):
    def __init__(self):
        super().__init__("canceled by the progress callback", "ERROR_CANCELED")


class Result:
    """The module's Result, without face_charts."""

    def __init__(self, uv, faces_uv, seams, stats, warnings):
        self.uv, self.faces_uv, self.seams, self.stats, self.warnings = uv, faces_uv, seams, stats, warnings
        self.face_charts = None


def _selection(path, pairs):
    with open(path, "w") as f:
        f.write("\n\n" + " ".join("%d %d" % (a, b) for a, b in np.asarray(pairs, dtype=np.int64).reshape(-1, 2)) + "\n")


def _arguments(hide_seams=None, **options):
    """uv_unwrap's flags for unwrap()'s keywords (the option table's, and hide_seams)."""
    args = option_table.cli_arguments(options)
    if hide_seams:
        args.append("--hide-seams=%r" % float(hide_seams))
    return args


def unwrap(program, V, F, *, seams=None, forbidden=None, progress=None, threads=None, **options):
    V = np.asarray(V, dtype=np.float64)
    F = np.asarray(F, dtype=np.int64)
    with tempfile.TemporaryDirectory(prefix="uv_unwrap_seams") as tmp:
        mesh, obj = os.path.join(tmp, "mesh.off"), os.path.join(tmp, "mesh_uv.obj")
        stats, found = os.path.join(tmp, "stats.json"), os.path.join(tmp, "seams.txt")
        with open(mesh, "w") as f:
            f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
            np.savetxt(f, V, fmt="%.17g")
            np.savetxt(f, np.hstack([np.full((len(F), 1), 3), F]), fmt="%d")
        command = [program, mesh, "-o", obj, "--stats", stats, "--save-seams", found] + _arguments(**options)
        if seams is not None and len(seams):
            _selection(os.path.join(tmp, "keep.txt"), seams)
            command += ["--seams", os.path.join(tmp, "keep.txt")]
        if forbidden is not None and len(forbidden):
            _selection(os.path.join(tmp, "forbid.txt"), forbidden)
            command += ["--forbid", os.path.join(tmp, "forbid.txt")]
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        warnings, errors = [], []
        for line in process.stderr:
            phase = re.match(r"^\s+(\w+):", line)
            if phase and progress is not None and progress(phase.group(1)) is False:
                process.kill()
                process.wait()
                raise Cancelled()
            if line.startswith("uv_unwrap: warning: "):
                warnings.append(line[len("uv_unwrap: warning: "):].strip())
            elif line.startswith("uv_unwrap: error: "):
                errors.append(line[len("uv_unwrap: error: "):].strip())
        process.wait()
        report = json.load(open(stats)) if os.path.exists(stats) else {}
        if process.returncode != 0:
            raise UnwrapError("; ".join(errors) or "uv_unwrap failed", report.get("status") or "ERROR_INTERNAL")
        if any("repaired" in w for w in warnings):
            raise UnwrapError("the mesh needed a repair, which renumbers it: the uv_unwrap program cannot give "
                              "the result in Blender's numbering (the module can)", "ERROR_NON_MANIFOLD")
        uv, corners = [], []
        with open(obj) as f:
            for line in f:
                if line.startswith("vt "):
                    uv.append(line.split()[1:3])
                elif line.startswith("f "):
                    corners.append([tuple(int(x) - 1 for x in c.split("/")[:2]) for c in line.split()[1:]])
        faces_uv = np.empty((len(F), 3), dtype=np.int64)
        for j, face in enumerate(corners):
            vt = dict(face)
            faces_uv[j] = [vt[int(v)] for v in F[j]]
        with open(found) as f:
            lines = f.read().split("\n")
        pairs = np.array(lines[2].split(), dtype=np.int64).reshape(-1, 2) if len(lines) > 2 else np.empty((0, 2))
        pairs = np.unique(np.sort(pairs, axis=1), axis=0).astype(np.int64)
        return Result(np.array(uv, dtype=np.float64).reshape(-1, 2), faces_uv, pairs, report, warnings)
