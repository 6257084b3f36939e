#!/usr/bin/env bash
# Fresh machine → the whole test suite: installs the Debian packages, builds
# Release, runs every test through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j2
# The GL tests again on the EGL backend (surfaceless, llvmpipe here): auto
# picks OSMesa on this machine, so without this pass EGL would only be
# reached by the tests that force it (about 20 s more).
ROLLSPIN_GL=egl ctest --output-on-failure -j2 -L gl
