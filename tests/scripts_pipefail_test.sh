#!/usr/bin/env bash
# Under `set -o pipefail` a pipeline whose reader stops before its writer is
# done (grep -q, grep -m, head, an awk that exits, sed …q) fails with 141
# whenever the writer is still writing: SIGPIPE, "depending on timing", as
# scripts/device_bundle.sh did with `ldconfig -p | awk '… exit'`.
#   bash tests/scripts_pipefail_test.sh SOURCE_DIR
# 1. No script that sets pipefail (scripts/, tests/, bench/) has such a reader
#    after a pipe. 2. device_bundle.sh's ldconfig lookup, run as the script
#    defines it, under pipefail with a large fake ldconfig cache, exits 0 with
#    the right path (the old `awk '… exit'` exits 141 here every time).
set -uo pipefail
src=${1:?usage: scripts_pipefail_test.sh SOURCE_DIR}
passed=0 failed=0
pass() { passed=$((passed + 1)); echo "PASS $1"; }
fail() { failed=$((failed + 1)); echo "FAIL $1: $2"; }

# 1. The static check: a pipe, then a reader that stops early.
early='(^|[^|])\|[[:space:]]*(grep[[:space:]]+(-[a-zA-Z]*[qm]|--quiet|--max-count)|head([[:space:]]|$)|awk[^|]*[^a-z_]exit[^a-z_]|sed[[:space:]]+(-n[[:space:]]+)?.?[0-9]*q)'
mapfile -t scripts < <(cd "$src" && grep -rlE --include='*.sh' --include='*.sbatch' 'set -[a-z]*o pipefail|set -o pipefail' scripts tests bench)
[ "${#scripts[@]}" -ge 10 ] || fail "script scan" "found only ${#scripts[@]} scripts with pipefail under $src"
for script in "${scripts[@]}"; do
  hits=$(grep -nE "$early" "$src/$script" | grep -vE '^[0-9]+:[[:space:]]*#')
  if [ -n "$hits" ]; then fail "$script" "a reader that stops early after a pipe: $hits"; else pass "$script"; fi
done

# 2. The lookup as device_bundle.sh defines it, against a 20 MB fake cache
#    whose match is on its second line (so the reader is done long before
#    the writer: without the fix, SIGPIPE every time).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  echo "$((200000 + 1)) libs found in cache \`/etc/ld.so.cache'"
  printf '\tlibavcodec.so.59 (libc6,x86-64) => /usr/lib/x86_64-linux-gnu/libavcodec.so.59\n'
  for _ in $(seq 1 2000); do printf '\tlibfiller%s.so.1 (libc6,x86-64) => /usr/lib/x86_64-linux-gnu/libfiller.so.1\n' {1..100}; done
} >"$work/cache.txt"
mkdir "$work/bin"
printf '#!/bin/sh\nexec cat "%s"\n' "$work/cache.txt" >"$work/bin/ldconfig"
chmod +x "$work/bin/ldconfig"
definition=$(grep -E '^libraryPathOf\(\) \{.*\}$' "$src/scripts/device_bundle.sh")
if [ -z "$definition" ]; then
  fail "device_bundle lookup" "scripts/device_bundle.sh defines no libraryPathOf() (the ldconfig lookup moved?)"
else
  out=$(PATH="$work/bin:$PATH" bash -c "set -euo pipefail; $definition; lib=\$(libraryPathOf libavcodec.so.59); echo \"\$lib\"")
  code=$?
  if [ "$code" = 0 ] && [ "$out" = /usr/lib/x86_64-linux-gnu/libavcodec.so.59 ]; then
    pass "device_bundle lookup under pipefail"
  else
    fail "device_bundle lookup under pipefail" "exit $code, printed '$out'"
  fi
fi
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
