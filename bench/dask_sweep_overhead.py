#!/usr/bin/env python3
"""The Dask sweep against `shellindent sweep -j 2` (issue 18: within 15 %).

Runs a study (default: the paper's 8 lay-ups, studies/paper_layups.yaml) twice from scratch:
through the CLI with -j 2, and through shellindent.sweep() on a LocalCluster of 2 worker
processes (cluster start-up included); checks the two sweep.csv are equal and prints both wall
times. Never in ctest (timed); the figures go into docs/python.md.

    PYTHONPATH=build/python /usr/bin/python3 bench/dask_sweep_overhead.py [--quick] [--exe ...]
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

import shellindent as si


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default="build/shellindent")
    parser.add_argument("--study", default="studies/paper_layups.yaml")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    quick = ["--quick"] if args.quick else []
    tmp = tempfile.mkdtemp(prefix="dask_sweep_bench_")
    try:
        start = time.perf_counter()
        subprocess.run([args.exe, "sweep", args.study, "-j", "2", "--out",
                        os.path.join(tmp, "cli"), *quick], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        cli = time.perf_counter() - start
        start = time.perf_counter()
        with open(os.devnull, "w") as quiet:
            result = si.sweep(args.study, out=os.path.join(tmp, "dask"), quick=args.quick,
                              workers=2, log=quiet)
        dask = time.perf_counter() - start
        with open(os.path.join(tmp, "cli", "sweep.csv")) as f:
            same = f.read() == result.csv
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print(f"{args.study}{' --quick' if args.quick else ''}: {len(result.rows)} cases; "
          f"load {os.getloadavg()[0]:.1f}")
    print(f"shellindent sweep -j 2:        {cli:8.2f} s")
    print(f"shellindent.sweep, 2 workers:  {dask:8.2f} s  ({100 * (dask - cli) / cli:+.1f} %)")
    print("sweep.csv equal:", same)
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
