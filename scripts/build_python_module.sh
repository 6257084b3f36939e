#!/usr/bin/env bash
# Builds only the Python extension (target _rollspin) for one interpreter,
# in its own CMake tree: what `pip install .` runs (setup.py).
#   bash scripts/build_python_module.sh BUILD_DIR PYTHON
# BUILD_DIR should sit beside build/ (one level under the checkout): ccache
# then sees the same relative paths as build/'s compiles (compiler_cache.sh)
# and hits their objects.
set -euo pipefail
build_dir=$1
python=$2
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
source scripts/jobs.sh
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE="$python" -DROLLSPIN_PYTHON=ON \
      -DROLLSPIN_BUILD_TESTS=OFF -DROLLSPIN_BUILD_BENCHMARKS=OFF "${cache_flags[@]}"
cmake --build "$build_dir" -j"$jobs" --target _rollspin
