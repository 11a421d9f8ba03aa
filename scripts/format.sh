#!/usr/bin/env bash
# Formats every C++ source in place with the project's .clang-format.
set -euo pipefail
cd "$(dirname "$0")/.."
exec cmake -DCLANG_FORMAT="$(command -v clang-format || command -v clang-format-14)" \
  -DSOURCE_DIR="$PWD" -DFIX=ON -P cmake/CheckFormat.cmake
