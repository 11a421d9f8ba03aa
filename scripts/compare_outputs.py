#!/usr/bin/python3
"""Runs the user-visible jobs with two builds and compares every output file (issue 14: a
restructuring must not change what the toolkit writes).

The jobs: the main job (`shellindent run`, the built-in default case, and its figure by
studies/plot_path.py), the paper study (`studies/paper_layups.py --quick` and the full study,
every variant), the sandwich study (`studies/sandwich.py`) and the verification report
(`studies/verification.py` with the gtest binary). Reports and figures always go to the output
directory (never into the tracked docs/).

Each side runs in the same staging directory, WORK/stage, with its executable, test binary and
study scripts copied into it, so the paths written into the outputs (case files, study files)
are the same for both; the staging directory is then renamed to WORK/<label>. The comparison
walks WORK/<a>/out and WORK/<b>/out:
  identical     the same bytes;
  volatile      the same after masking what changes from run to run: durations ("3.1 s", ETA),
                dates, load averages and JSON keys that hold them (wall_s, cpu_s, measured,
                load_average), and the order of lines in logs of parallel sweeps;
  reordered     the verification records (records.jsonl, verification.csv, verification.json):
                the same records, in another order (the order in which the test binaries ran
                them, which follows the test files);
  round-off     numbers differ within --rtol/--atol, everything else the same (only with a
                tolerance given; the default compares exactly);
  different     anything else (listed with the first differing lines).

Usage:
  scripts/compare_outputs.py run --label old --exe OLD/shellindent --tests OLD/shellindent_tests \\
      --src OLD_SOURCE_TREE --work /tmp/cmp [--jobs-only main,paper_quick,...] [-j 2]
  scripts/compare_outputs.py compare --work /tmp/cmp old new [--rtol 1e-9 --atol 1e-14]
  scripts/compare_outputs.py both --work /tmp/cmp --old-exe ... --old-tests ... --old-src ...
      --new-exe ... --new-tests ... --new-src ...
Exit status: 0 if nothing is `different`, 1 otherwise, 2 for bad arguments.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

JOBS = ["main", "paper_quick", "paper_full", "sandwich", "verification"]
TEST_BINARIES = ["shellindent_tests", "continuation_tests", "fitting_tests"]

# ---- running ---------------------------------------------------------------------------------


def job_commands(jobs_j, root):
    """{job: [argv, ...]} relative to the staging directory (cwd)."""
    py = "/usr/bin/python3"
    tests = [f"bin/{b}" for b in TEST_BINARIES if os.path.exists(os.path.join(root, "bin", b))]
    return {
        "main": [["bin/shellindent", "run", "--out", "out/main"],
                 [py, "src/studies/plot_path.py", "out/main", "out/main/force_depth.png"]],
        "paper_quick": [[py, "src/studies/paper_layups.py", "--quick", "--exe", "bin/shellindent",
                         "-j", str(jobs_j), "--out", "out/paper_quick",
                         "--report-dir", "out/paper_quick/report"]],
        "paper_full": [[py, "src/studies/paper_layups.py", "--exe", "bin/shellindent",
                        "-j", str(jobs_j), "--out", "out/paper_full",
                        "--report-dir", "out/paper_full/report"]],
        "sandwich": [[py, "src/studies/sandwich.py", "--exe", "bin/shellindent", "-j", str(jobs_j),
                      "--out", "out/sandwich", "--report-dir", "out/sandwich/report"]],
        "verification": [[py, "src/studies/verification.py", "--tests"] + tests + [
                          "--out", "out/verification",
                          "--doc", "out/verification_doc/verification.md"]],
    }


def stage(args):
    """WORK/stage with bin/ (the two binaries) and src/ (studies/, docs/verification.md)."""
    root = os.path.join(args.work, "stage")
    if os.path.exists(root):
        shutil.rmtree(root)
    os.makedirs(os.path.join(root, "bin"))
    shutil.copy2(args.exe, os.path.join(root, "bin", "shellindent"))
    if args.tests:
        # The toolkit's gtest binary and, beside it, the generic libraries' own (if built).
        for name in TEST_BINARIES:
            path = os.path.join(os.path.dirname(args.tests), name)
            if os.path.exists(path):
                shutil.copy2(path, os.path.join(root, "bin", name))
    shutil.copytree(os.path.join(args.src, "studies"), os.path.join(root, "src", "studies"),
                    ignore=shutil.ignore_patterns("__pycache__"))
    os.makedirs(os.path.join(root, "out", "verification_doc"))
    # The report's template: this side's docs/verification.md, or one given for both sides (its
    # prose may change with the code; the generated tables are what is compared).
    shutil.copy2(args.verification_doc or os.path.join(args.src, "docs", "verification.md"),
                 os.path.join(root, "out", "verification_doc", "verification.md"))
    return root


def run_side(args):
    root = stage(args)
    wanted = args.jobs_only.split(",") if args.jobs_only else JOBS
    commands = job_commands(args.j, root)
    for job in wanted:
        for k, argv in enumerate(commands[job]):
            start = time.monotonic()
            with open(os.path.join(root, "out", f"{job}.{k}.stdout"), "w") as out, \
                    open(os.path.join(root, "out", f"{job}.{k}.stderr"), "w") as err:
                code = subprocess.call(argv, cwd=root, stdout=out, stderr=err)
            with open(os.path.join(root, "out", f"{job}.{k}.exit"), "w") as f:
                f.write(f"{code}\n")
            print(f"{args.label}: {job} step {k}: exit {code}, {time.monotonic() - start:.1f} s",
                  file=sys.stderr, flush=True)
    target = os.path.join(args.work, args.label)
    if os.path.exists(target):
        shutil.rmtree(target)
    os.rename(root, target)
    return 0


# ---- comparing -------------------------------------------------------------------------------

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf")
DURATION = re.compile(r"\b\d+(?:\.\d+)?(?:e[-+]?\d+)? ?(?:s|ms|min)\b")
DATE = re.compile(r"\d{4}-\d{2}-\d{2}[ T]\d{2}:\d{2}(?::\d{2}(?:\.\d+)?)?(?: UTC)?")
LOAD = re.compile(r"(load(?: average)?:?|end of this script:) \d+(?:\.\d+)?(?:, \d+(?:\.\d+)?)*")
# Timings, the last lines of a parallel sweep's log (which case ends last varies), and the build
# record of path.json (two builds compared differ in their source fingerprint by definition).
VOLATILE_KEY = re.compile(
    r"(^|_)(wall|cpu|seconds|elapsed)(_|$)|load_average|measured|^time|stderr_tail"
    r"|source_fingerprint")
PROGRESS = re.compile(r"(sweep:) \d+/")
# The lines that say which test binary runs (the verification runs one or three).
BINARY_BANNERS = ("Running main() from", "running: ")
SOURCE_PATH = re.compile(r"[^\s:]*/tests/")
TIME_HEADER = re.compile(r"time|measured", re.I)
LOG_SUFFIXES = (".log", ".stderr")
# What the verification's test binaries print: one binary's tests after another's.
LOG_FILES = ("run.log", "verification.0.stdout")


def mask_json(value):
    if isinstance(value, dict):
        return {k: ("<volatile>" if VOLATILE_KEY.search(k)
                    else mask_json(v))
                for k, v in value.items()}
    if isinstance(value, list):
        return [mask_json(v) for v in value]
    if isinstance(value, str):
        return mask_text(value)
    return value


def mask_text(text):
    text = DATE.sub("<date>", text)
    text = SOURCE_PATH.sub("tests/", text)  # __FILE__ in test messages: as the build spelt it
    text = LOAD.sub(r"\1 <load>", text)
    text = PROGRESS.sub(r"\1 <n>/", text)
    return mask_table_columns(DURATION.sub("<duration>", text))


def mask_table_columns(text):
    """Markdown tables: the cells of columns whose header names a time ("wall time (s)")."""
    lines = text.split("\n")
    masked = set()
    for i, line in enumerate(lines):
        if line.startswith("|") and i + 1 < len(lines) and re.match(r"\|\s*-", lines[i + 1]):
            masked = {k for k, cell in enumerate(line.split("|")) if TIME_HEADER.search(cell)}
        elif not line.startswith("|"):
            masked = set()
        elif masked:
            cells = line.split("|")
            lines[i] = "|".join("<volatile>" if k in masked else c for k, c in enumerate(cells))
    return "\n".join(lines)


def normalised(path, data):
    """The file's content with the run-to-run changes masked (None: binary, compare bytes)."""
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return None
    if path.endswith(".json"):
        try:
            return json.dumps(mask_json(json.loads(text)), indent=1, sort_keys=True)
        except ValueError:
            pass
    text = mask_text(text)
    if path.endswith(LOG_SUFFIXES) or os.path.basename(path) in LOG_FILES:
        # Parallel sweeps finish their cases in any order; progress lines overwrite themselves.
        lines = [line for chunk in text.split("\n") for line in chunk.split("\r")
                 if not line.startswith(BINARY_BANNERS)]
        text = "\n".join(sorted(lines))
    return text


