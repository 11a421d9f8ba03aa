#!/usr/bin/env bash
# Issue 17 item 3's performance budget, never in ctest: a D7136 plate path (studies/astm_d7136.yaml
# as a quarter model at the default mesh: size_apex 0.5 mm, size_edge 2 mm, refine_radius 13 mm,
# graded) to 5 mm against the paper's cap (bench/cases/cap_default.yaml) to 5 mm with a mesh of
# about as many unknowns, alternated in one loop so that a shared machine's load falls on both
# alike, one thread; CPU (user) and wall seconds, the unknowns, points and work counters from
# path.json. The budget: the plate within 2x the cap's CPU time. Figures go to
# docs/performance.md ("The support frame").
#   bench/pair_fixture.sh BINARY [REPEATS] [CAP_SIZE_APEX_MM]
set -euo pipefail
cd "$(dirname "$0")/.."
BIN="$1"
REPEATS="${2:-2}"
CAP_SIZE="${3:-0.42}"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
cp "$BIN" "$OUT/bin"
sed -e "s/size_apex: 1 mm, size_edge: 4 mm, refine_radius: 10 mm}/symmetry: quarter}/" \
  -e "s/vtu_every: 10/vtu_every: 0/" studies/astm_d7136.yaml >"$OUT/plate.yaml"
sed -e "s/depth_max: 10 mm/depth_max: 5 mm/" -e "s/size_apex: 0.5 mm/size_apex: $CAP_SIZE mm/" \
  bench/cases/cap_default.yaml >"$OUT/cap.yaml"
printf '%-6s %4s %8s %8s %9s %7s %6s %7s\n' case rep user_s wall_s unknowns points iters factor
for rep in $(seq "$REPEATS"); do
  for c in plate cap; do
    dir="$OUT/$c"
    rm -rf "$dir"
    /usr/bin/time -f '%U %e' -o "$OUT/time" env OMP_NUM_THREADS=1 "$OUT/bin" run "$OUT/$c.yaml" \
      --out "$dir" --threads 1 >/dev/null 2>"$OUT/log" ||
      { echo "$c: the run failed ($(tail -n 1 "$OUT/log"))" >&2; exit 1; }
    read -r user wall <"$OUT/time"
    python3 - "$dir/path.json" "$c" "$rep" "$user" "$wall" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
w = j["work"]
iters = int(sum(p.get("iterations", 0) for p in j["points"]))
print(f"{sys.argv[2]:<6} {sys.argv[3]:>4} {float(sys.argv[4]):8.2f} {float(sys.argv[5]):8.2f} "
      f"{int(j['shell_unknowns']):9d} {len(j['points']):7d} {iters:6d} {int(w['factorizations']):7d}")
PY
  done
done
