"""Unwraps a library of mesh files on a Dask cluster, losing nothing.

    python3 -m uv_unwrap.batch INPUT... --output-dir DIR [--workers N | --scheduler ADDRESS]
                               [--timeout S] [--memory-limit SIZE] [--retries N] [uv_unwrap's options]

INPUT: mesh files or folders (walked, subfolders too, for the files uv_unwrap
reads; the outputs keep the subfolders under DIR). One task per mesh: the
worker runs the uv_unwrap program on it in a child process, so that a crash,
a hang (--timeout) or a memory peak (--memory-limit) ends that child only,
and the statistics are uv_unwrap's own (--jsonl). A worker that dies has its
task run again on another (--retries); a mesh that still fails is recorded
with the reason. Outputs are written atomically (a temporary folder beside
the output's, then os.replace). DIR/batch.jsonl holds one line per input:
uv_unwrap's statistics (the keys of uv_unwrap --stats) plus `worker`,
`attempts`, `options_hash` and `input_signature`. Run again with the same
options, the batch skips the inputs recorded as done (output there, same
options, same input file) and redoes the others.
Exit status: 0 every input unwrapped, 1 some failed (all recorded), 2 usage error.
"""
import argparse
import contextlib
import glob
import hashlib
import itertools
import json
import os
import shutil
import signal
import sys

from .batch_task import ONE_THREAD, TEMPORARY, UsageError, find_program, unwrap_task

# the files uv_unwrap reads (tools/uv_unwrap_options.cpp: is_mesh_file())
MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl", ".gltf", ".glb")
# the output format of an input without --format (tools/uv_unwrap.cpp: output_format())
OUTPUT_FORMAT = {".obj": "obj", ".ply": "ply", ".off": "obj", ".stl": "obj", ".gltf": "gltf", ".glb": "glb"}
RECORDS = "batch.jsonl"
# failures that may pass another time: redone by a rerun (the others are the input's own)
TRANSIENT = {"ERROR_TIMEOUT", "ERROR_KILLED", "ERROR_OUT_OF_MEMORY", "ERROR_WORKER_LOST", "ERROR_CANCELED",
             "ERROR_CANNOT_WRITE", "ERROR_INTERNAL"}


# ------------------------------------------------------------------ options

