#!/usr/bin/env bash
# Issue 5's path targets as timed CLI runs (never in ctest): the paper's cap 0-10 mm by
# pseudo-arclength at ~1e4 unknowns (target < 15 s on 2 cores) and ~1e5 (target < 3 min), and
# the main job (the built-in quarter cap). Prints wall and CPU time, peak memory and the points.
#   bench/time_paths.sh [BUILD_DIR] [CASE...]     (default: build, bench/cases/cap_path_*.yaml)
# Run it on an idle machine: the figures go to docs/performance.md.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
shift || true
CASES=("$@")
if ((${#CASES[@]} == 0)); then CASES=(bench/cases/cap_path_1e4.yaml bench/cases/cap_path_1e5.yaml default); fi
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT

printf '%-34s %10s %10s %10s %8s  %s\n' case wall_s user_s rss_MB points load_avg
for c in "${CASES[@]}"; do
  dir="$OUT/$(basename "$c" .yaml)"
  args=(run --threads 2 --out "$dir")
  [[ "$c" != default ]] && args+=("$c")
  /usr/bin/time -f '%e %U %M' -o "$OUT/time" "$BUILD/shellindent" "${args[@]}" >/dev/null 2>"$OUT/log" ||
    { echo "$c: the run failed (log: $(tail -n 2 "$OUT/log"))" >&2; exit 1; }
  read -r wall user rss <"$OUT/time"
  points=$(($(wc -l <"$dir/path.csv") - 1))
  printf '%-34s %10.1f %10.1f %10.0f %8d  %s\n' "$c" "$wall" "$user" "$((rss / 1024))" "$points" \
    "$(cut -d' ' -f1-3 /proc/loadavg)"
done
