#!/usr/bin/env bash
# The faults found by trying rollspin as a new user would (issue 45), one case
# each, through the real binary:
#   webm-full-disk    WebM onto a full disk fails cleanly (exit 1, nothing
#                     left), no SIGSEGV from a second trailer
#   two-sigints       two SIGINTs 5 ms apart (timeout -s INT: the process,
#                     then its group) are one interruption: the partial stays
#   gif-shard         --shard with GIF is refused up front, naming what works
#   partial-tags      an interrupted MP4/WebM says the frames it holds
#   compare-*         which threshold failed, sizes on a mismatch, 0.6 as typed
#   report-folder-*   `report errors -o DIR` leaves no empty DIR it created
#   set-*, memory-*   the out-of-range number, the list syntax, the way out
#                     of ulimit -v (refused up front; many threads never crash)
# Usage: disk_signal_limit_faults_test.sh ROLLSPIN WORKDIR (run by ctest, label faults).
set -uo pipefail
source "$(dirname "$0")/fault_support.sh"
fault_test_setup "$@"

# --- WebM on a full disk (and the other videos, which already failed cleanly)
disk=$work/full
if mount_small "$disk" 100k; then
  for ext in webm mp4 mov gif; do
    "$rollspin" render "$scenes/lollipop.toml" --width 640 --height 360 --set animation.duration=3 --quiet \
      -o "$disk/x.$ext" 2>"$work/full.$ext.err"
    code=$?
    if [ $code -eq 1 ] && [ -z "$(left_in "$disk")" ] && grep -q 'rollspin: error' "$work/full.$ext.err"; then
      pass "full-disk-$ext"
    else
      fail "full-disk-$ext" "exit $code, left: $(left_in "$disk"); $(tail -n 3 "$work/full.$ext.err")"
    fi
  done
  umount_small "$disk"
else
  skip full-disk "cannot mount a tmpfs here (needs root: uid $(id -u))"
fi

# --- Two SIGINTs 5 ms apart, as `timeout -s INT` sends them (child, then group)
for ext in mp4 mov; do
  dir=$work/twice-$ext
  mkdir -p "$dir"
  "$rollspin" render "$scenes/lollipop.toml" --width 640 --height 360 --set animation.duration=100 \
    -o "$dir/m.$ext" 2>"$dir/stderr" &
  pid=$!
  if ! wait_for "has_file_over '$dir' '.m.$ext.' 8192"; then
    kill -KILL $pid; wait $pid
    fail "two-sigints-$ext" "no frames reached the file: $(tail -n 3 "$dir/stderr")"
    continue
  fi
  kill -INT $pid; sleep_ms 5; kill -INT $pid
  wait $pid
  code=$?
  if [ $code -eq 130 ] && [ "$(left_in "$dir")" = "m.partial.$ext " ] && grep -q 'shorter, playable' "$dir/stderr" &&
     [ "$(video_frames "$dir/m.partial.$ext")" -gt 0 ]; then
    pass "two-sigints-$ext"
  else
    fail "two-sigints-$ext" "exit $code, left: $(left_in "$dir"); $(tr '\n' ' ' <"$dir/stderr" | tail -c 300)"
  fi
done

# --- GIF shards: refused before any frame, naming what works
dir=$work/gif-shard
mkdir -p "$dir"
"$rollspin" render "$scenes/lollipop.toml" "${small[@]}" --set animation.duration=1 --shard 1/2 --quiet \
  -o "$dir/g.gif" 2>"$dir/stderr"
code=$?
if [ $code -eq 2 ] && [ -z "$(left_in "$dir")" ] && grep -q -- '--shard' "$dir/stderr" && grep -q '\.mp4' "$dir/stderr"; then
  pass gif-shard
else
  fail gif-shard "exit $code, left: $(left_in "$dir"); $(cat "$dir/stderr")"
fi

# --- An interrupted partial's tags say the frames it holds
for ext in mp4 webm mov; do
  dir=$work/tags-$ext
  mkdir -p "$dir"
  "$rollspin" render "$scenes/lollipop.toml" "${small[@]}" --set animation.duration=100 -o "$dir/p.$ext" 2>"$dir/stderr" &
  pid=$!
  if ! wait_for "has_file_over '$dir' '.p.$ext.' 16384"; then
    kill -KILL $pid; wait $pid
    fail "partial-tags-$ext" "no frames reached the file"
    continue
  fi
  kill -INT $pid
  wait $pid
  frames=$(video_frames "$dir/p.partial.$ext" 2>/dev/null) tag=$(frames_tag "$dir/p.partial.$ext" 2>/dev/null)
  if [ -n "$frames" ] && [ "$frames" -gt 0 ] && [ "$tag" = "0-$((frames - 1))" ]; then
    pass "partial-tags-$ext"
  else
    fail "partial-tags-$ext" "holds ${frames:-?} frames, its tag says '${tag}'"
  fi
done

# --- compare: which threshold failed; sizes on a mismatch; thresholds as typed
dir=$work/compare
mkdir -p "$dir"
"$rollspin" render "$scenes/lollipop.toml" --still "${small[@]}" --at fraction=0.3 --quiet -o "$dir/a.png" &&
  "$rollspin" render "$scenes/lollipop.toml" --still "${small[@]}" --at fraction=0.5 --quiet -o "$dir/b.png" &&
  "$rollspin" render "$scenes/lollipop.toml" --still --set render.width=120 --set render.height=90 --quiet \
    -o "$dir/c.png" || fail compare "could not render the stills"
