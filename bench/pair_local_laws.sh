#!/usr/bin/env bash
# Issue 20's cost target as a paired measurement (never in ctest): a path with each local contact
# law against the same path with `local: none`, alternated in one loop so that a shared machine's
# load falls on both alike; CPU seconds (user) are the measure. The case is a case file whose
# `contact:` line is a flow map without `local` (default: studies/cap_00_path.yaml, the paper cap
# 0-10 mm, full model, 1 mm apex mesh). The binary is copied first, so rebuilding meanwhile does
# not mix versions. Figures go to docs/performance.md ("Local contact laws").
#   bench/pair_local_laws.sh [BUILD_DIR] [CASE] [REPEATS] [SET]
# SET `nonlinear` (default): the laws of the total force on the case as written; `linear`: the
# case with `kinematics: linear`, the linear laws (vam, the elastic face with and without the
# F-bar rows) against `none` and `none` with the F-bar rows, all on the linear fast path.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
CASE="${2:-studies/cap_00_path.yaml}"
REPEATS="${3:-2}"
SET="${4:-nonlinear}"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
cp "$BUILD/shellindent" "$OUT/shellindent"
if [[ "$SET" == linear ]]; then
  LAWS=("none" "none, fbar: true" "vam" "anisotropic, local_support: shell"
        "anisotropic, local_support: shell, fbar: true")
  KINEMATICS=linear
else
  LAWS=("none" "hertz" "yang_sun" "anisotropic, local_support: bonded" "anisotropic, local_support: plate"
        "anisotropic, local_support: shell")
  KINEMATICS=""
fi
for i in "${!LAWS[@]}"; do
  sed "s/^\(contact: {.*\)}/\1, local: ${LAWS[$i]}}/" "$CASE" > "$OUT/case_$i.yaml"
  [[ -n "$KINEMATICS" ]] && sed -i "s/^kinematics: .*/kinematics: $KINEMATICS/" "$OUT/case_$i.yaml"
  grep -q "local: ${LAWS[$i]}" "$OUT/case_$i.yaml" || { echo "no contact flow map in $CASE" >&2; exit 2; }
done
printf '%-40s %4s %8s %8s %7s %6s\n' law rep user_s ratio points iters
for rep in $(seq "$REPEATS"); do
  base=""
  for i in "${!LAWS[@]}"; do
    dir="$OUT/run_$i"
    /usr/bin/time -f '%U' -o "$OUT/time" env OMP_NUM_THREADS=1 "$OUT/shellindent" run \
      "$OUT/case_$i.yaml" --out "$dir" --threads 1 >/dev/null 2>"$OUT/log" ||
      { echo "${LAWS[$i]}: the run failed ($(tail -n 1 "$OUT/log"))" >&2; exit 1; }
    user=$(cat "$OUT/time")
    [[ -z "$base" ]] && base=$user
    points=$(($(wc -l <"$dir/path.csv") - 1))
    iters=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == "iterations") k = c }
                     NR > 1 { s += $k } END { print s }' "$dir/path.csv")
    printf '%-40s %4d %8.2f %8.2f %7d %6d\n' "${LAWS[$i]}" "$rep" "$user" \
      "$(awk -v a="$user" -v b="$base" 'BEGIN { print a / b }')" "$points" "$iters"
  done
done
