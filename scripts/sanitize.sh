#!/usr/bin/env bash
# Builds rollspin and the unit-test programs with AddressSanitizer +
# UndefinedBehaviorSanitizer into build-asan/ and runs the unit and fault
# tests under them (every test ran in the Release pass, scripts/test.sh; see
# "What this pass runs" below).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
source scripts/jobs.sh
# src/ optimised as a release is (-O2: the suite's numerics stay fast; the
# test programs at -O1, see tests/CMakeLists.txt), with the asserts on: this
# pass is where the broken-invariant checks run, as a release build compiles
# them out (NDEBUG).
#
# Clang builds this pass (GCC 12 builds the release): with ASan + UBSan it
# compiles rollspin in about half GCC's time (src/draw's largest batch: 19 s
# against 43 s; the whole pass's build: docs/speed-history.md, ci15), the
# tests run as fast, and a second compiler reads every file. The fuzz build
# (scripts/fuzz.sh) is Clang's too. A build-asan/ made with GCC before
# starts afresh: CMake would drop its cache itself, but then configure the
# tree again without the options given here (a plain build, no sanitizers).
if [ -f build-asan/CMakeCache.txt ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang++$' build-asan/CMakeCache.txt; then
  rm -rf build-asan/CMakeCache.txt build-asan/CMakeFiles
fi
cmake -S . -B build-asan -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2" -DROLLSPIN_SANITIZE=ON -DROLLSPIN_BUILD_BENCHMARKS=OFF "${cache_flags[@]}" >/dev/null
cmake --build build-asan -j"$jobs" --target rollspin_unit_tests
# Mesa's llvmpipe keeps some allocations for the life of the process (its
# LLVM JIT and screen caches): suppress leaks from inside the GL stack only.
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"
# intercept_tls_get_addr=0: the sanitizer runtime's __tls_get_addr
# interceptor (GCC's up to 13, and LLVM 14's, which GCC's copies) can
# mistake a dynamic TLS block (Mesa and LLVM, loaded with dlopen, have
# them) for a pre-2.25 glibc header when it happens to start at
# a certain page offset, and LeakSanitizer's tracer then segfaults at exit
# ("Tracer caught signal 11", a rare flake seen once in CI on a GL test that
# had passed). Leaks are still checked; dynamic TLS is just not scanned.
#
# quarantine_size_mb=64 (default 256) and malloc_context_size=10 (default
# 30): a freed block waits in a 64 MiB quarantine before reuse, and a report
# shows ten frames of where a block was allocated. With the defaults each
# process kept faulting in fresh pages (a still at 192x108 spent a quarter of
# its time in page faults and zeroing) and recording deep stacks; these
# settings take about an eighth off the pass, and a use after free is still
# caught while the block is among the last 64 MiB freed.
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:intercept_tls_get_addr=0:quarantine_size_mb=64:malloc_context_size=10"
# Mesa's EGL driver (swrast_dri.so) is dlopen'ed by libEGL_mesa and
# dlclose'd again before the leak check: an ASan build of rollspin keeps it
# mapped itself (render/egl_context.cpp, keepDriversMappedForLeakCheck), so
# the suppressions for the GL stack apply to EGL as to OSMesa. (Preloading
# the driver into every process did the same at about 0.1 s of CPU each,
# ffprobe and pdftotext included: a quarter of the process-heavy tests.)
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The sweep tests (every scene × aspect × frame; the fault matrix's every
# command × fault) visit a deterministic quarter of their data here: this
# pass looks for memory and undefined-behaviour errors along the code paths,
# which the sample reaches, at a quarter of the cost (tests/support/sweep.hpp);
# the Release pass checks every datum.
export ROLLSPIN_TEST_SWEEP=sample
# The GL tests render through EGL here (surfaceless, llvmpipe without a GPU):
# the Release pass has run them on `auto`, which is OSMesa on a machine
# without one, so the two passes together reach both backends. (They were a
# separate Release pass, 94 s of .ci/run; here they cost nothing extra.)
export ROLLSPIN_GL=egl
# One rasterizer thread per GL test, as in scripts/test.sh.
export LP_NUM_THREADS=${LP_NUM_THREADS:-0}
cd build-asan
# ctest starts the longest tests first when it knows their times; a fresh
# build-asan has none, so the Release pass's measured times (same test names,
# in proportion) order this pass too, where the COST hints of
# tests/CMakeLists.txt reach only some tests (ctest replaces the file with its
# own measurements as it runs).
if [ -f ../build/Testing/Temporary/CTestCostData.txt ] && [ ! -f Testing/Temporary/CTestCostData.txt ]; then
  mkdir -p Testing/Temporary
  cp ../build/Testing/Temporary/CTestCostData.txt Testing/Temporary/
fi
# What this pass runs: the label-`unit` tests (every module's own tests in
# process, the CLI's commands, messages and exit codes through the
# sanitized binary) and the fault tests (full disks, signals, limits: every
# writing command under each). Those are where a memory or UB error hides:
# parsers, files, buffers, error paths. The Release pass (scripts/test.sh)
# has run every test already; the ones left out here are the gl tests
# (rendering sweeps: every scene, size and backend; 4-6x slower under ASan
# for the same code paths the fault tests render through), python (not
# built here: an instrumented module cannot load into an uninstrumented
# interpreter), the tool-checked ones (cluster, recipes,
# docs, browser, Blender, glTF validator, pip install), which test scripts
# and readers, not our memory, and the checks of the source tree (label
# source: format, file and function lengths, test layout, key spellings). Together the passes took 42 min in CI; the
# whole suite under ASan was over half of it (docs/speed-history.md, CI).
ctest --output-on-failure -j"$jobs" -L 'unit|faults'