"$rollspin" compare "$dir/a.png" "$dir/b.png" --max-delta 0.6 --min-ssim 0.9999 --json >"$dir/json" 2>/dev/null
code=$?
if [ $code -eq 1 ] && grep -q '"max_delta": 0.6,' "$dir/json" && grep -q '"failed": \["max_delta", "min_ssim"\]' "$dir/json"; then
  pass compare-json-names-the-threshold
else
  fail compare-json-names-the-threshold "exit $code: $(tr '\n' ' ' <"$dir/json")"
fi
"$rollspin" compare "$dir/a.png" "$dir/b.png" --max-delta 0.6 >"$dir/text" 2>/dev/null
if grep -q '^DIFFERENT: --max-delta 0.6: .* pixels differ by more than 0.6 levels' "$dir/text" && ! grep -q 0.5999 "$dir/text"; then
  pass compare-text-names-the-threshold
else
  fail compare-text-names-the-threshold "$(tr '\n' ' ' <"$dir/text")"
fi
"$rollspin" compare "$dir/a.png" "$dir/c.png" --json >"$dir/size" 2>/dev/null
code=$?
if [ $code -eq 1 ] && grep -q '"max_delta": null' "$dir/size" && grep -q '"differing_pixels": null' "$dir/size" &&
   grep -q '"failed": \["size"\]' "$dir/size" && grep -q '160x90 vs 120x90' "$dir/size"; then
  pass compare-size-mismatch
else
  fail compare-size-mismatch "exit $code: $(tr '\n' ' ' <"$dir/size")"
fi

# --- report errors -o DIR: no empty DIR left when it fails or is interrupted
report=(report errors "$scenes/lollipop.toml")
disk=$work/report-full
if mount_small "$disk" 16k; then
  "$rollspin" "${report[@]}" -o "$disk/new/report" >/dev/null 2>"$work/report-full.err"
  code=$?
  if [ $code -eq 1 ] && [ -z "$(left_in "$disk")" ]; then
    pass report-folder-full-disk
  else
    fail report-folder-full-disk "exit $code, left: $(left_in "$disk"); $(tail -n 2 "$work/report-full.err")"
  fi
  umount_small "$disk"
else
  skip report-folder-full-disk "cannot mount a tmpfs here (needs root: uid $(id -u))"
fi
dir=$work/report-int
mkdir -p "$dir"
"$rollspin" "${report[@]}" -o "$dir/new/report" >/dev/null 2>"$dir/stderr" &
pid=$!
wait_for "grep -q 'rollspin: ' '$dir/stderr'" 60
kill -INT $pid
wait $pid
code=$?
if [ $code -eq 130 ] && [ -z "$(left_in "$dir")" ]; then
  pass report-folder-interrupted
elif [ $code -eq 0 ]; then
  skip report-folder-interrupted "the report finished before the signal"
else
  fail report-folder-interrupted "exit $code, left: $(left_in "$dir")"
fi

# --- --set messages and the memory refusal
dir=$work/messages
mkdir -p "$dir"
"$rollspin" render "$scenes/lollipop.toml" --still --set path.radius=1e400 -o "$dir/x.png" 2>"$dir/range"
code=$?
if [ $code -eq 2 ] && grep -q 'out of range' "$dir/range" && ! grep -q 'got string' "$dir/range"; then
  pass set-number-out-of-range
else
  fail set-number-out-of-range "exit $code: $(cat "$dir/range")"
fi
"$rollspin" render "$scenes/lollipop.toml" --still --set labels.facts=turns -o "$dir/x.png" 2>"$dir/facts"
code=$?
if [ $code -eq 2 ] && grep -qF -- "--set 'labels.facts=[\"turns\"]'" "$dir/facts"; then
  pass set-list-syntax
else
  fail set-list-syntax "exit $code: $(cat "$dir/facts")"
fi
# Under ulimit -v: a 4K still cannot fit in 700 MB and is refused before any
# GL; a 1080p one with 32 llvmpipe threads (a many-core machine's count, which
# once crashed Mesa's compiler half-way) renders or is refused, never crashes.
if grep -qa __asan_init "$rollspin"; then
  skip memory-way-out "an AddressSanitizer build cannot run under ulimit -v"
  skip memory-many-threads "an AddressSanitizer build cannot run under ulimit -v"
else
  (ulimit -v 700000; exec "$rollspin" render "$scenes/lollipop.toml" --still --width 3840 --height 2160 -o "$dir/big.png") \
    2>"$dir/memory"
  code=$?
  if [ $code -eq 2 ] && grep -q 'render.msaa=1' "$dir/memory" && grep -q 'smaller size' "$dir/memory" &&
     grep -q 'ulimit -v' "$dir/memory" && [ ! -e "$dir/big.png" ]; then
    pass memory-way-out
  else
    fail memory-way-out "exit $code: $(grep -m 3 'rollspin:' "$dir/memory")"
  fi
  (ulimit -v 700000; export LP_NUM_THREADS=32; exec timeout -s KILL 120 "$rollspin" render "$scenes/lollipop.toml" --still \
    --width 1920 --height 1080 -o "$dir/threads.png") 2>"$dir/threads"
  code=$?
  if { [ $code -eq 0 ] && [ -s "$dir/threads.png" ]; } ||
     { [ $code -eq 2 ] && grep -q 'render.msaa=1' "$dir/threads" && [ ! -e "$dir/threads.png" ]; }; then
    pass memory-many-threads
  else
    fail memory-many-threads "exit $code: $(grep -m 3 'rollspin:' "$dir/threads")"
  fi
fi

finish
