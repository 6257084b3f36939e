#!/usr/bin/env bash
# Fresh machine → rollspin's main job on the default scene: installs the
# Debian packages that the build, the program and the Python package need
# (not the tests': scripts/test.sh adds those), builds Release, solves the lollipop, writes its
# orientation timeline to output/ and renders its video, output/lollipop.mp4;
# then installs rollspin to /usr/local (bin/rollspin, the bundled scenes, the
# man page and the bash/zsh completions), so that `rollspin render lollipop
# --still` and `man rollspin` work from any directory;
# and installs the Python package (`import rollspin`, docs/python.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The program, the Python module, the man page and completions (generated from
# the CLI's definitions); the tests are scripts/test.sh's.
bash scripts/build.sh rollspin _rollspin rollspin_cli_docs
./build/rollspin solve scenes/lollipop.toml
./build/rollspin timeline scenes/lollipop.toml -o output/lollipop.csv
./build/rollspin render scenes/lollipop.toml
# Installs to /usr/local: bin/rollspin, share/rollspin/scenes, the man page,
# the completions, and the Python package where Debian's /usr/bin/python3
# finds it (/usr/local/lib/python3.X/dist-packages).
if [ "$(id -u)" -eq 0 ]; then cmake --install build; else sudo cmake --install build; fi
/usr/bin/python3 -c "import rollspin; print('rollspin: the Python package is installed:', rollspin.__file__)"
if command -v mandb >/dev/null; then mandb -q 2>/dev/null || sudo mandb -q 2>/dev/null || true; fi
