"""The task of python3 -m uv_unwrap.batch, run on a Dask worker: uv_unwrap on one mesh in a child
process (so that a crash, a hang or a memory peak ends the child only), its output published
atomically, its record returned (uv_unwrap's own --jsonl statistics)."""
import contextlib
import json
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time

# the prefix of the temporary folders of the outputs
TEMPORARY = ".uvbatch-"
# one BLAS / OpenMP thread per uv_unwrap: the workers are the parallelism
ONE_THREAD = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
              "GOTO_NUM_THREADS": "1", "BLIS_NUM_THREADS": "1"}


class UsageError(Exception):
    pass


def find_program(given):
    """The uv_unwrap program: --uv-unwrap, UV_UNWRAP, bin/ of the build holding this package, the PATH."""
    build_bin = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "bin", "uv_unwrap")
    for candidate in (given, os.environ.get("UV_UNWRAP"), build_bin, shutil.which("uv_unwrap")):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
        if candidate is given and given:
            raise UsageError("--uv-unwrap %s is not an executable file" % given)
    raise UsageError("no uv_unwrap program found (give --uv-unwrap PROGRAM or UV_UNWRAP)")


_libc = None


def _child_setup(memory_limit):
    """In the child before exec: it dies with its worker (PR_SET_PDEATHSIG), its data under --memory-limit."""
    def setup():
        if _libc is not None:
            _libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
        if memory_limit:
            import resource
            # RLIMIT_DATA: the heap and private mappings as they are used, not the address space reserved
            resource.setrlimit(resource.RLIMIT_DATA, (memory_limit, memory_limit))
    return setup


def _temporary_folder(output):
    """A new folder for the output's files beside the output's folder (at its depth, so that relative
    URIs written into a glTF stay right; on its file system, so that os.replace is atomic)."""
    folder = os.path.dirname(output)
    os.makedirs(folder, exist_ok=True)
    parent = os.path.dirname(folder)
    with contextlib.suppress(OSError):
        if os.stat(parent).st_dev == os.stat(folder).st_dev:
            return tempfile.mkdtemp(prefix="." + os.path.basename(folder) + TEMPORARY, dir=parent)
    return tempfile.mkdtemp(prefix=TEMPORARY, dir=folder)


def _publish(temporary, output):
    """Moves the files uv_unwrap wrote into the output's folder, each atomically, the output itself last."""
    name = os.path.basename(output)
    written = sorted(os.listdir(temporary))
    if name not in written:
        raise RuntimeError("uv_unwrap reported success but wrote no %s" % name)
    for file in [w for w in written if w != name] + [name]:
        os.replace(os.path.join(temporary, file), os.path.join(os.path.dirname(output), file))


def _worker_name():
    with contextlib.suppress(Exception):
        from distributed import get_worker
        return get_worker().address
    return socket.gethostname()


def _outcome(returncode, stdout, stderr, job):
    """The record of a finished uv_unwrap: its --jsonl line, or what its end tells."""
    lines = [line for line in stdout.decode("utf-8", "replace").splitlines() if line.strip()]
    record = None
    with contextlib.suppress(ValueError, IndexError):
        record = json.loads(lines[-1])
    if returncode < 0:
        try:
            name = signal.Signals(-returncode).name
        except ValueError:
            name = "signal %d" % -returncode
        memory = " (under --memory-limit %d bytes: out of memory?)" % job["memory_limit"] if job["memory_limit"] else ""
        return {"status": "ERROR_KILLED", "error": "uv_unwrap was killed by %s%s" % (name, memory)}
    if not isinstance(record, dict) or "status" not in record:
        said = stderr.decode("utf-8", "replace").strip().splitlines()
        return {"status": "ERROR_INTERNAL",
                "error": "uv_unwrap ended with status %d and no statistics%s"
                         % (returncode, ": " + said[-1] if said else "")}
    return record


def _run(program, job, output):
    """uv_unwrap on the input, its output written into a temporary folder, then published."""
    temporary = _temporary_folder(output)
    try:
        target = os.path.join(temporary, os.path.basename(output))
        child = subprocess.Popen([program, job["input"], "-o", target, "--jsonl", "-"] + job["flags"],
                                 stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 env=dict(os.environ, **ONE_THREAD), start_new_session=True,
                                 preexec_fn=_child_setup(job["memory_limit"]))
        try:
            stdout, stderr = child.communicate(timeout=job["timeout"])
            record = _outcome(child.returncode, stdout, stderr, job)
        except subprocess.TimeoutExpired:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(child.pid, signal.SIGKILL)
            child.communicate()
            record = {"status": "ERROR_TIMEOUT", "error": "uv_unwrap took more than --timeout %g s" % job["timeout"]}
        if record["status"] == "ok":
            _publish(temporary, output)
        return record
    finally:
        shutil.rmtree(temporary, ignore_errors=True)


def unwrap_task(job):
    """Runs on a worker: uv_unwrap on job["input"] in a child process; returns the input's record.
    The input's failures are in the record; an exception here is the worker's own trouble."""
    global _libc
    if _libc is None:
        import ctypes
        with contextlib.suppress(OSError):
            _libc = ctypes.CDLL(None, use_errno=True)
    start = time.monotonic()
    program = job["program"]
    if not (os.path.isfile(program) and os.access(program, os.X_OK)):
        program = find_program(None)  # another machine: its own uv_unwrap
    output = job["output"]
    try:
        record = _run(program, job, output)
    except OSError as e:  # the output's folder: not writable, full, ...
        record = {"status": "ERROR_CANNOT_WRITE", "error": "%s: %s" % (output, e)}
    record.update(input=job["input"], output=output if record["status"] == "ok" else None,
                  worker=_worker_name(), batch_seconds=round(time.monotonic() - start, 6))
    return record


