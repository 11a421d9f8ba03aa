#!/usr/bin/env bash
# Issue 19 item 3 (landing on depth_max) as a paired measurement, never in ctest: two shellindent
# binaries (before / after a change) on the same cases, alternated in one loop so that a shared
# machine's load falls on both alike, one thread; CPU (user) and wall seconds, the points and the
# library's work counters (path.json), and the largest relative change of the force at the depth
# grid (path_grid.csv) between the two. Binaries are copied first, so rebuilding meanwhile does
# not mix versions. Default cases: the built-in paper cap 0-2 mm and 0-10 mm. Figures go to
# docs/performance.md ("Landing on depth_max").
#   bench/pair_landing.sh OLD_BINARY NEW_BINARY [REPEATS] [DEPTH_MAX...]
set -euo pipefail
cd "$(dirname "$0")/.."
OLD="$1"
NEW="$2"
REPEATS="${3:-2}"
shift 3 || shift $#
DEPTHS=("$@")
if ((${#DEPTHS[@]} == 0)); then DEPTHS=(2 10); fi
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
cp "$OLD" "$OUT/old"
cp "$NEW" "$OUT/new"
for d in "${DEPTHS[@]}"; do
  sed "s/depth_max: 10 mm/depth_max: $d mm/" bench/cases/cap_default.yaml >"$OUT/case_$d.yaml"
done
printf '%-8s %-4s %4s %8s %8s %7s %6s %7s %7s\n' depth bin rep user_s wall_s points iters factor residual
for d in "${DEPTHS[@]}"; do
  for rep in $(seq "$REPEATS"); do
    for bin in old new; do
      dir="$OUT/${bin}_$d"
      rm -rf "$dir"
      /usr/bin/time -f '%U %e' -o "$OUT/time" env OMP_NUM_THREADS=1 "$OUT/$bin" run \
        "$OUT/case_$d.yaml" --out "$dir" --threads 1 >/dev/null 2>"$OUT/log" ||
        { echo "$bin $d mm: the run failed ($(tail -n 1 "$OUT/log"))" >&2; exit 1; }
      read -r user wall <"$OUT/time"
      python3 - "$dir/path.json" "$d" "$bin" "$rep" "$user" "$wall" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
w = j["work"]
iters = int(sum(p.get("iterations", 0) for p in j["points"]))
print(f"{sys.argv[2]:<8} {sys.argv[3]:<4} {sys.argv[4]:>4} {float(sys.argv[5]):8.2f} "
      f"{float(sys.argv[6]):8.2f} {len(j['points']):7d} {iters:6d} {int(w['factorizations']):7d} "
      f"{int(w['residuals']):7d}")
PY
    done
  done
  python3 - "$OUT/old_$d/path_grid.csv" "$OUT/new_$d/path_grid.csv" "$d" <<'PY'
import csv, sys
rows = [list(csv.DictReader(open(f))) for f in sys.argv[1:3]]
worst = max(abs(float(b["force_N"]) / float(a["force_N"]) - 1)
            for a, b in zip(*rows) if float(a["force_N"]) > 0)
last = [r[-1] for r in rows]
print(f"{sys.argv[3]} mm: max relative change of force at the depth grid {worst:.2e} "
      f"({len(rows[0])} / {len(rows[1])} rows; last row depth {last[0]['depth_mm']} / "
      f"{last[1]['depth_mm']}, interpolated {last[0]['interpolated']} / {last[1]['interpolated']})")
PY
done
