#!/usr/bin/env bash
# Installs what is missing (Debian packages, idempotent) and builds shellindent.
#   scripts/setup.sh [BUILD_DIR] [extra cmake args...]
# Environment: SHELLINDENT_SKIP_APT=1 skips the package check (for machines set up by hand).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR="${1:-build}"
shift || true

# Debian packages of ../shared/docs/toolchain.md. libopenblas0-pthread switches the
# libblas.so.3 alternative: CHOLMOD and UMFPACK measured about 1.6x faster than reference BLAS.
# python3-yaml: studies/sandwich.py reads its case file. pybind11-dev + python3-dev: the Python
# module (python/, docs/python.md), built and tested with python3-numpy; python3-distributed:
# its sweeps on a Dask cluster (shellindent.sweep, tested on a LocalCluster). clang +
# libclang-rt-14-dev: libFuzzer for the fuzz targets (tests/fuzz/, scripts/fuzz.sh). ccache: a
# rebuild (another clone, another branch, CI after a session) compiles only what changed; the
# paths are taken relative to the checkout (CCACHE_BASEDIR), so clones in other folders share it.
PACKAGES=(
  cmake ninja-build g++ pkg-config clang-format
  libsundials-dev libeigen3-dev libsuitesparse-dev libopenblas0-pthread
  libnlopt-cxx-dev libspectra-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy python3-yaml python3-dev pybind11-dev
  python3-distributed python3-meshio
  clang libclang-rt-14-dev
  ccache
)

missing=()
if [[ "${SHELLINDENT_SKIP_APT:-0}" != 1 ]]; then
  for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
fi
if ((${#missing[@]})); then
  echo "setup: installing missing packages: ${missing[*]}" >&2
  SUDO=""
  if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: all required packages are installed" >&2
fi

GENERATOR=()
if command -v ninja >/dev/null; then GENERATOR=(-G Ninja); fi
LAUNCHER=()
if command -v ccache >/dev/null; then
  LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"
fi
if [[ ! -f "$BUILD_DIR/CMakeCache.txt" ]]; then
  cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release "${LAUNCHER[@]}" "$@" >&2
else
  cmake -S . -B "$BUILD_DIR" "${LAUNCHER[@]}" "$@" >/dev/null
fi
cmake --build "$BUILD_DIR" -j"$(nproc)" >&2
echo "setup: built $BUILD_DIR/shellindent" >&2
