#!/usr/bin/env bash
# vrut-rutting's checkpoints, from outside, as a user meets them:
#  - a run killed with SIGKILL between checkpoints, resumed with --resume,
#    ends with the results of the run never stopped, bit for bit;
#  - Ctrl-C leaves a valid checkpoint beside valid partial results, and
#    resuming that gives the same results again; so does a scheduler's
#    SIGTERM (exit 143) while the specimens settle (the run says it stops
#    when the loading begins);
#  - a 3D ensemble killed and resumed the same way, on the stones its
#    checkpoint kept (not placed again), and stopped by Ctrl-C;
#  - each resume takes the test up where its checkpoint left it: its first
#    sample lies past 0, and past a stopped run's last (not started over);
#  - a damaged checkpoint, and options given beside --resume, are refused.
# Usage: checkpoint_resume.sh VRUT_RUTTING
set -u
exe=$1
work=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# A small test (about 2 s on 2 cores, rigid stones at alpha_T 4e3): long enough that the signals come while it loads.
small=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 4e3 --settle-steps 300)

# Waits (at most 60 s) until FILE exists or holds PATTERN.
wait_for() {  # wait_for FILE [PATTERN]
  for _ in $(seq 1200); do
    if [[ $# -eq 1 ]]; then [[ -e $1 ]] && return 0; else grep -q "$2" "$1" 2>/dev/null && return 0; fi
    sleep 0.05
  done
  return 1
}
# A resume, told from a run started over (runs are deterministic, so the
# results alone cannot tell them apart): the resumed run's first sample lies
# past minute AFTER (0, or the minutes a stopped run had done).
resumed_past() {  # resumed_past OUTPUT_FILE AFTER
  local minute
  minute=$(sed -n 's/^resumed: minute \([0-9.]*\) of .*/\1/p' "$1" | head -n 1)
  if [[ -z $minute ]]; then fail "$1: no 'resumed: minute' line"; return; fi
  if awk -v m="$minute" -v a="$2" 'BEGIN { exit !(m > a) }'; then echo "ok:   $1 took up the test at minute $minute (after $2)"
  else fail "$1: its first sample at minute $minute, not after $2: started over?"; fi
}
# The results, less what depends on the clock or the thread count.
same_results() {  # same_results DIR_A DIR_B
  local f
  for f in deformation.csv final.vtk; do
    cmp -s "$1/$f" "$2/$f" || { fail "$f of $2 differs from that of $1"; return; }
  done
  if [[ -e $1/seeds.csv ]]; then cmp -s "$1/seeds.csv" "$2/seeds.csv" || { fail "seeds.csv of $2 differs"; return; }; fi
  diff <(grep -vE '"(wall_seconds|particle_steps_per_second|threads)"' "$1/summary.json") \
       <(grep -vE '"(wall_seconds|particle_steps_per_second|threads)"' "$2/summary.json") >/dev/null ||
    { fail "summary.json of $2 differs from that of $1"; return; }
  echo "ok:   $2 ends as $1 did"
}

"$exe" "${small[@]}" --out whole >whole.out 2>&1 || fail "the uninterrupted run failed: $(tail -n 3 whole.out)"

# SIGKILL between checkpoints: nothing is written on the way out, so only
# the last checkpoint is left. A checkpoint every 0.2 s and the kill as soon
# as the first is seen: the run has most of its 2 s still to go, so the kill
# cannot come after its end (a kill 0.5 s after a first checkpoint at 1 s
# once came after it, on a loaded machine).
"$exe" "${small[@]}" --checkpoint-every 0.2 --out killed >killed.out 2>&1 &
pid=$!
wait_for killed/checkpoint.vrut || fail "no checkpoint within 60 s"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
[[ -s killed/checkpoint.vrut && ! -e killed/summary.json ]] || fail "after SIGKILL: $(ls killed)"
"$exe" --resume killed >resumed.out 2>&1 || fail "--resume after SIGKILL failed: $(tail -n 3 resumed.out)"
grep -q "resuming from" resumed.out || fail "the resumed run does not say it resumes"
resumed_past resumed.out 0
same_results whole killed
[[ -e killed/checkpoint.vrut ]] && fail "a finished run left its checkpoint behind"

# An ensemble killed the same way resumes every specimen: the same curves,
# per-seed table and statistics as the ensemble never stopped.
"$exe" "${small[@]}" --seeds 1-2 --out ensemble >ensemble.out 2>&1 || fail "the whole ensemble failed: $(tail -n 3 ensemble.out)"
"$exe" "${small[@]}" --seeds 1-2 --checkpoint-every 0.2 --out ensemble_killed >ensemble_killed.out 2>&1 &
pid=$!
wait_for ensemble_killed/checkpoint.vrut || fail "no ensemble checkpoint within 60 s"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
[[ -s ensemble_killed/checkpoint.vrut && ! -e ensemble_killed/summary.json ]] || fail "after SIGKILL: $(ls ensemble_killed)"
"$exe" --resume ensemble_killed >ensemble_resumed.out 2>&1 || fail "--resume of the ensemble failed: $(tail -n 3 ensemble_resumed.out)"
grep -q '"specimens": 2' ensemble_killed/summary.json 2>/dev/null || fail "the resumed ensemble has not 2 specimens"
same_results ensemble ensemble_killed

# 3D: an ensemble killed between checkpoints and resumed on one thread ends
# as the ensemble never stopped. (Ctrl-C takes the same path in 2D and 3D,
# the stop that run_loading asks at each sample, tested above in 2D.)
small3=(--dim 3 --gradation 1 --width-mm 40 --sphere-radius-mm 1.5 --shift 2e5 --settle-steps 300 --seeds 1-2)
"$exe" "${small3[@]}" --out whole3 >whole3.out 2>&1 || fail "the whole 3D ensemble failed: $(tail -n 3 whole3.out)"
"$exe" "${small3[@]}" --checkpoint-every 1 --out killed3 >killed3.out 2>&1 &
pid=$!
wait_for killed3/checkpoint.vrut || fail "no 3D checkpoint within 60 s"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
[[ -s killed3/checkpoint.vrut && ! -e killed3/summary.json ]] || fail "3D, after SIGKILL: $(ls killed3)"
"$exe" --resume killed3 --threads 1 >resumed3.out 2>&1 || fail "--resume of the 3D ensemble failed: $(tail -n 3 resumed3.out)"
resumed_past resumed3.out 0
same_results whole3 killed3
# ... on the stones the checkpoint kept, not placed again.
[[ $(grep -c "the stones placed when the run began, from the checkpoint" resumed3.out) -eq 2 ]] ||
  fail "the resumed 3D ensemble does not say it took both seeds' stones from the checkpoint: $(head -n 5 resumed3.out)"
! grep -q "placing stones" resumed3.out || fail "the resumed 3D ensemble placed its stones again"

# Ctrl-C: partial results and a checkpoint, and how to go on; resumed (on
# one thread), the run ends as one never stopped.
# SIGNAL=TERM (a scheduler's) instead of Ctrl-C: exit 143 and the same partial results.
ctrl_c_and_resume() {  # [SIGNAL=TERM] ctrl_c_and_resume DIR WHOLE_DIR PROGRESS_PATTERN ARGS...
  local dir=$1 whole_dir=$2 pattern=$3 pid code signal=${SIGNAL:-INT}; shift 3
  local want=130
  [[ $signal == TERM ]] && want=143
  "$exe" "$@" --out "$dir" >"$dir.out" 2>"$dir.err" &
  pid=$!
  wait_for "$dir.err" "$pattern" || fail "$dir: no progress within 60 s"
  kill "-$signal" "$pid"
  wait "$pid"; code=$?
  [[ $code -eq $want ]] || fail "$dir: SIG$signal gave exit $code, not $want"
  grep -q "go on with: .*--resume $dir" "$dir.out" || fail "$dir: Ctrl-C does not say how to resume: $(cat "$dir.out")"
  grep -q '"interrupted": true' "$dir/summary.json" 2>/dev/null || fail "$dir: no partial summary.json"
  [[ -s $dir/checkpoint.vrut ]] || fail "$dir: Ctrl-C left no checkpoint"
  local done_minutes
  done_minutes=$(sed -n 's/.*"minutes_done": \([0-9.e+-]*\).*/\1/p' "$dir/summary.json")
  "$exe" --resume "$dir" --threads 1 >"$dir.resumed.out" 2>&1 || fail "--resume $dir failed: $(tail -n 3 "$dir.resumed.out")"
  if [[ -n $done_minutes ]]; then resumed_past "$dir.resumed.out" "$done_minutes"; else fail "$dir: no minutes_done"; fi
  same_results "$whole_dir" "$dir"
}
ctrl_c_and_resume stopped whole "loading.*[1-9]0 *%" "${small[@]}"
# The same in 3D, the 3D ensemble above (its loading, about 2 s, gives the
# poll a window of a second or more).
ctrl_c_and_resume stopped3 whole3 "loading.*[1-9]0 *%" "${small3[@]}"

# A scheduler's SIGTERM while settling: the run says it stops at the
# loading's first sample, does so with a checkpoint (exit 143), and the
# resumed run ends as one never stopped. (A longer settling, so that the
# signal comes while it lasts; the settling's path is the same for Ctrl-C.)
long_settle=(--width-mm 60 --height-mm 30 --disk-radius-mm 1 --shift 4e3 --settle-steps 60000)
"$exe" "${long_settle[@]}" --out settled_whole >settled_whole.out 2>&1 || fail "the long-settling run failed"
SIGNAL=TERM ctrl_c_and_resume settling settled_whole "settling.*[1-9]0 *%" "${long_settle[@]}"
grep -q "SIGTERM while settling" settling.err || fail "SIGTERM while settling is not told: $(tail -n 3 settling.err)"
grep -q "terminated (SIGTERM)" settling.err || fail "SIGTERM is not told as such: $(tail -n 3 settling.err)"

# Refusals: with exit 2 and a message, and the checkpoint left as it was.
check_refused() {  # check_refused PATTERN ARGS...
  local pattern=$1; shift
  local out code
  out=$("$exe" "$@" 2>&1); code=$?
  if [[ $code -ne 2 ]] || ! grep -qE "$pattern" <<<"$out"; then fail "$* -> exit $code: $out"; else echo "ok:   $* refused"; fi
}
"$exe" "${small[@]}" --checkpoint-every 0.2 --out again >again.out 2>&1 &
pid=$!
wait_for again/checkpoint.vrut || fail "no checkpoint within 60 s"
kill -KILL "$pid"
wait "$pid" 2>/dev/null
check_refused "only --backend, --threads and --checkpoint-every" --resume again --seed 4
check_refused "holds the checkpoint of an unfinished run" "${small[@]}" --out again
check_refused "no checkpoint in" --resume whole
cp again/checkpoint.vrut good.vrut
printf 'x' | dd of=again/checkpoint.vrut bs=1 seek=5000 conv=notrunc status=none
check_refused "damaged" --resume again
cmp -s good.vrut again/checkpoint.vrut && fail "the test did not damage the checkpoint"

echo "$failures failure(s)"
exit $((failures > 0))