def record_set(path, data):
    """The verification records of a file, order-free (None if not such a file)."""
    name = os.path.basename(path)
    text = data.decode("utf-8", "replace")
    if name == "records.jsonl":
        return sorted(line for line in text.splitlines() if line.strip())
    if name == "verification.csv":
        lines = text.splitlines()
        return lines[:1] + sorted(lines[1:])
    if name == "verification.json":
        doc = json.loads(text)
        doc["records"] = sorted(json.dumps(r, sort_keys=True) for r in doc["records"])
        return doc
    return None


def numeric_diff(a, b, rtol, atol):
    """(same apart from numbers within tolerance, largest relative difference)."""
    ta, tb = NUMBER.split(a), NUMBER.split(b)
    na, nb = NUMBER.findall(a), NUMBER.findall(b)
    if ta != tb or len(na) != len(nb):
        return False, None
    worst = 0.0
    for x, y in zip(na, nb):
        if x == y:
            continue
        fx, fy = float(x), float(y)
        if fx != fx and fy != fy:
            continue
        d = abs(fx - fy)
        scale = max(abs(fx), abs(fy))
        if d > atol + rtol * scale:
            return False, None
        worst = max(worst, d / scale if scale > 0 else 0.0)
    return True, worst


def first_differences(a, b, n=3):
    la, lb = a.splitlines(), b.splitlines()
    out = []
    for i in range(max(len(la), len(lb))):
        x = la[i] if i < len(la) else "<missing>"
        y = lb[i] if i < len(lb) else "<missing>"
        if x != y:
            out.append(f"    line {i + 1}:\n      - {x[:200]}\n      + {y[:200]}")
            if len(out) == n:
                break
    return out


