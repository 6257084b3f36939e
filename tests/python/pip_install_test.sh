#!/usr/bin/env bash
# `pip install .` as docs/python.md gives it, for a user whose python3 is a
# virtual environment's: a copy of the checkout (as a fresh clone has it), a
# venv made by PYTHON with the system's packages, pip install
# --no-build-isolation (nothing downloaded), then, from another folder, the
# venv's python imports the installed package, finds a bundled scene by name
# inside it and solves it as the CLI does. The extension's CMake tree stays
# in WORK between runs (the copy is refreshed): a rerun configures nothing.
#   pip_install_test.sh SOURCE_DIR WORK PYTHON ROLLSPIN_BINARY
set -euo pipefail
source_dir=$1 work=$2 python=$3 cli=$4
clone=$work/clone venv=$work/venv
mkdir -p "$clone"
# The checkout's files (not its build trees, .git or web/node_modules), over
# the last run's copy; the npm packages as install-deps.sh leaves them (the
# viewer's bundle is built with their esbuild).
tar -C "$source_dir" --exclude='./build*' --exclude=./.git --exclude=./web/node_modules --exclude=./output \
    --exclude=./site --exclude='*/__pycache__' -cf - . | tar -C "$clone" -xf -
if [ -d "$source_dir/web/node_modules" ]; then ln -sfn "$(realpath "$source_dir/web/node_modules")" "$clone/web/node_modules"; fi
rm -rf "$venv"
"$python" -m venv --system-site-packages "$venv"
(cd "$clone" && "$venv/bin/pip" install --quiet --no-build-isolation --no-index .)
# The venv's interpreter built it, and nothing of setuptools' was left in the checkout.
grep -qE "^Python_EXECUTABLE:[A-Z]+=$venv/bin/python3?$" \
  "$clone"/build-python-*/CMakeCache.txt || { echo "FAIL: the extension was not built for $venv/bin/python"; exit 1; }
leftovers=$(cd "$clone" && ls -d build lib ./*.egg-info python/*.egg-info 2>/dev/null || true)
[ -z "$leftovers" ] || { echo "FAIL: pip left $leftovers in the checkout"; exit 1; }
expected=$(cd "$work" && "$cli" solve lollipop --json)
cd "$work"
"$venv/bin/python" - "$venv" "$expected" <<'PY'
import json, os, sys
import rollspin
venv, expected = os.path.realpath(sys.argv[1]), json.loads(sys.argv[2])
where = os.path.realpath(rollspin.__file__)
assert where.startswith(venv + os.sep), f"imported {where}, not the venv's package"
first = rollspin.scene_dirs()[0]
assert str(first).startswith(venv) and (first / "lollipop.toml").is_file(), f"bundled scenes: {rollspin.scene_dirs()}"
solution = rollspin.load("lollipop").solve()
assert solution.quaternion.tolist() == expected["quaternion"], (solution.quaternion, expected["quaternion"])
print(f"pip install: imported {where}; lollipop solved as the CLI solves it: {solution!r}")
PY
