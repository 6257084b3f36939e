#!/usr/bin/env bash
# The fault matrix (issue 45): every writing command x every output format x
# every fault, through the real binary. Faults:
#   full     the output folder is a 4 KiB tmpfs (as root; skipped elsewhere)
#   int      one SIGINT once the command is mid-work
#   int2     two SIGINTs 5 ms apart (what `timeout -s INT` sends: the process,
#            then its group): one interruption
#   term     SIGTERM
#   kill     SIGKILL, then the same command again: it must finish and clean
#            the stale temporary the killed run left
# Each run must end in a complete output, the documented partial
# (NAME.partial.EXT, its tags saying the frames it holds), or nothing; never a
# crash (exit 139, or 128 + a signal other than the one sent); and its
# message must not lie ("wrote X": X is there and complete; "removed the
# unfinished X" / "nothing written": X is not there).
# "Mid-work": a clip is signalled once its temporary file has data in it,
# the other commands once they have run for a moment (their temporary lives
# only for the last write). Renders are 160x90 and short.
# Usage: fault_matrix_test.sh ROLLSPIN WORKDIR (run by ctest, label faults).
set -uo pipefail
source "$(dirname "$0")/fault_support.sh"
fault_test_setup "$@"
lollipop=$scenes/lollipop.toml

# Inputs made once: a still for compare (against itself: exit 0, so that
# the rerun after SIGKILL must succeed), two parts for join.
inputs=$work/inputs
mkdir -p "$inputs"
"$rollspin" render "$lollipop" --still "${small[@]}" --quiet -o "$inputs/a.png" &&
  for k in 1 2; do
    "$rollspin" render "$lollipop" "${small[@]}" --set animation.duration=1 --shard $k/2 --quiet -o "$inputs/j.mp4" || exit 1
  done || { echo "fault_matrix: could not make the inputs"; exit 1; }

# Case table: NAME | OUTPUT (relative to the case folder) | KIND | the command's arguments (OUT = the output).
# KIND: video (a partial may stay), frames (a folder; a partial folder may
# stay), file (complete or nothing), folder (complete or nothing).
long=(--set animation.duration=100)
cases=(
  "still-png|x.png|file|render $lollipop --still ${small[*]} -o OUT"
  "still-jpg|x.jpg|file|render $lollipop --still ${small[*]} -o OUT"
  "still-pdf|x.pdf|file|render $lollipop --still ${small[*]} -o OUT"
  "still-svg|x.svg|file|render $lollipop --still ${small[*]} -o OUT"
  "clip-mp4|x.mp4|video|render $lollipop ${small[*]} ${long[*]} -o OUT"
  "clip-webm|x.webm|video|render $lollipop ${small[*]} ${long[*]} -o OUT"
  "clip-mov|x.mov|video|render $lollipop ${small[*]} ${long[*]} -o OUT"
  "clip-gif|x.gif|video|render $lollipop ${small[*]} ${long[*]} -o OUT"
  "clip-png-frames|frames|frames|render $lollipop ${small[*]} ${long[*]} -o OUT"
  "viewer-html|x.html|file|render $lollipop -o OUT"
  "timeline-csv|t.csv|file|timeline $lollipop --set timeline.samples=200000 -o OUT"
  "report-errors|report|folder|report errors $lollipop -o OUT"
  "join-mp4|j.mp4|file|join $inputs/j.part-1-of-2.mp4 $inputs/j.part-2-of-2.mp4 -o OUT"
  "compare-diff|diff.png|file|compare $inputs/a.png $inputs/a.png --diff OUT"
)
# What the rerun after SIGKILL renders: the same output, quickly.
short_of() { sed -e 's/animation.duration=100/animation.duration=0.5/' -e 's/timeline.samples=200000/timeline.samples=2000/' <<<"$1"; }

# Is OUT (a path) complete for its kind?
complete() {
  local out=$1 kind=$2
  case $kind in
    video) ffmpeg -v error -i "$out" -f null - >/dev/null 2>"$work/decode.log" && [ ! -s "$work/decode.log" ] ;;
    frames) [ -d "$out" ] && [ -n "$(ls "$out"/*.png 2>/dev/null)" ] ;;
    folder) [ -d "$out" ] && [ -n "$(ls -A "$out")" ] ;;
    file) [ -s "$out" ] ;;
  esac
}

# Judges one finished run: $1 case name, $2 fault, $3 folder, $4 output name,
# $5 kind, $6 exit code, $7 the signal sent (0: none).
judge() {
  local name="$1/$2" dir=$3 outname=$4 kind=$5 code=$6 sent=$7
  local out=$dir/$outname err=$dir/stderr
  if [ "$code" -eq 139 ] || { [ "$code" -ge 128 ] && [ "$code" -ne $((128 + sent)) ]; }; then
    fail "$name" "crashed: exit $code; $(grep -m 3 'rollspin' "$err" | tr '\n' ' ')"
    return
  fi
  local stem=${outname%.*} ext=${outname##*.} partial
  if [ "$kind" = frames ]; then partial=$stem.partial; else partial=$stem.partial.$ext; fi
  local left
  left=$(left_in "$dir")
  case "$left" in
    "")
      if grep -q "wrote $out" "$err"; then fail "$name" "says it wrote $out, which is not there"; return; fi ;;
    # A timeline's CSV comes with its sidecar NAME.csv.json (renamed after it).
    "$outname " | "$outname $outname.json ")
      if ! complete "$out" "$kind"; then fail "$name" "$outname is there but not complete: $(head -c 200 "$work/decode.log")"; return; fi
      if grep -q "removed the unfinished $out\b" "$err"; then fail "$name" "says it removed $out, which is there"; return; fi ;;
    "$partial ")
      if [ "$kind" = video ]; then
        if ! complete "$dir/$partial" video; then fail "$name" "the partial does not decode cleanly"; return; fi
        local frames tag
        frames=$(video_frames "$dir/$partial") tag=$(frames_tag "$dir/$partial")
        if [ -n "$tag" ] && [ "$tag" != "0-$((frames - 1))" ]; then
          fail "$name" "the partial holds $frames frames, its tags say $tag"; return
        fi
      elif [ "$kind" != frames ]; then
        fail "$name" "a partial $partial, which $kind outputs do not have"; return
      fi
      grep -q "$partial" "$err" || { fail "$name" "left $partial without saying so"; return; } ;;
    *)
      fail "$name" "left: $left"; return ;;
  esac
  pass "$name"
}

