# Sourced by build.sh, test.sh, sanitize.sh and fuzz.sh: how many compile and
# test jobs run side by side. One a core, but no more than one for every
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
