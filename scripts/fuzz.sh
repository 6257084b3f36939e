#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan + coverage) into
# build-fuzz/ and runs each for FUZZ_SECONDS (default 60) from a seed corpus:
# scenes/ plus tests/fuzz/seeds/scene (inputs that once crashed it) for the
# scene loader, tests/fuzz/seeds/expression for the expression parser,
# tests/fuzz/seeds/image (small PNG and JPEG files) for the image loaders
# (ball.texture, both sides of `compare`). A crash
# leaves its input in build-fuzz/artifacts/ and fails the script: turn it into
# a regression test, and add the input to the seeds.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
source scripts/compiler_cache.sh
source scripts/jobs.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROLLSPIN_FUZZ=ON \
  -DROLLSPIN_BUILD_TESTS=OFF -DROLLSPIN_BUILD_BENCHMARKS=OFF "${cache_flags[@]}" >/dev/null
cmake --build build-fuzz -j"$jobs" --target fuzz_scene fuzz_expression fuzz_image
mkdir -p build-fuzz/artifacts build-fuzz/corpus/scene build-fuzz/corpus/expression build-fuzz/corpus/image
cp scenes/*.toml tests/fuzz/seeds/scene/* build-fuzz/corpus/scene/
cp tests/fuzz/seeds/expression/* build-fuzz/corpus/expression/
cp tests/fuzz/seeds/image/* build-fuzz/corpus/image/
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
# -timeout=300: a valid but long curve (a uv ellipse over t in [0, 6586],
# ~1000 turns, found by this fuzzer) takes 5.7 s to fit in Release and 136 s
# in this ASan + coverage build; that is work, not a hang. One such input
# took 341 s in CI, so fuzz_scene now bounds the panels a path may fit per
# input (geometry::PanelBudget, 500: some 10 s here); the limit stays for
# any other slow input. libFuzzer checks -max_total_time between inputs, so
# a slow input lengthens the run by at most its own time; a real hang still
# trips the limit.
#
# On a crash, CI's log is all there is: the fuzzer's progress lines are left
# out, the report and stack follow, and last the input itself (gzip + base64:
# `base64 -d | gunzip > crash.bin`, then run the fuzz target on that file).
# The targets run side by side (each fuzzer is one process on one thread),
# all for the same FUZZ_SECONDS: three on two cores share them, so the
# step's wall time stays FUZZ_SECONDS (each target gets about two thirds of
# a core).
targets=(scene expression image)
declare -A pid
for target in "${targets[@]}"; do
  echo "fuzz: $target for ${seconds}s"
  ./build-fuzz/tests/fuzz/fuzz_$target build-fuzz/corpus/$target -max_total_time="$seconds" -timeout=300 \
    -rss_limit_mb=2048 -max_len=4096 -artifact_prefix=build-fuzz/artifacts/$target- -print_final_stats=1 \
    >"build-fuzz/fuzz_$target.log" 2>&1 &
  pid[$target]=$!
done
failed=0
for target in "${targets[@]}"; do
  log=build-fuzz/fuzz_$target.log
  if wait "${pid[$target]}"; then
    echo "fuzz: $target:"
    tail -n 6 "$log"
  else
    status=$?
    echo "fuzz: $target FAILED (exit $status):"
    grep -v -E '^#[0-9]+[[:space:]]' "$log" | tail -n 80
    crash=$(sed -n 's/.*Test unit written to //p' "$log" | tail -n 1)
    if [[ -n $crash && -f $crash ]]; then
      echo "fuzz: input $crash ($(wc -c <"$crash") bytes), gzip | base64:"
      gzip -9nc "$crash" | base64 -w 100
    fi
    failed=$status
  fi
done
exit "$failed"