def option_table():
    """The rows of the option table (tools/options/option_table.h), copied beside this file by the build."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "option_table.json")
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        raise UsageError("the option table is missing (%s): use the package as built (build/python)" % e)


def _number(row, integer):
    low, high, open_low = row["min"], row["max"], row["min_open"]

    def parse(text):
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            raise argparse.ArgumentTypeError("%r is not %s" % (text, row["expected"]))
        if value != value or (value <= low if open_low else value < low) or (high is not None and value > high):
            raise argparse.ArgumentTypeError("%r is not %s" % (text, row["expected"]))
        return value
    return parse


def _ratio(text):
    try:
        w, h = text.split(":") if ":" in text else (text, "1")
        if float(w) > 0 and float(h) > 0:
            return text
    except ValueError:
        pass
    raise argparse.ArgumentTypeError("%r is not a ratio W:H or a positive number" % text)


def add_table_options(parser, rows):
    """One option per row of the table, named by its Python keyword (--seam-cost or --seam_cost)."""
    group = parser.add_argument_group("uv_unwrap's options (the option table; the keywords of uv_unwrap.unwrap())")
    for row in rows:
        names = ["--" + row["python"].replace("_", "-")]
        if "_" in row["python"]:
            names.append("--" + row["python"])
        shown = row["default"] if row["kind"] != "choice" or row["default"] is None else row["choices"][row["default"]]
        default = "" if shown is None or row["kind"] in ("flag", "inverted_flag") else " (default %s)" % shown
        kind, common = row["kind"], {"dest": "table_" + row["python"], "help": row["help"] + default}
        if kind in ("flag", "inverted_flag"):
            group.add_argument(*names, action="store_true", **common)
        elif kind == "choice":
            group.add_argument(*names, choices=row["choices"], **common)
        elif kind == "ratio":
            group.add_argument(*names, type=_ratio, metavar="W:H", **common)
        else:
            group.add_argument(*names, type=_number(row, kind == "count"), metavar="N" if kind == "count" else "X",
                               **common)
    group.add_argument("--no-box", action="store_true", help="no bounding box (unwrap()'s box=False)")
    group.add_argument("--hide-seams", type=_number({"min": 0, "max": None, "min_open": False,
                                                     "expected": "a number >= 0"}, False), metavar="S",
                       help="move seams to where the surface is least visible, strength S (uv_unwrap --hide-seams)")
    group.add_argument("--format", choices=["obj", "ply", "gltf", "glb"],
                       help="format of the outputs (default: that of the input; obj for .off and .stl)")


def cli_arguments(args, rows):
    """uv_unwrap's flags for the options given (those not given: the library's defaults)."""
    flags = []
    for row in rows:
        value = getattr(args, "table_" + row["python"])
        if value is None or value is False:
            continue
        if row["kind"] in ("flag", "inverted_flag"):
            flags.append(row["cli"])
        elif row["kind"] == "real":
            flags += [row["cli"], repr(float(value))]
        else:
            flags += [row["cli"], str(value)]
    if args.no_box:
        flags.append("--no-box")
    if args.hide_seams is not None:
        flags.append("--hide-seams=%r" % float(args.hide_seams))
    return flags


def options_hash(flags, output_format):
    """What decides the outputs: uv_unwrap's flags and the format (not --timeout, --workers, ...)."""
    text = json.dumps({"flags": flags, "format": output_format}, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="python3 -m uv_unwrap.batch", description=__doc__.split("\n\n")[0],
        epilog="Exit status: 0 every input unwrapped, 1 some failed (all recorded in DIR/batch.jsonl), 2 usage error.")
    parser.add_argument("inputs", nargs="+", metavar="INPUT", help="mesh files, or folders (walked)")
    parser.add_argument("--output-dir", required=True, metavar="DIR", help="folder of the outputs and of batch.jsonl")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, metavar="N",
                       help="start a local cluster of N workers, one thread each (default: the cores)")
    where.add_argument("--scheduler", metavar="ADDRESS", help="use this Dask scheduler (tcp://host:8786) instead")
    parser.add_argument("--timeout", type=_number({"min": 0, "max": None, "min_open": True,
                                                   "expected": "a positive number"}, False),
                        metavar="S", help="per mesh: seconds before its uv_unwrap is killed (default: none)")
    parser.add_argument("--memory-limit", metavar="SIZE",
                        help="per mesh: the most memory its uv_unwrap may take (4GB, 500MiB, bytes; default: none)")
    parser.add_argument("--retries", type=int, default=1, metavar="N",
                        help="times a task whose worker died is run again on another worker (default 1)")
    parser.add_argument("--uv-unwrap", metavar="PROGRAM",
                        help="the uv_unwrap program (default: UV_UNWRAP, then the build's bin/, then the PATH)")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar, no summary")
    rows = option_table()
    add_table_options(parser, rows)
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error("--workers must be at least 1")
    if args.retries < 0:
        parser.error("--retries must be at least 0")
    if args.memory_limit is not None:
        from dask.utils import parse_bytes
        try:
            args.memory_limit = int(parse_bytes(args.memory_limit))
        except (ValueError, TypeError):
            parser.error("--memory-limit: %r is not a size (e.g. 4GB, 500MiB)" % args.memory_limit)
        if args.memory_limit <= 0:
            parser.error("--memory-limit must be positive")
    if args.no_box and args.table_box_stiffness:
        parser.error("--no-box contradicts --box-stiffness (give one of them)")
    args.flags = cli_arguments(args, rows)
    return args


# ------------------------------------------------------------------ inputs

