#!/usr/bin/env bash
# Jobs that outlive their client (docs/deployment.md, "What survives what"), on real services
# over loopback DDS: `submit --detach` returns on the interpreter's acceptance while no step
# writer runs yet (so not on completion); a `submit --wait` killed (SIGKILL) once its job is
# accepted; `status` marks both jobs stalled while no step writer lives; once one starts, both
# complete, land in its --output-dir and are fetched by a later client (`ncbridge fetch`),
# byte-identical to `ncbridge convert`; a second fetch says the file left the bus. `cancel`
# drops a controller's run still arriving (controller-sim then exits 1, status says cancelled),
# and says "done already" for a finished job.
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$HERE/../integration/lib.sh"
export XDG_RUNTIME_DIR="$WORK/run"  # no `up` here: the bus is the one lib.sh exports
mkdir -m 700 "$XDG_RUNTIME_DIR"
N="$BIN/ncbridge"
EX="$SOURCE_DIR/examples/plate"

mkdir "$WORK/expected"
generate_program 3 2000 > "$WORK/a.ngc"
generate_program 4 2000 > "$WORK/b.ngc"
for p in a b; do
  "$N" convert "$WORK/$p.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" -o "$WORK/expected/$p.stp" 2> /dev/null
done

start_stage interpreter interp1
start_stage cc1-builder cc1
start_stage feature-recognizer fr
# Every stage but the step writer.
for _ in $(seq 1 50); do
  out=$("$N" status --listen 0.3 2>/dev/null || true)
  grep -Eq '^  interpreter +1 live' <<<"$out" && grep -Eq '^  cc1_builder +1 live' <<<"$out" && break
  sleep 0.2
done

# --detach: back once accepted, though no step writer can finish the job.
timeout 60 "$N" submit "$WORK/a.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id job-a --detach \
  > "$WORK/detach.out" 2> "$WORK/detach.log" || fail "submit --detach failed: $(cat "$WORK/detach.log")"
[[ "$(cat "$WORK/detach.out")" == job-a ]] || fail "submit --detach did not print the job id: $(cat "$WORK/detach.out")"

# A waiting client killed once its job is accepted.
start client "$N" submit "$WORK/b.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id job-b --wait --output-dir "$WORK/never"
client=$STARTED_PID
for _ in $(seq 1 100); do
  "$N" status --listen 0.3 2>/dev/null | grep -Eq '^  job-b .*interpreter:' && break
  sleep 0.1
done
kill -KILL "$(service_pid "$client")" 2>/dev/null || fail "the submit --wait client ended before it was killed"
[[ ! -e "$WORK/never/b.stp" ]] || fail "the killed client wrote its output"

# No step writer: both jobs are stalled, not shown as running.
sleep 1
"$N" status --listen 1 > "$WORK/status1.txt"
for j in job-a job-b; do
  grep -E "^  $j .*\[stalled: no live step_writer worker\]" "$WORK/status1.txt" > /dev/null \
    || fail "status does not mark $j stalled: $(cat "$WORK/status1.txt")"
done

mkdir "$WORK/out"
start_stage step-writer sw --output-dir "$WORK/out"
for j in a b; do
  for _ in $(seq 1 200); do [[ -s "$WORK/out/$j.stp" ]] && break; sleep 0.1; done
  cmp "$WORK/out/$j.stp" "$WORK/expected/$j.stp" || fail "the step writer's $j.stp differs from convert's"
done
timeout 60 "$N" fetch job-a -o "$WORK/fetched_a.stp" 2> "$WORK/fetch.log" || fail "fetch job-a: $(cat "$WORK/fetch.log")"
timeout 60 "$N" fetch job-b --output-dir "$WORK/fetched" 2>> "$WORK/fetch.log" || fail "fetch job-b: $(cat "$WORK/fetch.log")"
cmp "$WORK/fetched_a.stp" "$WORK/expected/a.stp" || fail "fetched job-a differs from convert's"
cmp "$WORK/fetched/b.stp" "$WORK/expected/b.stp" || fail "fetched job-b (named as the step writer names it) differs"
rc=0
timeout 60 "$N" fetch job-a -o "$WORK/again.stp" 2> "$WORK/again.log" || rc=$?
[[ $rc == 1 ]] || fail "a second fetch of job-a exited $rc, not 1"
grep -q "no longer on the bus" "$WORK/again.log" || fail "a second fetch did not say why: $(cat "$WORK/again.log")"
[[ ! -e "$WORK/again.stp" ]] || fail "a failed fetch wrote its output"
rc=0
timeout 60 "$N" fetch no-such-job -o "$WORK/none.stp" 2> "$WORK/none.log" || rc=$?
[[ $rc == 1 ]] && grep -q "know no such job" "$WORK/none.log" || fail "fetch of an unknown job: exit $rc, $(cat "$WORK/none.log")"

# cancel: a done job is left as it is; a run still arriving is dropped.
timeout 30 "$N" cancel job-a > "$WORK/cancel_done.txt"
grep -q "job-a: done already" "$WORK/cancel_done.txt" || fail "cancel of a done job: $(cat "$WORK/cancel_done.txt")"
start sim "$N" controller-sim "$EX/plate.ngc" --controller mill9 --run-id slow --tool-table "$EX/tools.tbl" \
  --tool-table-units inch --rate 10
sim=$STARTED_PID
sleep 1
timeout 30 "$N" cancel mill9/slow > "$WORK/cancel.txt" 2>&1 || fail "cancel failed: $(cat "$WORK/cancel.txt")"
grep -q "^mill9/slow: cancelled (interpreter" "$WORK/cancel.txt" || fail "cancel did not say the interpreter dropped it: $(cat "$WORK/cancel.txt")"
rc=0
wait "$sim" || rc=$?
[[ $rc == 1 ]] || fail "controller-sim of the cancelled run exited $rc, not 1: $(cat "$WORK/sim.log")"
grep -q "cancelled" "$WORK/sim.log" || fail "controller-sim did not say its run was cancelled: $(cat "$WORK/sim.log")"
"$N" status --listen 1 --controller mill9 > "$WORK/status2.txt"
grep -q "mill9/slow  cancelled" "$WORK/status2.txt" || fail "status does not show the run cancelled: $(cat "$WORK/status2.txt")"
rc=0
timeout 30 "$N" fetch mill9/slow -o "$WORK/cancelled.stp" 2> "$WORK/fetch_cancelled.log" || rc=$?
[[ $rc == 1 ]] && grep -q "was cancelled" "$WORK/fetch_cancelled.log" || fail "fetch of a cancelled job: exit $rc"
echo "PASS: detached and killed clients' jobs fetched byte-identical, stalled jobs marked, cancel"
