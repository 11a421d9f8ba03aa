#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz/ with clang (address + undefined sanitizers) and
# runs each for SECONDS seconds (default 60) on a copy of its corpus tests/fuzz/corpus/<target>/.
#   scripts/fuzz.sh [SECONDS] [BUILD_DIR]        e.g. scripts/fuzz.sh 600 for the 10-minute runs
# A crash, a leak, a timeout (10 s per input) or an exception other than si::Error fails the run
# (exit 1) and leaves the input as BUILD_DIR/crash-* (add it to the corpus once fixed: the test
# suite replays the corpus, tests/io/test_fuzz_corpus.cpp). Inputs that found new coverage are
# kept in BUILD_DIR/corpus/<target>/; to grow the repository's corpus, merge them into it with
#   BUILD_DIR/tests/fuzz/fuzz_<target> -merge=1 tests/fuzz/corpus/<target> BUILD_DIR/corpus/<target>
# and keep it small (a few hundred files). Needs clang and libclang-rt-14-dev (scripts/setup.sh
# installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-60}"
BUILD_DIR="${2:-build-fuzz}"
CXX_FUZZ="$(command -v clang++ || command -v clang++-14)"
LAUNCHER=()
if command -v ccache >/dev/null; then
  LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"  # clones in other folders share the cache (scripts/setup.sh)
fi
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER="$CXX_FUZZ" "${LAUNCHER[@]}" \
  -DSHELLINDENT_FUZZ=ON -DSHELLINDENT_TESTS=OFF >/dev/null
cmake --build "$BUILD_DIR" --target fuzz_case_file fuzz_layup -j"$(nproc)"

status=0
for target in case_file layup; do
  work="$BUILD_DIR/corpus/$target"
  mkdir -p "$work"
  cp -n tests/fuzz/corpus/$target/* "$work/" 2>/dev/null || true
  echo "fuzz: $target for $SECONDS_EACH s" >&2
  # -rss_limit_mb: a reader that allocates without bound is a finding, not a machine to swap.
  if ! (cd "$BUILD_DIR" && "./tests/fuzz/fuzz_$target" -max_total_time="$SECONDS_EACH" -timeout=10 \
          -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 "corpus/$target" \
          2>"fuzz_$target.log"); then
    status=1
    echo "fuzz: $target FAILED (see $BUILD_DIR/fuzz_$target.log and $BUILD_DIR/crash-*)" >&2
  fi
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)" \
    "$BUILD_DIR/fuzz_$target.log" >&2 || true
done
exit $status
