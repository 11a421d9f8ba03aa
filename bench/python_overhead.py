#!/usr/bin/env python3
"""The Python module's overhead against the CLI (issue 18: under 1 % of a default run).

Runs the built-in default case (the source paper's cap, 0-10 mm, pseudo-arclength) without VTU
files, once through `shellindent run` and once through shellindent.run() in this process, each
`--repeat` times, alternately, on one assembly thread; reports the median and minimum wall and CPU times
(CPU: the child's for the CLI, this process's for the module) and the module's import time.
The CLI's process start and file writing count against it; the module's callback per point
(a no-op progress function, the GIL taken and released at each point) counts against the
module. Never in ctest (timed); the figures go into docs/python.md.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--exe build/shellindent]
                                                                     [--repeat 3]
"""

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

start = time.perf_counter()
import shellindent as si  # noqa: E402  (timed)

IMPORT_S = time.perf_counter() - start


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def time_cli(exe, case_file, out):
    wall, cpu = time.perf_counter(), children_cpu()
    subprocess.run([exe, "run", case_file, "--out", out, "--threads", "1"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - wall, children_cpu() - cpu, None


def time_module(case):
    wall, cpu = time.perf_counter(), time.process_time()
    result = si.run(case, progress=lambda p: None, threads=1)
    return time.perf_counter() - wall, time.process_time() - cpu, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default="build/shellindent")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    text = si.default_case().yaml.replace("vtu_every: 10", "vtu_every: 0")
    with tempfile.TemporaryDirectory() as tmp:
        case_file = os.path.join(tmp, "default_no_vtu.yaml")
        with open(case_file, "w") as f:
            f.write(text)
        case = si.read_case(case_file)
        cli, mod = [], []
        for i in range(args.repeat):
            cli.append(time_cli(args.exe, case_file, os.path.join(tmp, f"cli{i}")))
            mod.append(time_module(case))
    points = len(mod[-1][2])
    print(f"default case without VTU, {points} points, one thread, median of {args.repeat}; "
          f"load {os.getloadavg()[0]:.1f}")
    print(f"{'':8} {'median wall s':>14} {'median CPU s':>13} {'min wall s':>11} {'min CPU s':>10}")
    rows = {"CLI": cli, "module": mod}
    for name, runs in rows.items():
        print(f"{name:8} {statistics.median(r[0] for r in runs):14.3f} "
              f"{statistics.median(r[1] for r in runs):13.3f} {min(r[0] for r in runs):11.3f} "
              f"{min(r[1] for r in runs):10.3f}")
    # The minimum is the run least disturbed by the machine's other work.
    for k, what in ((0, "wall"), (1, "CPU")):
        for stat_name, stat in (("median", statistics.median), ("min", min)):
            c = stat(r[k] for r in cli)
            m = stat(r[k] for r in mod)
            print(f"module - CLI ({stat_name} {what}): {m - c:+.3f} s = "
                  f"{100 * (m - c) / c:+.2f} %")
    print(f"import shellindent: {IMPORT_S:.3f} s")
    for name, runs in rows.items():
        print(f"{name} runs (wall/CPU s): "
              + ", ".join(f"{w:.2f}/{c:.2f}" for w, c, _ in runs))
    return 0


if __name__ == "__main__":
    sys.exit(main())
