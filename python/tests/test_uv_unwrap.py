"""The uv_unwrap module: its results against the C++ API and uv_unwrap, the
properties of an atlas, its errors, cancellation, threads and the GIL."""
import json
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import uv_unwrap
from conftest import corner_uvs, data_mesh, edge_faces, read_off, signed_areas, spherical_cap, write_off


def reference(tmp_path, V, F):
    """The C++ API's result on (V, F) (test_python_reference)."""
    program = os.environ.get("UV_UNWRAP_REFERENCE")
    if not program:
        pytest.skip("UV_UNWRAP_REFERENCE (the test_python_reference program) is not set")
    mesh, out = tmp_path / "mesh.off", tmp_path / "reference.txt"
    write_off(mesh, V, F)
    subprocess.run([program, str(mesh), str(out)], check=True)
    ref = {"seams": [], "corners": {}}
    for line in out.read_text().splitlines():
        words = line.split()
        if words[0] == "seam":
            ref["seams"].append((int(words[1]), int(words[2])))
        elif words[0] == "corner":
            ref["corners"][(int(words[1]), int(words[2]))] = (float(words[3]), float(words[4]))
        else:
            ref[words[0]] = float(words[1])
    return ref


def check_atlas(V, F, r):
    """What every result must be: a valid atlas in the input's numbering."""
    m = len(F)
    assert r.uv.ndim == 2 and r.uv.shape[1] == 2 and r.uv.dtype == np.float64
    assert r.faces_uv.shape == (m, 3) and r.face_charts.shape == (m,)
    assert np.all(np.isfinite(r.uv))
    assert r.uv.min() >= 0.0 and r.uv.max() <= 1.0
    assert np.all(signed_areas(r) > 0), "flipped faces"
    assert r.stats["flipped_faces"] == 0 and r.stats["border_crossings"] == 0
    assert r.stats["uv_in_unit_square"] is True
    assert len(np.unique(r.face_charts)) == r.stats["charts"]
    # seams: edges of F; corners split across them, shared across the other interior edges
    corners = corner_uvs(r)
    seams = {tuple(s) for s in r.seams.tolist()}
    edges = edge_faces(F)
    assert seams <= set(edges)
    assert len(seams) == r.stats["seam_edges"]
    for key, sides in edges.items():
        if len(sides) != 2:
            continue
        (f, a, b), (g, c, d) = sides
        same = np.array_equal(corners[f, a], corners[g, c]) and np.array_equal(corners[f, b], corners[g, d])
        assert same != (key in seams), f"edge {key}: seam {key in seams}, UVs shared {same}"
        assert (r.face_charts[f] == r.face_charts[g]) == (key not in seams) or key in seams


def test_same_result_as_the_cpp_api(tmp_path, cap):
    V, F = cap
    r = uv_unwrap.unwrap(V, F)
    ref = reference(tmp_path, V, F)
    assert r.stats["distortion"] == ref["distortion"]
    assert r.stats["seam_length"] == ref["seam_length"]
    assert r.stats["charts"] == ref["charts"]
    assert [tuple(s) for s in r.seams.tolist()] == ref["seams"]
    corners = corner_uvs(r)
    for j, t in enumerate(F):
        for k in range(3):
            assert tuple(corners[j, k]) == ref["corners"][(j, int(t[k]))]
    check_atlas(V, F, r)


def test_cgal_data_mesh_as_uv_unwrap(tmp_path):
    V, F = data_mesh("pig.off")
    r = uv_unwrap.unwrap(V, F)
    check_atlas(V, F, r)
    program = os.environ.get("UV_UNWRAP")
    if program:  # the command line on the same file: the same statistics
        stats = tmp_path / "stats.json"
        mesh = os.path.join(os.environ["CGAL_DATA_DIR"], "meshes", "pig.off")
        subprocess.run([program, mesh, "-q", "-o", str(tmp_path / "pig.obj"), "--stats", str(stats)], check=True)
        cli = json.loads(stats.read_text())
        assert list(cli) == list(r.stats)
        for key in ("distortion", "seam_length", "charts", "seam_edges", "uv_coverage", "border_crossings"):
            assert r.stats[key] == cli[key], key