def collect_inputs(inputs, output_dir, output_format):
    """[(input path, output path)], folders walked in name order; the output folder is left out."""
    out_root = os.path.abspath(output_dir)
    jobs, named = [], []

    def add(path, relative_dir):
        if os.path.abspath(path) in (src for src, _ in jobs):
            return  # a file given twice is one input
        stem, extension = os.path.splitext(os.path.basename(path))
        fmt = output_format or OUTPUT_FORMAT.get(extension.lower(), "obj")
        jobs.append((os.path.abspath(path), os.path.join(output_dir, relative_dir, stem + "_uv." + fmt)))
        named.append((relative_dir, stem, extension.lstrip(".").lower(), fmt))

    for given in inputs:
        if os.path.isdir(given):
            root = os.path.abspath(given)
            for folder, subfolders, files in os.walk(root):
                subfolders[:] = sorted(d for d in subfolders if not d.startswith(".")
                                       and os.path.abspath(os.path.join(folder, d)) != out_root)
                relative = os.path.relpath(folder, root)
                for name in sorted(files):
                    if os.path.splitext(name)[1].lower() in MESH_EXTENSIONS:
                        add(os.path.join(folder, name), "" if relative == "." else relative)
        elif os.path.exists(given):
            add(given, "")
        else:
            raise UsageError("%s: no such file or folder" % given)
    if not jobs:
        raise UsageError("no mesh files in %s (%s)" % (" ".join(inputs), " ".join(MESH_EXTENSIONS)))
    return unique_outputs(jobs, named, output_dir)


def unique_outputs(jobs, named, output_dir):
    """Inputs whose outputs would share a name (pig.off beside pig.stl, one name in two given folders)
    get their extension in it, then their rank, so that no output overwrites another."""
    def count(paths):
        counts = {}
        for p in paths:
            counts[p] = counts.get(p, 0) + 1
        return counts
    outputs = [out for _, out in jobs]
    clashes = count(outputs)
    for i, (relative_dir, stem, extension, fmt) in enumerate(named):
        if clashes[outputs[i]] > 1:
            outputs[i] = os.path.join(output_dir, relative_dir, "%s_%s_uv.%s" % (stem, extension, fmt))
    clashes, rank = count(outputs), {}
    for i, (relative_dir, stem, extension, fmt) in enumerate(named):
        if clashes[outputs[i]] > 1:
            key = outputs[i]
            rank[key] = rank.get(key, 0) + 1
            outputs[i] = os.path.join(output_dir, relative_dir, "%s_%s_%d_uv.%s" % (stem, extension, rank[key], fmt))
    return [(src, out) for (src, _), out in zip(jobs, outputs)]


def input_signature(path):
    try:
        s = os.stat(path)
        return "%d:%d" % (s.st_size, s.st_mtime_ns)
    except OSError:
        return None


def read_records(path):
    """{input: its last record} of batch.jsonl (a line cut short by a crash is left out)."""
    records = {}
    with contextlib.suppress(FileNotFoundError), open(path, encoding="utf-8", errors="surrogateescape") as f:
        for line in f:
            with contextlib.suppress(ValueError):
                record = json.loads(line)
                if isinstance(record, dict) and "input" in record:
                    records[record["input"]] = record
    return records


def is_done(record, output, digest, signature):
    """The input needs no run: recorded with these options on this file, and its output there or its failure its own."""
    if record is None or record.get("options_hash") != digest or record.get("input_signature") != signature:
        return False
    if record.get("status") == "ok":
        return record.get("output") == output and os.path.isfile(output)
    return record.get("status") not in TRANSIENT


# ------------------------------------------------------------------ the batch (on the client)

