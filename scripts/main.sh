#!/usr/bin/env bash
# The main job: set up (install + build), then run shellindent on its built-in default.
# Until the shell solver lands this is the section analysis of the source paper's lay-ups
# ([theta/-theta]2S, theta = 0..90 by 15, and [0/90]2S): a table on stdout, JSON/CSV and a
# PNG figure in results/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build
OUT="${1:-results}"
build/shellindent section --paper --out "$OUT"
/usr/bin/python3 studies/plot_paper_sections.py "$OUT/paper_sections.csv" "$OUT/paper_sections.png"