def test_options_reach_the_method(cap):
    V, F = cap
    base = uv_unwrap.unwrap(V, F)
    cheap = uv_unwrap.unwrap(V, F, seam_cost=0.25)
    assert cheap.stats["seam_length"] > base.stats["seam_length"]
    assert cheap.stats["distortion"] < base.stats["distortion"]
    bounded = uv_unwrap.unwrap(V, F, max_distortion=4.2)
    assert bounded.stats["distortion"] <= 4.2 and bounded.stats["distortion_bound_met"]
    padded = uv_unwrap.unwrap(V, F, padding=8, texture_size=256)
    check_atlas(V, F, padded)
    assert padded.uv.min() >= 8 / 256 * 0.999


@pytest.mark.parametrize("options, arguments", [
    ({"box": (2, 1), "padding": 8, "texture_size": 256}, ["--box", "2:1", "--padding", "8", "--texture-size", "256"]),
    ({"box": False, "seam_cost": 2.0}, ["--no-box", "--lambda", "2"]),
    ({"hide_seams": 6, "allow_overlaps": True}, ["--hide-seams=6", "--allow-overlaps"]),
    ({"inner_solver": "proxy-quasi-newton", "max_newton_iterations": 200, "box_stiffness": 12},
     ["--inner-solver", "proxy-quasi-newton", "--max-newton-iterations", "200", "--box-stiffness", "12"]),
])
def test_options_as_uv_unwrap(tmp_path, cap, options, arguments):
    program = os.environ.get("UV_UNWRAP")
    if not program:
        pytest.skip("UV_UNWRAP (the uv_unwrap program) is not set")
    V, F = cap
    write_off(tmp_path / "cap.off", V, F)
    stats = tmp_path / "stats.json"
    subprocess.run([program, str(tmp_path / "cap.off"), "-q", "-o", str(tmp_path / "cap.obj"), "--stats", str(stats)]
                   + arguments, check=True)
    cli = json.loads(stats.read_text())
    r = uv_unwrap.unwrap(V, F, **options)
    for key in ("distortion", "seam_length", "charts", "uv_coverage", "seam_visibility"):
        assert r.stats[key] == cli[key], key


def test_inner_solver_reaches_the_library(cap):
    V, F = cap
    default = uv_unwrap.unwrap(V, F)
    newton = uv_unwrap.unwrap(V, F, inner_solver="newton")
    proxy = uv_unwrap.unwrap(V, F, inner_solver="proxy-quasi-newton")
    for key in ("factorizations", "newton_iterations", "distortion", "seam_length"):
        assert newton.stats[key] == default.stats[key], key
    # the proxy solver takes L-BFGS steps between its factorizations: more iterations, other factorizations
    assert proxy.stats["newton_iterations"] > newton.stats["newton_iterations"]
    assert proxy.stats["factorizations"] != newton.stats["factorizations"]
    check_atlas(V, F, proxy)


def test_kept_and_forbidden_seams(cap):
    V, F = cap
    free = uv_unwrap.unwrap(V, F)
    # never cut where the unconstrained run cuts; keep a meridian it mostly leaves
    keep = np.array([(0, 1)] + [(1 + k * 36, 1 + (k + 1) * 36) for k in range(11)])
    kept = {tuple(sorted(e)) for e in keep.tolist()}
    assert not kept <= {tuple(e) for e in free.seams.tolist()}
    forbidden = np.array([e for e in free.seams.tolist() if tuple(e) not in kept])
    with pytest.raises(ValueError, match=r"is both in seams \(to cut\) and in forbidden"):
        uv_unwrap.unwrap(V, F, seams=keep, forbidden=free.seams)
    r = uv_unwrap.unwrap(V, F, seams=keep, forbidden=forbidden)
    check_atlas(V, F, r)
    seams = {tuple(s) for s in r.seams.tolist()}
    assert kept <= seams
    assert not ({tuple(e) for e in forbidden.tolist()} & seams)


