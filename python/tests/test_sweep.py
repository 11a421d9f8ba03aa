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
        client, cluster = _local_client(2)
        try:
            killed = []

            def kill_a_busy_worker():
                deadline = time.monotonic() + 60
                while time.monotonic() < deadline and not killed:
                    busy = [w for w, tasks in client.processing().items() if tasks]
                    if busy:
                        pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
                        os.kill(pid, 9)
                        killed.append(pid)
                    time.sleep(0.01)

            killer = threading.Thread(target=kill_a_busy_worker)
            killer.start()
            result = si.sweep(STUDY, client=client, out=out)
            killer.join()
        finally:
            client.close()
            cluster.close()
        self.assertTrue(killed, "no worker was busy to kill")
        self.assertEqual(result.failed, 0)
        self.assertEqual(read(os.path.join(out, "sweep.csv")), self.cli_csv)


if __name__ == "__main__":
    unittest.main()
