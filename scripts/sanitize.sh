#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer (a Debug build at -O1, so
# that the numerical tests finish): memory errors, leaks and undefined behaviour anywhere in the
# toolkit fail the run. Not part of CI (it takes far longer than the 20-minute budget on 2 cores:
# docs/hardening.md has the measured time); run it before a release or after touching memory-
# heavy code.
#   scripts/sanitize.sh [BUILD_DIR] [ctest args...]   e.g. scripts/sanitize.sh build-asan -R Case
# The study smoke tests and the verification study are excluded (they time the solver; under the
# sanitizers they only run slower), as is the format check.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build-asan}"
shift || true
FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -O1"
LAUNCHER=()
if command -v ccache >/dev/null; then
  LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"  # clones in other folders share the cache (scripts/setup.sh)
fi
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Debug "${LAUNCHER[@]}" \
  -DCMAKE_CXX_FLAGS="$FLAGS" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
# detect_leaks: on; OpenMP's and OpenBLAS's thread pools live until exit, which LSan accepts.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$BUILD_DIR"
ctest --output-on-failure -j"$(nproc)" -E "^(study_|verification_study|clang_format)" \
  --timeout 3000 "$@"