def test_face_weights_move_seams(cap):
    V, F = cap
    south = set(np.flatnonzero(V[:, 2] < 0.3).tolist())
    in_south = lambda r: sum(1 for a, b in r.seams.tolist() if a in south and b in south)
    free = uv_unwrap.unwrap(V, F)
    assert in_south(free) < len(free.seams)  # unweighted, some seams run in the north
    north = V[F].mean(axis=1)[:, 2] > 0.3
    r = uv_unwrap.unwrap(V, F, face_weights=np.where(north, 10.0, 0.1))
    check_atlas(V, F, r)
    assert in_south(r) == len(r.seams) > 0


@pytest.mark.parametrize("change, error, message", [
    (lambda V, F: (V[:, :2], F), ValueError, r"V must have shape \(n, 3\), not \(\d+, 2\)"),
    (lambda V, F: (V.astype(str), F), TypeError, "V must hold numbers"),
    (lambda V, F: (V, F.astype(np.float64)), TypeError, "F must hold integer vertex indices, not float64"),
    (lambda V, F: (V, F.ravel()), ValueError, r"F must have shape \(n, 3\)"),
    (lambda V, F: (np.where(np.arange(len(V))[:, None] == 7, np.nan, V), F), ValueError,
     r"V\[7\] = \(nan, nan, nan\) has a non-finite coordinate"),
    (lambda V, F: (V, np.where(F == F.max(), len(V), F)), IndexError, "is not a vertex index"),
    (lambda V, F: (V, np.where(F == 0, -1, F)), IndexError, r"= -1 is not a vertex index"),
    (lambda V, F: (V, F[:0]), ValueError, "F has no faces"),
])
def test_bad_arrays(cap, change, error, message):
    V, F = change(*cap)
    with pytest.raises(error, match=message):
        uv_unwrap.unwrap(V, F)


@pytest.mark.parametrize("options, error, message", [
    ({"seam_cost": 0}, ValueError, "seam_cost must be a positive number"),
    ({"max_distortion": 3.5}, ValueError, "max_distortion must be a number >= 4"),
    ({"padding": -1}, ValueError, "padding must be a number >= 0"),
    ({"texture_size": 0}, ValueError, "texture_size must be at least 1"),
    ({"box": (1, 0)}, ValueError, "aspect ratio"),
    ({"inner_solver": "bfgs"}, ValueError, "inner_solver must be 'newton' or 'proxy-quasi-newton', not 'bfgs'"),
    ({"epsilon_start": -1}, ValueError, "epsilon_start must be a positive number"),
    ({"max_newton_iterations": 2.5}, ValueError, "max_newton_iterations must be at least 1"),
    ({"face_weights": np.ones(3)}, ValueError, "one value per face"),
    ({"seams": np.array([[0, 10**6]])}, IndexError, r"seams\[0, 1\] = 1000000 is not a vertex index"),
    ({"progress": 3}, TypeError, "progress must be callable"),
    ({"threads": 0}, ValueError, "threads must be at least 1"),
])
def test_bad_options(cap, options, error, message):
    with pytest.raises(error, match=message):
        uv_unwrap.unwrap(*cap, **options)


def test_method_failure_has_the_library_error_name(cap):
    V, F = cap
    with pytest.raises(uv_unwrap.UnwrapError, match="not joined by an edge") as info:
        uv_unwrap.unwrap(V, F, seams=np.array([[0, len(V) - 1]]))
    assert info.value.name == "ERROR_WRONG_PARAMETER"
    # a closed mesh whose every edge is forbidden cannot be opened
    closed_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    closed_F = np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
    every_edge = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    with pytest.raises(uv_unwrap.UnwrapError) as info:
        uv_unwrap.unwrap(closed_V, closed_F, forbidden=every_edge)
    assert info.value.name == "ERROR_FORBIDDEN_EDGES_BLOCK_CUT"


