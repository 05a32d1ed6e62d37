"""python3 -m uv_unwrap.batch on a local cluster of 2 workers: a folder of 20 meshes with broken
ones gives 18 valid outputs and 20 records; a worker killed in the middle of a mesh loses
nothing; a mesh over --timeout is recorded as such and the batch goes on; a rerun skips what is
done and redoes only what is missing. The outputs are checked on their own (the OBJ parsed here)."""
import json
import math
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from conftest import spherical_cap, write_off

pytest.importorskip("distributed")

# the keys of uv_unwrap --stats, and those the batch adds
STATS_KEYS = {"input", "output", "status", "error", "warnings", "vertices", "faces", "charts", "seam_edges",
              "seam_length", "distortion", "flipped_faces", "border_crossings", "uv_in_unit_square",
              "newton_iterations"}
BATCH_KEYS = {"worker", "attempts", "options_hash", "input_signature"}
LATIN1 = os.fsdecode(b"caf\xe9")  # a file name that is not UTF-8


def program():
    path = os.environ.get("UV_UNWRAP")
    if not path:
        pytest.skip("UV_UNWRAP (the uv_unwrap program) is not set")
    return path


def run_batch(inputs, out, *options, wait=True):
    command = [sys.executable, "-m", "uv_unwrap.batch", *map(str, inputs), "--output-dir", str(out),
               "--workers", "2", "--uv-unwrap", program(), *options]
    if not wait:
        return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    return subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=240)


def small_caps(folder, count):
    """`count` spherical caps of 100-400 faces, different shapes; their names in order."""
    folder.mkdir(parents=True, exist_ok=True)
    names = []
    for i in range(count):
        V, F = spherical_cap(rings=5 + i % 4, segments=12 + 2 * (i % 5), reach=(0.45 + 0.025 * i) * math.pi)
        names.append("cap_%02d.off" % i)
        write_off(folder / names[-1], V, F)
    return names


def read_obj(path):
    """(V, UV, F, FT) of an OBJ with v, vt and f v/vt lines."""
    V, T, F, FT = [], [], [], []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                V.append([float(w) for w in words[1:4]])
            elif words[0] == "vt":
                T.append([float(w) for w in words[1:3]])
            elif words[0] == "f":
                corners = [w.split("/") for w in words[1:]]
                F.append([int(c[0]) - 1 for c in corners])
                FT.append([int(c[1]) - 1 for c in corners])
    return np.array(V), np.array(T), np.array(F), np.array(FT)


def border_crossings(T, FT):
    """Proper crossings of the UV border segments (UV edges used by one face)."""
    count = {}
    for t in FT:
        for k in range(3):
            e = tuple(sorted((t[k], t[(k + 1) % 3])))
            count[e] = count.get(e, 0) + 1
    S = np.array([e for e, c in count.items() if c == 1])
    p, q = T[S[:, 0]], T[S[:, 1]]

    def orient(a, b, c):
        return (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])
    P, Q, R, U = p[:, None], q[:, None], p[None, :], q[None, :]
    crossing = (orient(R, U, P) * orient(R, U, Q) < 0) & (orient(P, Q, R) * orient(P, Q, U) < 0)
    shared = (S[:, None, 0] == S[None, :, 0]) | (S[:, None, 0] == S[None, :, 1]) | \
             (S[:, None, 1] == S[None, :, 0]) | (S[:, None, 1] == S[None, :, 1])
    return int(np.triu(crossing & ~shared, 1).sum())


