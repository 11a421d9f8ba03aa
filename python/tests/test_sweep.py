"""shellindent.sweep on a Dask LocalCluster (2 worker processes on the loopback address) against
`shellindent sweep -j 2`: the same sweep.csv byte for byte, also when a worker is killed while
it runs a case (the scheduler resubmits it); a sweep started again submits nothing."""

import os
import shutil
import threading
import time
import unittest

import shellindent as si
from cases import OUT, run_cli
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

    def test_a_worker_killed_mid_run_loses_only_its_case(self):
        out = fresh("sweep_dask_killed")
        result, killed = sweep_killing_busy_workers(STUDY, out, kills=1)
        self.assertEqual(killed, 1, "no worker was busy to kill")
        self.assertEqual(result.failed, 0)
        self.assertEqual(read(os.path.join(out, "sweep.csv")), self.cli_csv)


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