def files_under(root):
    found = set()
    for d, _, names in os.walk(root):
        for name in names:
            found.add(os.path.relpath(os.path.join(d, name), root))
    return found


def compare(args):
    a_root = os.path.join(args.work, args.a, "out")
    b_root = os.path.join(args.work, args.b, "out")
    fa, fb = files_under(a_root), files_under(b_root)
    if args.jobs_only:
        jobs = tuple(args.jobs_only.split(","))
        def of_jobs(rel):
            return rel.split("/")[0].split(".")[0] in jobs
        fa, fb = {f for f in fa if of_jobs(f)}, {f for f in fb if of_jobs(f)}
    result = {"identical": [], "volatile": [], "reordered": [], "round-off": [], "different": []}
    details = []
    for rel in sorted(fa - fb):
        result["different"].append(rel)
        details.append(f"  {rel}: only in {args.a}")
    for rel in sorted(fb - fa):
        result["different"].append(rel)
        details.append(f"  {rel}: only in {args.b}")
    worst_roundoff = 0.0
    for rel in sorted(fa & fb):
        with open(os.path.join(a_root, rel), "rb") as f:
            da = f.read()
        with open(os.path.join(b_root, rel), "rb") as f:
            db = f.read()
        if da == db:
            result["identical"].append(rel)
            continue
        na, nb = normalised(rel, da), normalised(rel, db)
        if na is not None and na == nb:
            result["volatile"].append(rel)
            continue
        ra = record_set(rel, da)
        if ra is not None and ra == record_set(rel, db):
            result["reordered"].append(rel)
            continue
        if na is not None and args.rtol > 0:
            ok, worst = numeric_diff(na, nb, args.rtol, args.atol)
            if ok:
                result["round-off"].append(rel)
                worst_roundoff = max(worst_roundoff, worst)
                details.append(f"  {rel}: round-off, largest relative difference {worst:.3g}")
                continue
        result["different"].append(rel)
        details.append(f"  {rel}: different" + ("" if na is not None else " (binary)"))
        if na is not None:
            details.extend(first_differences(na, nb))
    total = len(fa | fb)
    print(f"compared {total} files of {args.a} and {args.b}: "
          f"{len(result['identical'])} byte-identical, "
          f"{len(result['volatile'])} identical up to timings/dates/log order, "
          f"{len(result['reordered'])} the same records in another order, "
          f"{len(result['round-off'])} within rtol {args.rtol:g} / atol {args.atol:g}"
          + (f" (largest {worst_roundoff:.3g})" if result["round-off"] else "")
          + f", {len(result['different'])} different")
    if args.list_volatile and result["volatile"]:
        print("volatile only:\n  " + "\n  ".join(result["volatile"]))
    if details:
        print("\n".join(details))
    return 1 if result["different"] else 0


