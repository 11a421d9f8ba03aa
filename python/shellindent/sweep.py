"""Parameter studies on a Dask cluster: shellindent.sweep(study, client=...).

The study file (docs/sweeps.md) is read and its cases expanded by the same C++ as
`shellindent sweep` (io/study_file); each case that is not already done becomes one task on the
cluster, which runs it with shellindent.run() on one thread and sends its result files back;
the client writes them into OUT/cases/NNN_<values>/ and, when all are in, sweep.csv and
sweep.json made by the same C++ as the CLI's (io/sweep_table), so the table is the CLI's.

No file system is shared with the workers: a task receives the case's text and returns the
files' text. Resuming is the CLI's: a case whose directory holds the same case.yaml and a
finished path.json is not submitted again. A worker that dies loses its running case, which
the scheduler resubmits; with the LocalCluster started here a case whose worker dies twice is
reported failed, with the reason in its run.log and the table (scheduler option
distributed.scheduler.allowed-failures = 1; an existing cluster keeps its own).
"""

import json
import os
import sys
import tempfile
import time

from . import _core
from .case import parse_case
from .errors import Error
from .run import run, write_atomically

STALE = ("path.json", "path.csv", "path_grid.csv", "events.json", "checkpoint.json")


def run_case_files(yaml, label):
    """The task: one case run on a worker, its files returned as {name: text}, status and
    seconds. Input errors found at set-up (the reader has checked the text already) are the
    case's failure, as a run.log line, like the CLI's."""
    start = time.monotonic()
    try:
        # A checkpoint as the CLI keeps one (in the worker's temporary directory, not sent
        # back): the same computation bit for bit, so the table equals `shellindent sweep`'s.
        with tempfile.TemporaryDirectory(prefix="shellindent-case-") as scratch:
            result = run(parse_case(yaml, label), threads=1,
                         checkpoint=os.path.join(scratch, "checkpoint.json"))
    except Error as e:
        return {"files": {"run.log": f"shellindent: error: {e}\n"}, "status": "failed",
                "seconds": time.monotonic() - start}
    files = result.files()
    files["run.log"] = (f"{result.status}: {len(result)} points" +
                        (f"; {result.reason}" if result.reason else "") + "\n")
    return {"files": files, "status": result.status, "seconds": time.monotonic() - start}


def _local_client(workers):
    import dask
    from distributed import Client, LocalCluster
    with dask.config.set({"distributed.scheduler.allowed-failures": 1}):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
    return Client(cluster), cluster


class SweepResult:
    """What sweep() did: the output directory, the table's text and the rows (sweep.json's
    cases), and how many cases failed."""

    def __init__(self, out, csv, doc):
        self.out = out
        self.csv = csv
        self.rows = json.loads(doc)["cases"]
        self.failed = sum(r["status"] not in ("completed", "reached_bound") for r in self.rows)

    def __repr__(self):
        return f"<shellindent.SweepResult {len(self.rows)} cases, {self.failed} failed>"


def sweep(study, client=None, out=None, quick=False, workers=2, log=sys.stderr):
    """Runs every case of the study file `study` on the Dask cluster of `client` (default: a
    LocalCluster of `workers` processes on the loopback address, closed at the end); writes
    OUT/cases/*/ and OUT/sweep.csv, sweep.json (OUT: `out`, default results/<study name>/).
    `quick` applies the study's quick: keys. Returns a SweepResult; bad input raises
    InputError before anything runs."""
    s = _core.read_study(os.fspath(study), quick)
    root = os.fspath(out) if out is not None else os.path.join("results", s.name)
    cases = s.cases
    dirs = [os.path.join(root, "cases", c["slug"]) for c in cases]
    todo = []
    for c, d in zip(cases, dirs):
        state = _core.case_state(d, c["yaml"])
        if state == "done":
            print(f"sweep: {c['label']}: already done, skipped", file=log)
            continue
        if state == "stale":
            print(f"sweep: {c['label']}: its results were written by another build of "
                  "shellindent (or one that did not record its source fingerprint): run again",
                  file=log)
        for stale in STALE:
            if os.path.exists(os.path.join(d, stale)):
                os.remove(os.path.join(d, stale))
        write_atomically(d, "case.yaml", c["yaml"])
        todo.append((c, d))
    own = None
    if todo and client is None:
        client, own = _local_client(workers)
    try:
        if todo:
            _run_all(client, todo, len(cases), log)
    finally:
        if own is not None:
            client.close()
            own.close()
    csv, doc = s.tables(dirs)
    write_atomically(root, "sweep.csv", csv)
    write_atomically(root, "sweep.json", doc)
    result = SweepResult(root, csv, doc)
    print(f"sweep: wrote {os.path.join(root, 'sweep.csv')} and sweep.json"
          + (f"; {result.failed} of {len(cases)} case(s) failed" if result.failed else ""),
          file=log)
    return result


def _run_all(client, todo, total, log):
    from distributed import as_completed
    futures = {client.submit(run_case_files, c["yaml"], c["label"], pure=False): (c, d)
               for c, d in todo}
    done = total - len(todo)
    for future in as_completed(futures):
        c, d = futures[future]
        done += 1
        try:
            outcome = future.result()
        except Exception as e:  # KilledWorker: the case's worker died, and its retry's
            outcome = {"files": {"run.log": f"failed on the cluster: {type(e).__name__}: {e}\n"},
                       "status": "failed", "seconds": float("nan")}
        for name, text in outcome["files"].items():
            write_atomically(d, name, text)
        took = f", {outcome['seconds']:.1f} s" if outcome["seconds"] == outcome["seconds"] else ""
        print(f"sweep: {done}/{total} {c['label']}: {outcome['status']}{took}", file=log)