def test_non_manifold_input_is_repaired_with_a_warning():
    # two caps touching at their poles (a non-manifold vertex), the second
    # with its own copy of the shared pole position, plus a duplicated face
    V1, F1 = spherical_cap(rings=6, segments=16)
    V2 = V1 * np.array([1, 1, -1]) + np.array([0, 0, 2])
    V = np.vstack([V1, V2])
    F = np.vstack([F1, F1[:, ::-1] + len(V1), F1[:1]])
    with pytest.warns(UserWarning, match="repaired"):
        r = uv_unwrap.unwrap(V, F)
    assert any("repaired" in w for w in r.stats["warnings"])
    assert r.faces_uv.shape == (len(F), 3)
    kept = r.faces_uv[:, 0] >= 0
    assert kept.sum() >= len(F) - 1  # the duplicate may be dropped
    c = corner_uvs(r)[kept]
    e1, e2 = c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]
    assert np.all(np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]) > 0)
    assert r.uv.min() >= 0 and r.uv.max() <= 1 and r.stats["flipped_faces"] == 0


def test_progress_reports_and_cancel(cap):
    phases = []
    r = uv_unwrap.unwrap(*cap, progress=lambda phase, **info: phases.append((phase, info)))
    assert [p for p, _ in phases][0] == "initialize" and "final" in [p for p, _ in phases]
    assert set(phases[0][1]) == {"pass_", "alternation", "alternations", "distortion"}

    calls = []

    def stop_at_third(phase, **info):
        calls.append(phase)
        return len(calls) < 3

    with pytest.raises(uv_unwrap.Cancelled) as info:
        uv_unwrap.unwrap(*cap, progress=stop_at_third)
    assert info.value.name == "ERROR_CANCELED" and len(calls) == 3
    assert isinstance(info.value, uv_unwrap.UnwrapError)

    def fail(phase, **info):
        raise ZeroDivisionError("from progress")

    with pytest.raises(ZeroDivisionError, match="from progress"):
        uv_unwrap.unwrap(*cap, progress=fail)


def test_progress_cancels_the_visibility_phase(cap):
    phases = []
    uv_unwrap.unwrap(*cap, hide_seams=6, progress=lambda phase, **info: phases.append((phase, info)))
    visibility = [info for p, info in phases if p == "visibility"]
    assert phases[0][0] == "visibility" and phases[len(visibility)][0] == "initialize"
    assert visibility[0]["alternation"] == 0 and visibility[-1]["alternation"] == visibility[-1]["alternations"]

    calls = []

    def stop_in_visibility(phase, **info):
        calls.append(phase)
        return phase != "visibility"

    with pytest.raises(uv_unwrap.Cancelled) as info:
        uv_unwrap.unwrap(*cap, hide_seams=6, progress=stop_in_visibility)
    assert info.value.name == "ERROR_CANCELED" and calls == ["visibility"]


def test_ctrl_c_cancels():
    V, F = spherical_cap(rings=40, segments=120)  # a few seconds of work
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        uv_unwrap.unwrap(V, F)
    timer.join()
    assert time.monotonic() - start < 10


def test_other_python_threads_run_while_it_unwraps():
    V, F = spherical_cap(rings=20, segments=60)
    ticks, done = [0], threading.Event()

    def count():
        while not done.is_set():
            ticks[0] += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    uv_unwrap.unwrap(V, F)
    seconds = time.monotonic() - start
    done.set()
    counter.join()
    # with the GIL held throughout, the counter would stand still; it sleeps
    # 1 ms a tick, but on a busy machine its wake-ups can come much later
    assert ticks[0] > max(20, 0.02 * seconds / 0.001), (ticks[0], seconds)


def test_same_result_for_one_and_two_threads(cap):
    one = uv_unwrap.unwrap(*cap, threads=1)
    two = uv_unwrap.unwrap(*cap, threads=2)
    assert np.array_equal(one.uv, two.uv)
    assert np.array_equal(one.faces_uv, two.faces_uv)
    assert np.array_equal(one.seams, two.seams)
    assert one.stats["distortion"] == two.stats["distortion"]


def test_hard_edges_in_the_statistics():
    V = np.array([[x, 2.0 * y, 3.0 * z] for z in (0, 1) for y in (0, 1) for x in (0, 1)])
    F = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                  [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]])
    assert uv_unwrap.unwrap(V, F, hard_edge_angle=30.0).stats["hard_edges"] == 12  # the box's edges
    assert uv_unwrap.unwrap(V, F).stats["hard_edges"] == 0
