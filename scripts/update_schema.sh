#!/usr/bin/env bash
# Regenerates docs/results.md's column table and studies/result_columns.py from the column table
# (src/analysis/path_columns.cpp) with a built test binary: scripts/update_schema.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
SHELLINDENT_WRITE_SCHEMA=1 "$BUILD_DIR/tests/shellindent_tests" --gtest_filter='ColumnTables.*'