# ---- command line ----------------------------------------------------------------------------


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run the jobs with one build")
    r.add_argument("--label", required=True)
    r.add_argument("--exe", required=True)
    r.add_argument("--tests", help="gtest binary for the verification report")
    r.add_argument("--src", required=True, help="the source tree whose studies/ to use")
    r.add_argument("--work", required=True)
    r.add_argument("--jobs-only", help=f"comma-separated subset of {','.join(JOBS)}")
    r.add_argument("--verification-doc", help="template of the verification report")
    r.add_argument("-j", type=int, default=2)
    c = sub.add_parser("compare", help="compare two runs")
    c.add_argument("--work", required=True)
    c.add_argument("a")
    c.add_argument("b")
    c.add_argument("--jobs-only", help="compare only these jobs' outputs")
    b = sub.add_parser("both", help="run old and new, then compare")
    b.add_argument("--work", required=True)
    for side in ("old", "new"):
        b.add_argument(f"--{side}-exe", required=True)
        b.add_argument(f"--{side}-tests")
        b.add_argument(f"--{side}-src", required=True)
    b.add_argument("--jobs-only")
    b.add_argument("--verification-doc")
    b.add_argument("-j", type=int, default=2)
    for q in (c, b):
        q.add_argument("--rtol", type=float, default=0.0, help="numeric tolerance mode")
        q.add_argument("--atol", type=float, default=0.0)
        q.add_argument("--list-volatile", action="store_true")
    args = p.parse_args()
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    if args.command == "run":
        return run_side(args)
    if args.command == "compare":
        return compare(args)
    for side in ("old", "new"):
        side_args = argparse.Namespace(label=side, exe=getattr(args, f"{side}_exe"),
                                       tests=getattr(args, f"{side}_tests"),
                                       src=getattr(args, f"{side}_src"), work=args.work,
                                       jobs_only=args.jobs_only, j=args.j,
                                       verification_doc=args.verification_doc)
        run_side(side_args)
    args.a, args.b = "old", "new"
    return compare(args)


if __name__ == "__main__":
    sys.exit(main())
