#!/usr/bin/env bash
# Builds only the Python extension (target _rollspin) for one interpreter,
# in its own CMake tree: what `pip install .` runs (setup.py).
#   bash scripts/build_python_module.sh BUILD_DIR PYTHON
# BUILD_DIR is the extension's own tree (setup.py puts it beside build/),
# kept between runs: a second `pip install .` recompiles what changed.
set -euo pipefail
build_dir=$1
python=$2
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
source scripts/jobs.sh
# A unity build, as scripts/test.sh's: `pip install .` compiles from scratch,
# and in batches that takes about half the compiler's time. (ccache cannot
# lend it build/'s objects: a batch is named by its tree's folder.)
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE="$python" -DROLLSPIN_PYTHON=ON \
      -DROLLSPIN_BUILD_TESTS=OFF -DROLLSPIN_BUILD_BENCHMARKS=OFF -DROLLSPIN_UNITY_BUILD=ON "${cache_flags[@]}"
cmake --build "$build_dir" -j"$jobs" --target _rollspin