def check_output(path, faces):
    """A valid atlas of the input's `faces` faces: UVs finite in [0,1], no flipped face, no crossing."""
    V, T, F, FT = read_obj(path)
    assert len(F) == faces and FT.shape == F.shape, path
    assert np.all(np.isfinite(T)) and T.min() >= 0.0 and T.max() <= 1.0, path
    a, b, c = T[FT[:, 0]], T[FT[:, 1]], T[FT[:, 2]]
    area = 0.5 * ((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    assert np.all(area > 0), "%s: %d flipped faces" % (path, int((area <= 0).sum()))
    assert border_crossings(T, FT) == 0, path


def read_records(out):
    with open(out / "batch.jsonl") as f:
        return [json.loads(line) for line in f]


def by_name(records):
    return {os.path.basename(r["input"]): r for r in records}


@pytest.fixture(scope="module")
def library(tmp_path_factory):
    """20 inputs: 17 caps, one with a Latin-1 name, random bytes (.obj) and an empty file (.off)."""
    folder = tmp_path_factory.mktemp("library")
    names = small_caps(folder, 17)
    V, F = spherical_cap(rings=6, segments=14)
    write_off(os.path.join(os.fsencode(folder), os.fsencode(LATIN1 + ".off")), V, F)
    (folder / "random_bytes.obj").write_bytes(np.random.default_rng(7).integers(0, 256, 4000, np.uint8).tobytes())
    (folder / "empty.off").write_bytes(b"")
    return folder, names + [LATIN1 + ".off"]


def test_library_rerun_and_deleted_outputs(library, tmp_path):
    folder, good = library
    out = tmp_path / "out"
    first = run_batch([folder], out)
    assert first.returncode == 1, first.stderr  # some inputs failed
    records = by_name(read_records(out))
    assert len(read_records(out)) == 20 and len(records) == 20
    assert records["random_bytes.obj"]["status"] == "ERROR_CANNOT_READ" and records["random_bytes.obj"]["error"]
    assert records["empty.off"]["status"] == "ERROR_EMPTY_MESH" and records["empty.off"]["error"]
    for name in good:
        r = records[name]
        assert STATS_KEYS | BATCH_KEYS <= set(r), name
        assert r["status"] == "ok" and r["attempts"] == 1 and r["flipped_faces"] == 0 and r["border_crossings"] == 0
        assert os.path.basename(r["output"]) == name[:-4] + "_uv.obj"
        check_output(r["output"], r["faces"])
    outputs = sorted(p.name for p in out.iterdir() if p.name != "batch.jsonl")
    assert len(outputs) == 18, outputs  # and no temporary file left
    assert not [p for p in tmp_path.iterdir() if p.name != "out"]

    # the same options again: nothing to run, the records as they were
    modified = {p: p.stat().st_mtime_ns for p in out.iterdir()}
    again = run_batch([folder], out)
    assert again.returncode == 1 and "0 run, 20 skipped" in again.stderr, again.stderr
    assert by_name(read_records(out)) == records
    assert all(p.stat().st_mtime_ns == t for p, t in modified.items() if p.name != "batch.jsonl")

    # 3 outputs deleted: those 3 only are run again
    deleted = good[2:5]
    for name in deleted:
        os.remove(records[name]["output"])
    third = run_batch([folder], out)
    assert third.returncode == 1 and "3 run, 17 skipped" in third.stderr, third.stderr
    redone = by_name(read_records(out))
    assert len(read_records(out)) == 20
    for name in good:
        if name in deleted:
            assert redone[name]["status"] == "ok" and redone[name]["batch_seconds"] != records[name]["batch_seconds"]
            check_output(redone[name]["output"], redone[name]["faces"])
        else:
            assert redone[name] == records[name]

    # what a rerun skips: the same options (their hash) on the same file, and the output there
    from uv_unwrap import batch
    r = redone[good[0]]
    assert batch.is_done(r, r["output"], r["options_hash"], r["input_signature"])
    other = batch.options_hash(batch.parse_arguments([str(folder), "--output-dir", str(out),
                                                      "--seam-cost", "2"]).flags, None)
    assert other != r["options_hash"] and not batch.is_done(r, r["output"], other, r["input_signature"])
    assert not batch.is_done(r, r["output"], r["options_hash"], "1:2")  # the input changed
    assert batch.is_done(redone["empty.off"], None, r["options_hash"], redone["empty.off"]["input_signature"])
    assert not batch.is_done(dict(redone["empty.off"], status="ERROR_TIMEOUT"), None, r["options_hash"],
                             redone["empty.off"]["input_signature"])


def uv_unwrap_children(marker):
    """{pid: (parent pid, command line)} of the running uv_unwrap processes whose command line holds `marker`."""
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                stat = f.read()
            with open("/proc/%s/cmdline" % entry, "rb") as f:
                command = f.read().split(b"\0")
        except OSError:
            continue
        fields = stat[stat.rindex(")") + 2:].split()
        if fields[0] != "Z" and os.path.basename(command[0]) == b"uv_unwrap" and marker in b" ".join(command):
            found[int(entry)] = (int(fields[1]), command)
    return found


def alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def test_worker_killed_in_the_middle_of_a_mesh(tmp_path):
    folder = tmp_path / "in"
    names = small_caps(folder, 8)
    out = tmp_path / "out"
    batch = run_batch([folder], out, wait=False)
    killed = None
    deadline = time.monotonic() + 120
    while killed is None and batch.poll() is None and time.monotonic() < deadline:
        for child, (worker, command) in uv_unwrap_children(os.fsencode(folder)).items():
            os.kill(worker, signal.SIGKILL)  # the worker's process, in the middle of this mesh
            killed = (child, os.path.basename(command[1]).decode())
            break
        time.sleep(0.005)
    stdout, stderr = batch.communicate(timeout=240)
    assert killed is not None, "no uv_unwrap seen running"
    assert batch.returncode == 0, stderr.decode(errors="replace")
    # its uv_unwrap ended with it (not left running), its task ran again elsewhere
    for _ in range(100):
        if not alive(killed[0]):
            break
        time.sleep(0.05)
    assert not alive(killed[0])
    records = by_name(read_records(out))
    assert sorted(records) == names and len(read_records(out)) == len(names)
    assert records[killed[1]]["attempts"] == 2
    for name, r in records.items():
        assert STATS_KEYS | BATCH_KEYS <= set(r) and r["status"] == "ok", r
        check_output(r["output"], r["faces"])
    assert sorted(p.name for p in out.iterdir()) == sorted(["batch.jsonl"] + [n[:-4] + "_uv.obj" for n in names])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in", "out"]  # no temporary folder left


def test_timeout_is_recorded_and_the_batch_goes_on(tmp_path):
    folder = tmp_path / "in"
    names = small_caps(folder, 3)
    V, F = spherical_cap(rings=100, segments=200)  # 40k faces: several seconds of CPU
    write_off(folder / "large.off", V, F)
    out = tmp_path / "out"
    result = run_batch([folder], out, "--timeout", "3")
    assert result.returncode == 1, result.stderr
    records = by_name(read_records(out))
    assert len(records) == 4
    assert records["large.off"]["status"] == "ERROR_TIMEOUT" and "timeout" in records["large.off"]["error"]
    assert records["large.off"]["output"] is None and not (out / "large_uv.obj").exists()
    for name in names:
        assert records[name]["status"] == "ok"
        check_output(records[name]["output"], records[name]["faces"])


def test_usage_errors_exit_2(tmp_path):
    missing = run_batch([tmp_path / "nothing"], tmp_path / "out")
    assert missing.returncode == 2 and "no such file" in missing.stderr
    small_caps(tmp_path / "in", 1)
    bad = run_batch([tmp_path / "in"], tmp_path / "out", "--seam-cost", "-1")
    assert bad.returncode == 2 and "--seam-cost" in bad.stderr


def test_inputs_of_one_name_get_outputs_of_their_own(tmp_path):
    """pig.off beside pig.stl, one name in two given folders, a file given twice: no output
    overwrites another (checked on the names the batch gives, without a cluster)."""
    from uv_unwrap import batch
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        for name in ("pig.off", "pig.stl", "cow.obj"):
            (tmp_path / folder / name).write_text("")
    given = [str(tmp_path / "a"), str(tmp_path / "b" / "pig.off"), str(tmp_path / "b" / "pig.stl"),
             str(tmp_path / "a" / "cow.obj")]
    pairs = batch.collect_inputs(given, str(tmp_path / "out"), None)
    inputs = [src for src, _ in pairs]
    outputs = [out for _, out in pairs]
    assert len(inputs) == 5 and len(set(inputs)) == 5  # cow.obj given twice is one input
    assert len(set(outputs)) == 5
    assert os.path.basename(dict(pairs)[str(tmp_path / "a" / "cow.obj")]) == "cow_uv.obj"
    assert sorted(os.path.basename(o) for o in outputs if "pig" in o) == \
        ["pig_off_1_uv.obj", "pig_off_2_uv.obj", "pig_stl_1_uv.obj", "pig_stl_2_uv.obj"]