@contextlib.contextmanager
def dask_client(args, say):
    """A client of --scheduler, or of a local cluster of --workers processes of one thread each."""
    import logging

    import dask
    from distributed import Client, LocalCluster
    if args.scheduler:
        try:
            client = Client(args.scheduler, timeout="20s")
        except (OSError, TimeoutError) as e:
            raise UsageError("cannot reach the scheduler %s: %s" % (args.scheduler, e))
        with client:
            say("scheduler %s, %d workers; dashboard: %s"
                % (args.scheduler, len(client.scheduler_info()["workers"]), client.dashboard_link))
            yield client
        return
    os.environ.update(ONE_THREAD)  # the workers' processes inherit it (and so their uv_unwrap children)
    # a worker's death fails its task at once: the batch runs it again itself, --retries times;
    # a worker holds only the task it runs (the others wait on the scheduler, not on a worker that may die)
    with dask.config.set({"distributed.scheduler.allowed-failures": 0,
                          "distributed.scheduler.worker-saturation": 1.0}):
        workers = args.workers or len(os.sched_getaffinity(0)) or 1
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
            import importlib.util
            served = importlib.util.find_spec("bokeh") is not None
            say("local cluster of %d workers; dashboard: %s%s" % (workers, cluster.dashboard_link,
                "" if served else " (served only where bokeh is installed)"))
            yield client


class Progress:
    """Meshes done / failed / total, rate and time left on a terminal (tqdm); failures as lines elsewhere."""

    def __init__(self, total, skipped, quiet):
        self.total, self.skipped, self.failed, self.quiet, self.bar = total, skipped, 0, quiet, None

    def start(self):
        """Once the cluster is up (its start is not the meshes' rate)."""
        if not self.quiet and sys.stderr.isatty():
            with contextlib.suppress(ImportError):
                from tqdm import tqdm
                self.bar = tqdm(total=self.total, unit="mesh", dynamic_ncols=True, desc="uv_unwrap.batch")
                self.bar.set_postfix(failed=0, skipped=self.skipped)

    def add(self, record):
        if record["status"] != "ok":
            self.failed += 1
            self.say("%s: %s (%s)" % (record["input"], record.get("error"), record["status"]))
        if self.bar is not None:
            self.bar.set_postfix(failed=self.failed, skipped=self.skipped, refresh=False)
            self.bar.update(1)

    def say(self, text):
        if self.quiet:
            return
        if self.bar is not None:
            self.bar.write("uv_unwrap.batch: " + text, file=sys.stderr)
        else:
            print("uv_unwrap.batch: " + text, file=sys.stderr, flush=True)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _failure(job, status, error):
    return {"input": job["input"], "output": None, "status": status, "error": error}


def run_tasks(client, jobs, retries, on_record):
    """Each job as a task, a bounded number at a time; a task whose worker died (or that raised) is run
    again up to `retries` times, then recorded as ERROR_WORKER_LOST. on_record(job, record) for each."""
    from distributed import as_completed
    waiting = iter(jobs)
    running = as_completed()
    job_of = {}
    window = max(64, 4 * sum(client.nthreads().values()))
    token = os.urandom(4).hex()

    def submit(job):
        future = client.submit(unwrap_task, job, key="uv_unwrap-%s-%d-%d" % (token, job["index"], job["attempt"]),
                               pure=False)
        job_of[future.key] = job
        running.add(future)

    for job in itertools.islice(waiting, window):
        submit(job)
    for future in running:
        job = job_of.pop(future.key)
        try:
            record = future.result()
        except Exception as e:  # KilledWorker (its worker died), or the worker's own failure
            if job["attempt"] <= retries:
                submit(dict(job, attempt=job["attempt"] + 1))
                continue
            record = _failure(job, "ERROR_WORKER_LOST", "its worker failed %d time(s): %s: %s"
                              % (job["attempt"], type(e).__name__, e))
        future.release()
        on_record(job, record)
        job = next(waiting, None)
        if job is not None:
            submit(job)


def write_records(path, kept, records):
    """batch.jsonl rewritten whole (a temporary file, then os.replace): one line per input."""
    temporary = path + ".tmp"
    with open(temporary, "w", encoding="utf-8") as f:
        for record in list(kept) + list(records):
            f.write(json.dumps(record) + "\n")
        f.flush()
        os.fsync(f.fileno())
    os.replace(temporary, path)


