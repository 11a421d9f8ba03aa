#!/usr/bin/env bash
# The main job: set up (install + build), then run shellindent on its built-in default, the
# source paper's cap: a clamped carbon/epoxy spherical cap ([0/0]2S, base radius 25 mm,
# R = 80.9 mm, t = 3.8 mm) indented by a rigid 12.7 mm sphere from 0 to 10 mm, geometrically
# nonlinear, by pseudo-arclength continuation in the depth. Prints the force-depth table,
# writes results/paper_cap/ (path.csv, path.json, events.json, VTU files for ParaView) and the
# figure results/paper_cap/force_depth.png. The run takes about 11 s after the build (measured
# 2026-11-27: 11.2 s of CPU time, 10.0 s wall, with the nonlinearity onset located; README.md
# states the same, studies/test_study_scripts.py checks that they agree).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build
OUT="${1:-results}"
build/shellindent run --out "$OUT/paper_cap"
/usr/bin/python3 studies/plot_path.py "$OUT/paper_cap" "$OUT/paper_cap/force_depth.png"
