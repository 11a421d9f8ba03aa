"""shellindent.sweep on a Dask LocalCluster (2 worker processes on the loopback address) against
`shellindent sweep -j 2`: the same sweep.csv byte for byte, also when a worker is killed while
it runs a case (the scheduler resubmits it); a sweep started again submits nothing, unless
another build wrote the case's results."""

import json
import os
import shutil
import subprocess
import threading
import time
import unittest

import shellindent as si
from shellindent import _core
from cases import EXE, OUT, run_cli
from shellindent.sweep import _local_client

HERE = os.path.dirname(os.path.abspath(__file__))
STUDY = os.path.join(HERE, "four_radii.yaml")


def fresh(name):
    path = os.path.join(OUT, name)
    shutil.rmtree(path, ignore_errors=True)
    return path


def read(path):
    with open(path) as f:
        return f.read()


def sweep_killing_busy_workers(study, out, kills):
    """sweep() on a fresh LocalCluster while another thread SIGKILLs the worker that runs
    a case, `kills` times (each a different worker process); returns the result and the
    number of kills made."""
    client, cluster = _local_client(2)
    killed = []
    stop = threading.Event()  # the sweep is over

    def kill_busy_workers():
        while not stop.is_set() and len(killed) < kills:
            # Worker address -> process id from the nannies (no call to a worker, which may be
            # dead already); a worker with a case assigned whose process was not killed yet.
            pids = {}
            for nanny in list(cluster.workers.values()):
                process = getattr(nanny.process, "process", None) if nanny.process else None
                if process is not None and nanny.worker_address:
                    pids[nanny.worker_address] = process.pid
            for worker, tasks in client.processing().items():
                pid = pids.get(worker)
                if tasks and pid is not None and pid not in killed:
                    os.kill(pid, 9)
                    killed.append(pid)
                    break
            time.sleep(0.01)

    killer = threading.Thread(target=kill_busy_workers)
    try:
        killer.start()
        result = si.sweep(study, client=client, out=out)
    finally:
        stop.set()
        killer.join()
        client.close()
        cluster.close()
    return result, len(killed)


class DaskSweep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.cli_out = fresh("sweep_cli")
        code, _, err = run_cli("sweep", STUDY, "-j", "2", "--out", cls.cli_out)
        if code != 0:
            raise AssertionError("shellindent sweep failed:\n" + err)
        cls.cli_csv = read(os.path.join(cls.cli_out, "sweep.csv"))

    def test_local_cluster_gives_the_cli_table_and_resumes(self):
        out = fresh("sweep_dask")
        result = si.sweep(STUDY, out=out, workers=2)
        self.assertEqual(result.failed, 0)
        self.assertEqual(read(os.path.join(out, "sweep.csv")), self.cli_csv)
        for case in os.listdir(os.path.join(self.cli_out, "cases")):
            self.assertEqual(read(os.path.join(out, "cases", case, "path.csv")),
                             read(os.path.join(self.cli_out, "cases", case, "path.csv")), case)
        # Again: every case is done, nothing is submitted (no cluster is even started).
        log = []

        class Log:
            def write(self, text):
                log.append(text)

        again = si.sweep(STUDY, out=out, log=Log())
        self.assertEqual(again.csv, self.cli_csv)
        self.assertEqual(sum("already done, skipped" in line for line in log), 4)
        # The workers' path.json names this module's build; another build's is stale (the sweep
        # would run the case again), and so is one without the record.
        case = os.path.join(out, "cases", sorted(os.listdir(os.path.join(out, "cases")))[0])
        text = read(os.path.join(case, "case.yaml"))
        doc = json.loads(read(os.path.join(case, "path.json")))
        self.assertEqual(doc["build"]["source_fingerprint"], _core.source_fingerprint())
        self.assertEqual(_core.case_state(case, text), "done")
        for build in ({"source_fingerprint": "0" * 64}, None):
            if build is None:
                del doc["build"]
            else:
                doc["build"] = build
            with open(os.path.join(case, "path.json"), "w") as f:
                json.dump(doc, f)
            self.assertEqual(_core.case_state(case, text), "stale")
        self.assertEqual(_core.case_state(case, text + "# another case\n"), "to_run")

    def test_a_worker_killed_mid_run_loses_only_its_case(self):
        out = fresh("sweep_dask_killed")
        result, killed = sweep_killing_busy_workers(STUDY, out, kills=1)
        self.assertEqual(killed, 1, "no worker was busy to kill")
        self.assertEqual(result.failed, 0)
        self.assertEqual(read(os.path.join(out, "sweep.csv")), self.cli_csv)

    def test_cli_scheduler_option_gives_the_cli_table(self):
        # `shellindent sweep --scheduler ADDRESS` on a 2-worker LocalCluster started here.
        from distributed import LocalCluster
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        out = fresh("sweep_scheduler")
        try:
            code, stdout, err = run_cli("sweep", STUDY, "--scheduler",
                                        cluster.scheduler_address, "--out", out)
        finally:
            cluster.close()
        self.assertEqual(code, 0, err)
        self.assertIn("on the Dask cluster at tcp://127.0.0.1:", err)
        self.assertEqual(read(os.path.join(out, "sweep.csv")), self.cli_csv)
        self.assertEqual(stdout, self.cli_csv)


