#!/usr/bin/python3
"""Verification study (issue 6): runs the verification tests of the gtest binaries, collects the
checks they record (tests/verification_record.hpp) and writes the report.

Every verification test computes its value, asserts it against the reference and, when the
environment variable SHELLINDENT_VERIFICATION_RECORD names a file, appends one JSON line per
check: table, check, reference, measured, error, tolerance, source, test. This script sets the
variable, runs the binaries (the toolkit's, and the continuation and fitting libraries' own), and
from the records, ordered by the document's tables (each table's rows in the order its tests
ran, whichever binary or file holds them), writes

  OUT/verification.csv, OUT/verification.json   one row per check, with pass/fail
  OUT/verification.png                          |error| / tolerance per check, by table
  docs/verification.md                          the tables between the markers
                                                <!-- verification:begin ID --> ... end ID -->

so that the numbers of the report are those of the tests ctest runs and cannot drift from the
code. Prose and rows without a record stay hand-written outside the markers.

Usage (from the source tree, after building):
  /usr/bin/python3 studies/verification.py     (build/tests/{shellindent,continuation,fitting}_tests)
  /usr/bin/python3 studies/verification.py --quick --tests ... --out build/verification_quick
  /usr/bin/python3 studies/verification.py --records OUT/records.jsonl   (report only, no run)
  /usr/bin/python3 studies/verification.py --self-test

--quick runs a fast subset (ctest's smoke test) and never edits docs/: the regenerated markdown
goes to OUT/verification.md. The full run (default) rewrites --doc (docs/verification.md) and the
figure docs/figures/verification.png. Exit status: 0 if the binary passed and every record is
within its tolerance; 1 otherwise; 2 for bad arguments or a missing binary or marker.
"""
import argparse
import csv
import datetime
import json
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.dirname(HERE)

RECORD_VARIABLE = "SHELLINDENT_VERIFICATION_RECORD"

# The verification suites (tests that compare with a published value, a closed form or another
# method and record their checks). The full study runs all of them.
FULL_FILTER = ":".join([
    "CltSection.*", "TransverseShear.*", "VamSection.*",
    "Mitc4Patch.*", "Mitc4Locking.*", "Mitc4Nonlinear.*",
    "LinearShellBenchmarks.*", "LaminateNavier.*", "InPlaneCantilever.*",
    "NonlinearShellBenchmarks.*", "ClampedPlateLinear.*", "PointLoads.*",
    "ClampedPlateSphere.*", "ContactVerification.*", "HertzDent.*", "LocalIndentation*",
    "AnisotropicHalfSpace.*", "LayerCompliance.*", "SphereOnLayer.*",
    "ContPseudoArclength.*", "ContEvents.*", "SzeHingedRoof.*", "SzeCaseFiles.*",
    "NistLinear.*", "*NistNonlinear.*",
])

# A fast subset of the same tests (a few seconds in Release): every kind of record (relative,
# absolute, custom scale) and every recorder path (section, element, linear benchmark, nonlinear
# path, fitting, continuation).
QUICK_FILTER = ":".join([
    "CltSection.IndentationLayups*", "TransverseShear.*", "VamSection.Vam_Paper*",
    "Mitc4Patch.MacNealHarder*", "LinearShellBenchmarks.ScordelisLoRoof*",
    "NonlinearShellBenchmarks.SzeLiuLo2004_CantileverEndShear*",
    "ContPseudoArclength.Circle*", "ContEvents.*", "NistLinear.*",
    "PointLoads.ThinCap*", "ContactVerification.ShallowCap*",
])

FIELDS = ["table", "check", "reference", "measured", "error", "tolerance", "pass", "scale_kind",
          "scale", "scale_name", "source", "test"]

BEGIN = re.compile(r"<!-- verification:begin ([A-Za-z0-9_.-]+) -->")
END = "<!-- verification:end {} -->"


# ---- records -------------------------------------------------------------------------------

def read_records(path):
    """The records of a JSON-lines file (missing file: none)."""
    if not os.path.exists(path):
        return []
    records = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                records.append(json.loads(line))
            except json.JSONDecodeError as e:
                raise SystemExit(f"{path}:{number}: not a JSON record ({e})")
    return records


def evaluate(record):
    """Adds `pass`: the error is a finite number within the tolerance (a null error or
    tolerance, written for a NaN or infinity, fails)."""
    error, tolerance = record.get("error"), record.get("tolerance")
    ok = (isinstance(error, (int, float)) and isinstance(tolerance, (int, float))
          and math.isfinite(error) and abs(error) <= tolerance)
    record["pass"] = bool(ok)
    return record