def remove_leftovers(outputs):
    """The temporary folders of tasks that died with their worker (their child killed with them)."""
    folders = {os.path.dirname(o) for o in outputs}
    for folder in folders:
        parent = os.path.dirname(folder)
        for leftover in glob.glob(os.path.join(glob.escape(parent), glob.escape("." + os.path.basename(folder))
                                               + TEMPORARY + "*")) + \
                glob.glob(os.path.join(glob.escape(folder), TEMPORARY + "*")):
            shutil.rmtree(leftover, ignore_errors=True)


def run_batch(args):
    import fcntl
    program = find_program(args.uv_unwrap)
    pairs = collect_inputs(args.inputs, os.path.abspath(args.output_dir), args.format)
    digest = options_hash(args.flags, args.format)
    os.makedirs(args.output_dir, exist_ok=True)
    path = os.path.join(args.output_dir, RECORDS)
    journal = open(path, "a", encoding="utf-8")
    try:
        fcntl.flock(journal, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        raise UsageError("another batch is writing into %s" % args.output_dir)
    old = read_records(path)
    final, jobs, claimed = {}, [], {}
    for index, (source, output) in enumerate(pairs):
        signature = input_signature(source)
        job = {"index": index, "input": source, "output": output, "program": program, "flags": args.flags,
               "timeout": args.timeout, "memory_limit": args.memory_limit, "attempt": 1,
               "options_hash": digest, "input_signature": signature}
        if source in final:
            continue  # given twice
        if output in claimed:
            final[source] = dict(_failure(job, "ERROR_USAGE", "another input (%s) writes the same output %s"
                                          % (claimed[output], output)), attempts=0, options_hash=digest,
                                 input_signature=signature)
            continue
        claimed[output] = source
        if is_done(old.get(source), output, digest, signature):
            final[source] = old[source]
        else:
            final[source] = None
            jobs.append(job)
    skipped = sum(1 for r in final.values() if r is not None)
    progress = Progress(len(jobs), skipped, args.quiet)

    def on_record(job, record):
        record.update(attempts=job["attempt"], options_hash=job["options_hash"],
                      input_signature=job["input_signature"])
        final[job["input"]] = record
        journal.write(json.dumps(record) + "\n")  # as it comes: an interrupted batch keeps what it did
        journal.flush()
        os.fsync(journal.fileno())
        progress.add(record)

    try:
        if jobs:
            with dask_client(args, progress.say) as client:
                progress.start()
                run_tasks(client, jobs, args.retries, on_record)
    finally:
        progress.close()
        remove_leftovers([o for _, o in pairs])
        write_records(path, [r for k, r in old.items() if k not in final],
                      [r for r in final.values() if r is not None])
        journal.close()
    records = list(final.values())
    ok = sum(1 for r in records if r is not None and r["status"] == "ok")
    progress.say("%d of %d inputs unwrapped (%d run, %d skipped as done); records in %s"
                 % (ok, len(records), len(jobs), skipped, path))
    return 0 if ok == len(records) else 1


def _interrupt(signum, frame):
    raise KeyboardInterrupt


def main(argv=None):
    with contextlib.suppress(ValueError):  # (main thread only)
        signal.signal(signal.SIGTERM, _interrupt)  # as Ctrl-C: the records written, the cluster closed
    try:
        args = parse_arguments(sys.argv[1:] if argv is None else argv)
        return run_batch(args)
    except UsageError as e:
        print("uv_unwrap.batch: error: %s" % e, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("uv_unwrap.batch: interrupted (the inputs done are recorded; run again to go on)", file=sys.stderr)
        return 130


if __name__ == "__main__":
    # through the package, so that the tasks name uv_unwrap.batch.unwrap_task (not __main__'s)
    from uv_unwrap import batch
    sys.exit(batch.main())
