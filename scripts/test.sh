#!/usr/bin/env bash
# Fresh machine → the whole test suite: installs the Debian packages, builds
# Release, runs every test through ctest (the Python tests and the example
# notebooks too: ctest's python_tests, pytest with the build's package).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
source scripts/jobs.sh
cd build
# A failed pass is run again, failed tests only, so that their output is the
# last thing printed (CI keeps only the tail of a log), and so that the log
# tells a flaky test (passes the second time) from a broken one.
pass() {
  "$@" --output-on-failure -j"$jobs" && return 0
  echo "test.sh: some tests failed; running those again for their output:" >&2
  "$@" --rerun-failed --output-on-failure -j1 || true
  return 1
}
pass ctest
# The GL tests again on the EGL backend (surfaceless, llvmpipe here): auto
# picks OSMesa on this machine, so without this pass EGL would only be
# reached by the tests that force it. The sweeps (every scene × aspect ×
# frame) take a sample here: this pass checks the backend, and the Release
# pass above has already checked every scene (tests/support/sweep.hpp).
ROLLSPIN_GL=egl ROLLSPIN_TEST_SWEEP=sample pass ctest -L gl