# Starts case $1's command in folder $2 (stderr there); sets $pid.
start() {
  local args=${1//OUT/$2/$3}
  # A non-interactive shell starts background commands with SIGINT
  # ignored; a terminal's Ctrl-C meets the default action until rollspin
  # installs its handler, so the command starts with that.
  # shellcheck disable=SC2086  # the table's words are the arguments
  env --default-signal=INT,TERM "$rollspin" $args 2>"$2/stderr" >/dev/null &
  pid=$!
}

# Waits until case output $2 (kind $3) in folder $1 is mid-work.
mid_work() {
  local dir=$1 outname=$2 kind=$3
  case $kind in
    video) wait_for "has_file_over '$dir' '.$outname.' 4096" 60 ;;
    frames) wait_for "ls '$dir'/.$outname.*/*.png >/dev/null 2>&1 || ls '$dir'/$outname/*.png >/dev/null 2>&1" 60 ;;
    *) sleep 0.2 ;;
  esac
}

can_mount=1
mount_small "$work/probe" 4k && umount_small "$work/probe" || can_mount=0
# Under ROLLSPIN_TEST_SWEEP=sample (the ASan pass; tests/support/sweep.hpp)
# a row runs the faults whose index plus the row's is a multiple of 4: every
# row meets one or two faults, every fault about a quarter of the rows.
faults=(full int int2 term kill)
sampled() { [ "${ROLLSPIN_TEST_SWEEP:-full}" = sample ] && (($1 % 4 != 0)); }
# One row of the table ($1, its index $2): its five faults in turn (the
# row's log is its result).
run_row() {
  local cname outname kind args fault dir code signal number killed stale
  IFS='|' read -r cname outname kind args <<<"$1"
  for index in "${!faults[@]}"; do
    fault=${faults[$index]}
    sampled $(($2 + index)) && continue
    dir=$work/$cname/$fault
    mkdir -p "$dir"
    case $fault in
      full)
        if [ $can_mount = 0 ]; then skip "$cname/full" "cannot mount a tmpfs here (needs root: uid $(id -u))"; continue; fi
        mount_small "$dir" 4k
        start "$args" "$dir" "$outname"
        wait $pid
        code=$?
        judge "$cname" full "$dir" "$outname" "$kind" $code 0
        cp "$dir/stderr" "$work/$cname.full.stderr"
        umount_small "$dir" ;;
      int | int2 | term)
        start "$args" "$dir" "$outname"
        mid_work "$dir" "$outname" "$kind"
        signal=INT number=2
        [ $fault = term ] && signal=TERM number=15
        kill -$signal $pid 2>/dev/null
        if [ $fault = int2 ]; then sleep_ms 5; kill -INT $pid 2>/dev/null; fi
        wait $pid
        code=$?
        judge "$cname" $fault "$dir" "$outname" "$kind" $code $number ;;
      kill)
        start "$args" "$dir" "$outname"
        mid_work "$dir" "$outname" "$kind"
        kill -KILL $pid 2>/dev/null
        wait $pid
        killed=$?
        start "$(short_of "$args")" "$dir" "$outname"
        wait $pid
        code=$?
        stale=$(cd "$dir" && ls -A | grep -E "^\.${outname//./\\.}\.[0-9]+\.tmp$" || true)
        if [ $code -ne 0 ]; then
          fail "$cname/kill" "the rerun after SIGKILL (exit $killed) failed: exit $code; $(tail -n 2 "$dir/stderr")"
        elif [ -n "$stale" ]; then
          fail "$cname/kill" "the rerun left the killed run's temporary $stale"
        else
          judge "$cname" kill "$dir" "$outname" "$kind" $code 0
        fi ;;
    esac
  done
}

# Two rows at a time (each run is mostly one busy thread: a GL context, an
# encoder), then the rows' results in table order.
matrix_start=$SECONDS
for row in "${!cases[@]}"; do
  entry=${cases[$row]}
  while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done
  run_row "$entry" "$row" >"$work/row-${entry%%|*}.log" 2>&1 &
done
wait
for entry in "${cases[@]}"; do
  log=$work/row-${entry%%|*}.log
  grep -v ' Killed ' "$log"
  passed=$((passed + $(grep -c '^ok ' "$log"))) failed=$((failed + $(grep -c '^FAILED ' "$log")))
  skipped=$((skipped + $(grep -c '^skipped: ' "$log")))
done
echo "fault matrix: ${#cases[@]} commands/formats x 5 faults = $((${#cases[@]} * 5)) cases$(
  [ "${ROLLSPIN_TEST_SWEEP:-full}" = sample ] && echo ", $((passed + failed + skipped)) of them run (ROLLSPIN_TEST_SWEEP=sample)") in $((SECONDS - matrix_start)) s"
finish
