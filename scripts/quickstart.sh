#!/usr/bin/env bash
# Fresh machine → rollspin's main job on the default scene: installs the
# Debian packages, builds Release, solves the lollipop, writes its
# orientation timeline to output/ and renders its video, output/lollipop.mp4;
# installs the Python package (`import rollspin`, docs/python.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh rollspin _rollspin  # the program and the Python module: the tests are scripts/test.sh's
# The Python package, where Debian's /usr/bin/python3 finds it
# (/usr/local/lib/python3.X/dist-packages), with the bundled scenes.
if [ "$(id -u)" -eq 0 ]; then cmake --install build --component python
else sudo cmake --install build --component python; fi
/usr/bin/python3 -c "import rollspin; print('rollspin: the Python package is installed:', rollspin.__file__)"
./build/rollspin solve scenes/lollipop.toml
./build/rollspin timeline scenes/lollipop.toml -o output/lollipop.csv
./build/rollspin render scenes/lollipop.toml
