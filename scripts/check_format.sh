#!/usr/bin/env bash
# The C++ sources against .clang-format (Debian's clang-format, 14 on
# Debian 12): every tracked .cpp/.hpp/.h/.c in src/, tests/, python/src/ and
# bench/. Lists the files that differ and exits 1; `--fix` rewrites them.
#   bash scripts/check_format.sh [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$format" ]; then
  echo "check_format: clang-format is not installed (apt-get install clang-format, or bash scripts/install-deps.sh --tests)"
  exit 77
fi
mapfile -t files < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' 'tests/*.c' \
                                   'python/src/*.cpp' 'python/src/*.hpp' 'bench/*.cpp' 'bench/*.hpp' 2>/dev/null ||
                     find src tests python/src bench -name '*.[ch]pp' -o -name '*.c')
if [ "${1:-}" = --fix ]; then
  "$format" -i "${files[@]}"
  exit 0
fi
differ=()
for f in "${files[@]}"; do
  "$format" --dry-run -Werror "$f" >/dev/null 2>&1 || differ+=("$f")
done
if [ ${#differ[@]} -gt 0 ]; then
  echo "check_format: ${#differ[@]} of ${#files[@]} files differ from .clang-format (bash scripts/check_format.sh --fix):"
  printf '  %s\n' "${differ[@]}"
  exit 1
fi
echo "check_format: ${#files[@]} files follow .clang-format"