def failing(records):
    return [r for r in records if not r["pass"]]


# ---- formatting ----------------------------------------------------------------------------

def fmt_number(x, digits=6):
    if x is None:
        return "NaN"
    if x == 0:
        return "0"
    return f"{x:.{digits}g}"


def measured_digits(record):
    """Enough significant digits of `measured` to show its difference from the reference."""
    ref, val = record.get("reference"), record.get("measured")
    if ref is None or val is None or val == 0:
        return 6
    diff = abs(val - ref)
    if diff == 0:
        return 10
    return int(min(15, max(6, math.ceil(math.log10(abs(val) / diff)) + 2)))


def is_relative(record):
    return record.get("scale_kind") == "relative" or record.get("scale_name") == "reference"


def fmt_error(record, value):
    """An error or a tolerance in the record's units: % when relative (and not at round-off
    level), "% of L" for a custom scale, plain for absolute."""
    if value is None:
        return "NaN"
    if is_relative(record):
        return f"{100 * value:+.3g} %" if abs(value) >= 1e-5 else f"{value:+.2g}"
    if record.get("scale_kind") == "custom":
        name = record.get("scale_name") or "scale"
        return (f"{100 * value:+.3g} % of {name}" if abs(value) >= 1e-5
                else f"{value:+.2g} {name}")
    return f"{value:+.3g}"


def fmt_tolerance(record):
    return fmt_error(record, record.get("tolerance")).lstrip("+")


def markdown_table(records):
    """One generated table: a row per record, in the order the tests ran."""
    sources = {r["source"] for r in records}
    one_source = len(sources) == 1
    lines = ["An empty source or test cell: as in the row above.", ""]
    if one_source:
        lines.append(f"Reference: {records[0]['source']}.")
        lines.append("")
    head = ["check", "reference", "ours", "error", "tolerance", "pass"]
    if not one_source:
        head.insert(2, "source")
    head.append("test")
    lines.append("| " + " | ".join(head) + " |")
    lines.append("|" + "---|" * len(head))
    previous = {}
    for r in records:
        # Source and test are printed where they change (an empty cell: as in the row above).
        source = "" if r["source"] == previous.get("source") else r["source"].replace("|", "\\|")
        test = "" if r["test"] == previous.get("test") else f"`{r['test']}`"
        previous = r
        row = [r["check"], fmt_number(r["reference"], 10),
               fmt_number(r["measured"], measured_digits(r)), fmt_error(r, r["error"]),
               fmt_tolerance(r), "yes" if r["pass"] else "**NO**"]
        row = [cell.replace("|", "\\|") for cell in row]
        if not one_source:
            row.insert(2, source)
        row.append(test)
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def by_table(records):
    tables = {}
    for r in records:
        tables.setdefault(r["table"], []).append(r)
    return tables


# ---- the document --------------------------------------------------------------------------

def marker_ids(text):
    return BEGIN.findall(text)


def regenerate(text, records, summary):
    """`text` with every marked block whose table has records replaced by the generated table,
    the `summary` block by `summary`; blocks without records are kept as they are. Records of
    tables without a marker go to the `unplaced` block, which is appended if missing. Returns
    (text, ids of marked tables without records)."""
    tables = by_table(records)
    ids = marker_ids(text)
    for table_id in ids:
        if ids.count(table_id) > 1:
            raise SystemExit(f"marker {table_id} appears more than once")
        if END.format(table_id) not in text:
            raise SystemExit(f"marker {table_id}: no matching end marker")
    unplaced = [r for t, rs in tables.items() if t not in ids for r in rs]
    if unplaced and "unplaced" not in ids:
        text = (text.rstrip("\n") + "\n\n## Generated checks without a section\n\n"
                "<!-- verification:begin unplaced -->\n<!-- verification:end unplaced -->\n")
        ids.append("unplaced")
    generated = dict((t, markdown_table(rs)) for t, rs in tables.items())
    if unplaced:
        generated["unplaced"] = markdown_table(unplaced)
    generated["summary"] = summary
    empty = []
    for table_id in ids:
        if table_id not in generated:
            empty.append(table_id)
            continue
        begin = f"<!-- verification:begin {table_id} -->"
        start = text.index(begin) + len(begin)
        stop = text.index(END.format(table_id), start)
        text = text[:start] + "\n" + generated[table_id] + "\n" + text[stop:]
    return text, empty


