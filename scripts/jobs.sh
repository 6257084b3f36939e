# Sourced by build.sh, test.sh, sanitize.sh, fuzz.sh and
# build_python_module.sh: how many compile and test jobs run side by side,
# and the build tool. One a core, but no more than one for every
# 3 GiB of memory (a compile of the bigger sources under the sanitizers, or
# an ASan test that renders, stays below that), and at least 2, the reference
# machine's count (2 cores, 24 GiB: 2 jobs). ROLLSPIN_JOBS overrides it.
# Sets `jobs`.
if [ -n "${ROLLSPIN_JOBS:-}" ]; then
  jobs=$ROLLSPIN_JOBS
else
  cores=$(nproc 2>/dev/null || echo 2)
  memory_gib=$(awk '/^MemTotal:/ {print int($2 / 1048576)}' /proc/meminfo 2>/dev/null || echo 6)
  jobs=$((cores < memory_gib / 3 ? cores : memory_gib / 3))
  [ "$jobs" -ge 2 ] || jobs=2
fi
# A new build tree uses Ninja where it is installed (install-deps.sh installs
# it): it starts a target's compiles while the libraries it links are still
# building, and checks what is out of date itself, so the two cores idle
# less (a cold unity Release build: 227 s against about 250 s with
# Makefiles, docs/speed-history.md). A tree keeps the generator it was made
# with: CMake reads it from the tree's cache, and CMAKE_GENERATOR only names
# one for a new tree. CMAKE_GENERATOR set already wins.
if [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja >/dev/null; then
  export CMAKE_GENERATOR=Ninja
fi
