#!/usr/bin/env bash
# The quick start installs what the build, the program and the Python
# package need, and nothing that only the tests need; `--tests` adds those
# (scripts/install-deps.sh, issue 54 cut 12). Reads the lists with --list:
# installs nothing. Also the npm side: the build's packages (three, esbuild)
# are "dependencies" that `npm ci --omit=dev` installs, the tests' are dev.
#   bash tests/install_deps_test.sh SOURCE_DIR
set -uo pipefail
src=${1:?usage: install_deps_test.sh SOURCE_DIR}
passed=0 failed=0
pass() { passed=$((passed + 1)); echo "PASS $1"; }
fail() { failed=$((failed + 1)); echo "FAIL $1: $2"; }

core=$(bash "$src/scripts/install-deps.sh" --list) || fail "--list" "exit $?"
all=$(bash "$src/scripts/install-deps.sh" --tests --list) || fail "--tests --list" "exit $?"
has() { grep -qxF -- "$2" <<<"$1"; }
for p in libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev slurm-wlm munge mkdocs python3-pytest \
         python3-nbclient chromium; do
  if has "$core" "$p"; then fail "quick start without $p" "the quick start installs $p, which only the tests need"
  else pass "quick start without $p"; fi
  if has "$all" "$p"; then pass "--tests has $p"; else fail "--tests has $p" "missing"; fi
done
# What the build and the program need at run time. gnuplot: `report errors`
# runs it for its plot (src/report), so it is not a test-only package.
grep -rq '"gnuplot ' "$src/src/report" || fail "report runs gnuplot" "src/report no longer runs gnuplot: move gnuplot-nox to the tests' list"
for p in cmake ninja-build build-essential libosmesa6-dev libavcodec-dev libcairo2-dev gnuplot-nox pybind11-dev python3-dev \
         python3-numpy python3-venv; do
  if has "$core" "$p"; then pass "quick start has $p"; else fail "quick start has $p" "missing"; fi
done
while read -r p; do
  has "$all" "$p" || fail "--tests keeps the quick start's" "$p is missing from --tests"
done <<<"$core"
if bash "$src/scripts/install-deps.sh" --bogus >/dev/null 2>&1; then fail "unknown option" "accepted"; else pass "unknown option"; fi

# npm: dependencies for the build, devDependencies for the tests, and the
# lock file saying the same (what npm ci --omit=dev reads).
python3 - "$src/web" <<'PY' && pass "npm build/test split" || fail "npm build/test split" "see above"
import json, sys
web = sys.argv[1]
pkg = json.load(open(f"{web}/package.json"))
lock = json.load(open(f"{web}/package-lock.json"))
ok = True
def check(cond, what):
    global ok
    if not cond:
        print("  " + what); ok = False
for name in ("three", "esbuild"):
    check(name in pkg.get("dependencies", {}), f"{name} is not in package.json's dependencies")
    check(not lock["packages"].get(f"node_modules/{name}", {}).get("dev"), f"the lock file marks {name} dev")
for name in ("playwright-core", "gltf-validator"):
    check(name in pkg.get("devDependencies", {}), f"{name} is not in package.json's devDependencies")
    check(lock["packages"].get(f"node_modules/{name}", {}).get("dev"), f"the lock file does not mark {name} dev")
check(lock["packages"][""].get("dependencies") == pkg.get("dependencies"), "the lock file's root dependencies differ from package.json's")
sys.exit(0 if ok else 1)
PY
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