def run_cli_with(env, *args):
    p = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ, **env))
    return p.returncode, p.stdout, p.stderr


class SchedulerErrors(unittest.TestCase):
    """--scheduler without a way to reach a cluster: exit 2, a message naming --scheduler, no
    output directory left behind."""

    def check_refused(self, env, address, expected):
        out = fresh("sweep_scheduler_refused")
        start = time.monotonic()
        code, _, err = run_cli_with(env, "sweep", STUDY, "--scheduler", address, "--out", out)
        self.assertEqual(code, 2, err)
        self.assertIn(f"shellindent: error: command line: --scheduler = '{address}': ", err)
        self.assertIn(expected, err)
        self.assertFalse(os.path.exists(out))
        return time.monotonic() - start

    def test_unreachable_scheduler_is_an_error_after_the_connect_timeout(self):
        # Port 9 (discard) on the loopback address: nobody listens there on a test machine.
        seconds = self.check_refused({}, "tcp://127.0.0.1:9", "cannot reach the Dask scheduler")
        self.assertLess(seconds, 60)

    def test_missing_dask_distributed_is_named(self):
        fake = fresh("no_distributed")
        os.makedirs(os.path.join(fake, "distributed"))
        with open(os.path.join(fake, "distributed", "__init__.py"), "w") as f:
            f.write("raise ImportError('no distributed here (test)')\n")
        env = {"PYTHONPATH": fake + os.pathsep + os.environ.get("PYTHONPATH", "")}
        self.check_refused(env, "tcp://127.0.0.1:9", "dask.distributed cannot be imported")

    def test_missing_interpreter_is_named(self):
        self.check_refused({"SHELLINDENT_PYTHON": "/nonexistent/python3"}, "tcp://127.0.0.1:9",
                           "cannot start the Python interpreter /nonexistent/python3")

    def test_missing_module_is_named(self):
        # An interpreter without the module: the build tree's is put first only when present,
        # so a python3 started with -I (isolated: no PYTHONPATH, no user site) stands for one.
        if subprocess.run(["/usr/bin/python3", "-I", "-c", "import shellindent"],
                          capture_output=True).returncode == 0:
            self.skipTest("shellindent is installed for /usr/bin/python3")
        directory = fresh("isolated_python")
        os.makedirs(directory)
        wrapper = os.path.join(directory, "python3")
        with open(wrapper, "w") as f:
            f.write("#!/bin/sh\nexec /usr/bin/python3 -I \"$@\"\n")
        os.chmod(wrapper, 0o755)
        self.check_refused({"SHELLINDENT_PYTHON": wrapper}, "tcp://127.0.0.1:9",
                           "the Python module shellindent cannot be imported")


class DaskSweepWorkerDiesTwice(unittest.TestCase):
    def test_the_case_is_retried_once_then_reported_failed(self):
        # One case on a 2-process LocalCluster (allowed-failures 1): its worker is killed, the
        # scheduler resubmits it, its new worker is killed too: the case is failed, the sweep
        # still writes its table, with the reason.
        out = fresh("sweep_dask_killed_twice")
        result, killed = sweep_killing_busy_workers(
            os.path.join(HERE, "one_slow_case.yaml"), out, kills=2)
        self.assertEqual(killed, 2)
        self.assertEqual(result.failed, 1)
        row = result.rows[0]
        self.assertEqual(row["status"], "failed")
        self.assertIn("KilledWorker", row["reason"])
        self.assertIn("KilledWorker", read(os.path.join(out, "sweep.csv")))


if __name__ == "__main__":
    unittest.main()
