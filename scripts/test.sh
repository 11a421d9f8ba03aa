#!/usr/bin/env bash
# Set up (install + build with warnings as errors) and run the whole test suite with ctest, then
# a short fuzz run of the case-file reader and the lay-up parser (60 s each, clang's libFuzzer
# with the address and undefined sanitizers; docs/hardening.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build-test -DSHELLINDENT_WERROR=ON
(cd build-test && ctest --output-on-failure -j"$(nproc)")
bash scripts/fuzz.sh "${SHELLINDENT_FUZZ_SECONDS:-60}" build-fuzz
