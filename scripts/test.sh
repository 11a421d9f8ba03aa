#!/usr/bin/env bash
# Set up (install + build with warnings as errors) and run the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build-test -DSHELLINDENT_WERROR=ON
cd build-test
ctest --output-on-failure -j"$(nproc)"