def summary_line(records, binary_ok, filter_name):
    tests = {r["test"] for r in records}
    bad = failing(records)
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    state = ("all within their tolerances" if not bad else f"**{len(bad)} outside their tolerance**")
    if not binary_ok:
        state += "; **the test binary reported failures**"
    run = f"{filter_name} run"
    if os.environ.get("SHELLINDENT_LONG_TESTS", "") not in ("", "0"):
        run += " with SHELLINDENT_LONG_TESTS=1"
    return (f"Generated {when} ({run}): {len(records)} checks recorded by "
            f"{len(tests)} tests, {state}.")


# ---- outputs -------------------------------------------------------------------------------

def write_csv(path, records):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in records:
            w.writerow(r)


def write_json(path, records, binary_ok):
    with open(path, "w") as f:
        json.dump({"binary_passed": binary_ok, "checks": len(records),
                   "failing": len(failing(records)), "records": records}, f, indent=1)
        f.write("\n")


def write_figure(path, records):
    """|error| / tolerance per check on a log scale, grouped (coloured) by table; the line at 1
    is the acceptance limit."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tables = by_table(records)
    fig, ax = plt.subplots(figsize=(11, 4.8))
    floor = 1e-8
    x = 0
    ticks, labels = [], []
    for name, rs in tables.items():
        ratios = []
        for r in rs:
            e, t = r.get("error"), r.get("tolerance")
            if e is None or t is None or not math.isfinite(e):
                ratios.append(1e3)  # a failed (NaN) check: plotted far above the limit
            elif t == 0:
                ratios.append(floor if e == 0 else 1e3)
            else:
                ratios.append(max(abs(e) / t, floor))
        xs = list(range(x, x + len(rs)))
        ax.scatter(xs, ratios, s=12)
        bad = [(xi, yi) for xi, yi, r in zip(xs, ratios, rs) if not r["pass"]]
        if bad:
            ax.scatter(*zip(*bad), s=40, facecolors="none", edgecolors="tab:red")
        ticks.append(x + (len(rs) - 1) / 2)
        labels.append(name)
        x += len(rs) + 3
    ax.axhline(1.0, color="k", lw=1, ls="--")
    ax.set_yscale("log")
    ax.set_ylim(floor / 2, 1e1)
    ax.set_ylabel("|error| / tolerance")
    ax.set_xticks(ticks)
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    ax.set_title(f"shellindent verification: {len(records)} checks "
                 f"({len(failing(records))} outside tolerance); below the dashed line = pass")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ---- running -------------------------------------------------------------------------------

def run_tests(binaries, gtest_filter, records_path):
    """Runs each binary with the recorder on (records appended to one file); returns whether
    all passed."""
    if os.path.exists(records_path):
        os.remove(records_path)
    env = dict(os.environ)
    env[RECORD_VARIABLE] = records_path
    passed = True
    for binary in binaries:
        command = [binary, f"--gtest_filter={gtest_filter}", "--gtest_brief=1"]
        print("running:", " ".join(command), flush=True)
        passed = subprocess.run(command, env=env).returncode == 0 and passed
    return passed


def in_document_order(records, doc_path):
    """The records grouped by table in the order the document's markers name the tables (then
    tables without a marker, in the order they first ran), each table's records in run order: the
    order of the outputs does not depend on which binary or source file holds a test."""
    ids = marker_ids(open(doc_path).read()) if doc_path and os.path.exists(doc_path) else []
    tables = by_table(records)
    order = [t for t in ids if t in tables] + [t for t in tables if t not in ids]
    return [r for t in order for r in tables[t]]


def report(records, binary_ok, out_dir, doc_in, doc_out, figure_paths, filter_name):
    """Writes every output; returns the exit status."""
    records = [evaluate(r) for r in records]
    os.makedirs(out_dir, exist_ok=True)
    write_csv(os.path.join(out_dir, "verification.csv"), records)
    write_json(os.path.join(out_dir, "verification.json"), records, binary_ok)
    for path in figure_paths:
        write_figure(path, records)
    if doc_in:
        with open(doc_in) as f:
            text = f.read()
        text, empty = regenerate(text, records, summary_line(records, binary_ok, filter_name))
        with open(doc_out, "w") as f:
            f.write(text)
        if empty:
            print("marked tables without records in this run (kept as they were):",
                  ", ".join(empty))
    bad = failing(records)
    for r in bad:
        print(f"FAIL {r['table']}: {r['check']}: reference {r['reference']}, measured "
              f"{r['measured']}, error {r['error']}, tolerance {r['tolerance']} ({r['test']})")
    print(f"{len(records)} checks, {len(bad)} outside tolerance; test binary "
          f"{'passed' if binary_ok else 'FAILED'}")
    if not records:
        print("no records: was the binary built with the recorder?")
        return 1
    return 0 if binary_ok and not bad else 1


def self_test():
    """The report fails on a record outside its tolerance, on a NaN record and on a failed
    binary, passes otherwise, and replaces only the marked blocks of a document."""
    good = {"table": "t", "check": "good", "reference": 2.0, "measured": 2.01, "error": 0.005,
            "tolerance": 0.01, "scale_kind": "relative", "scale": 1, "scale_name": "",
            "source": "s", "test": "Suite.Good"}
    bad = dict(good, check="bad", measured=2.1, error=0.05)
    nan = dict(good, check="nan", measured=None, error=None)
    doc = ("# title\n\nprose\n\n<!-- verification:begin t -->\nold row\n"
           "<!-- verification:end t -->\n\nafter\n<!-- verification:begin other -->\nkept\n"
           "<!-- verification:end other -->\n")
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        doc_in = os.path.join(tmp, "in.md")
        with open(doc_in, "w") as f:
            f.write(doc)

        def status(records, binary_ok):
            return report([dict(r) for r in records], binary_ok, tmp, doc_in,
                          os.path.join(tmp, "out.md"), [], "self-test")

        if status([good], True) != 0:
            problems.append("a good record and a passing binary must give 0")
        with open(os.path.join(tmp, "out.md")) as f:
            text = f.read()
        if "old row" in text or "| good |" not in text or "kept" not in text or "prose" not in text:
            problems.append("the marked block must be replaced and everything else kept:\n" + text)
        if status([good, bad], True) == 0:
            problems.append("a record outside its tolerance must fail")
        if status([good, nan], True) == 0:
            problems.append("a NaN record must fail")
        if status([good], False) == 0:
            problems.append("a failing binary must fail")
        if status([], True) == 0:
            problems.append("no records at all must fail")
    for p in problems:
        print("SELF-TEST FAILED:", p)
    print("self-test", "failed" if problems else "passed")
    return 1 if problems else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true",
                        help="fast subset; writes the markdown into --out, never into docs/")
    parser.add_argument("--tests", nargs="+",
                        default=[os.path.join(SOURCE_DIR, "build", "tests", name) for name in
                                 ("shellindent_tests", "continuation_tests", "fitting_tests")],
                        help="the gtest binaries (default build/tests/{shellindent,"
                             "continuation,fitting}_tests)")
    parser.add_argument("--out", default=None,
                        help="output directory (default build/verification)")
    parser.add_argument("--doc", default=os.path.join(SOURCE_DIR, "docs", "verification.md"),
                        help="the report whose marked tables are regenerated")
    parser.add_argument("--records", default=None,
                        help="report from this JSON-lines file instead of running the tests")
    parser.add_argument("--self-test", action="store_true", help="check the report logic")
    args = parser.parse_args()

    if args.self_test:
        return self_test()
    out_dir = args.out or os.path.join(SOURCE_DIR, "build",
                                       "verification_quick" if args.quick else "verification")
    os.makedirs(out_dir, exist_ok=True)
    if args.records:
        records_path, binary_ok = args.records, True
    else:
        missing = [t for t in args.tests if not os.access(t, os.X_OK)]
        if missing:
            print(f"no test binary at {', '.join(missing)} (build first, or pass --tests)")
            return 2
        records_path = os.path.join(out_dir, "records.jsonl")
        binary_ok = run_tests(args.tests, QUICK_FILTER if args.quick else FULL_FILTER,
                              records_path)
    if not os.path.exists(args.doc):
        print(f"no document {args.doc}")
        return 2
    figures = [os.path.join(out_dir, "verification.png")]
    if args.quick:
        doc_out = os.path.join(out_dir, "verification.md")
    else:
        doc_out = args.doc
        figures.append(os.path.join(os.path.dirname(os.path.abspath(args.doc)), "figures",
                                    "verification.png"))
        os.makedirs(os.path.dirname(figures[-1]), exist_ok=True)
    records = in_document_order(read_records(records_path), args.doc)
    return report(records, binary_ok, out_dir, args.doc, doc_out, figures,
                  "quick" if args.quick else "full")


if __name__ == "__main__":
    sys.exit(main())
