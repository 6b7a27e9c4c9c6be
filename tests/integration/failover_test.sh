#!/usr/bin/env bash
# Failover: two workers per stage as real processes; 20 programs submitted at once; in the
# middle of the batch one interpreter and one cc1_builder are killed with SIGKILL. Every job
# must still complete, byte-identical to `ncbridge convert`, and the writers' folder must hold
# each file once (20 files, no temporaries).
source "$(dirname "$0")/lib.sh"

make_programs "$WORK/programs" 20 30000   # longer generated programs: the kill lands mid-batch
mkdir -p "$WORK/out" "$WORK/results"
for stage in interpreter cc1-builder feature-recognizer step-writer; do
  for i in 1 2; do
    args=()
    [[ $stage == step-writer ]] && args=(--output-dir "$WORK/out")
    start_stage "$stage" "$stage-$i" "${args[@]}"
    eval "PID_${stage//-/_}_$i=$STARTED_PID"
  done
done
wait_workers 2

submits=()
while read -r prog tools stock; do
  name=$(name_of "$prog")
  timeout 180 "$BIN/ncbridge" submit "$prog" --tools "$tools" --stock "$stock" --job-id "${name%.stp}" \
    --wait -o "$WORK/results/$name" > "$WORK/submit-$name.log" 2>&1 &
  submits+=($!)
done < "$WORK/programs/list"

# Mid-batch: as soon as the first results are out, and while jobs are still in flight.
for _ in $(seq 1 600); do
  (( $(ls "$WORK/out" | wc -l) >= 1 )) && break
  sleep 0.01
done
done_before=$(ls "$WORK/out" | wc -l)
victims=()
for timeout_pid in "$PID_interpreter_1" "$PID_cc1_builder_1"; do
  pid=$(service_pid "$timeout_pid")
  [[ -n $pid ]] || fail "a worker to kill is not running"
  kill -KILL "$pid"
  victims+=("$pid")
done
echo "killed interpreter-1 and cc1-builder-1 (pids ${victims[*]}) with $done_before of 20 files written"
(( done_before < 20 )) || fail "the batch was over before the kill"

failed=0
for pid in "${submits[@]}"; do wait "$pid" || failed=$((failed + 1)); done
(( failed == 0 )) || fail "$failed submissions failed"
same=0
while read -r prog tools stock; do
  name=$(name_of "$prog")
  cmp -s "$WORK/programs/expected/$name" "$WORK/results/$name" || fail "$name differs from ncbridge convert"
  cmp -s "$WORK/programs/expected/$name" "$WORK/out/$name" || fail "$name in the writers' folder differs"
  same=$((same + 1))
done < "$WORK/programs/list"
files=$(ls -A "$WORK/out" | wc -l)
[[ $files == 20 ]] || fail "the writers' folder holds $files entries, not 20: $(ls -A "$WORK/out")"
# Inputs go to their owner only: the killed workers' jobs were sent again to the survivors, by
# the clients (programs: not logged, a client's output is its job ids) and the interpreters
# (canonical: logged). Every job a killed worker had started and not finished was done by the
# survivor of its stage, which received it only because it was sent again.
for stage in interpreter cc1-builder; do
  for job in $(sed -n 's/.* job \([^ ]*\): started$/\1/p' "$WORK/$stage-1.log"); do
    grep -q " job $job: done in" "$WORK/$stage-1.log" && continue
    grep -q " job $job: done in" "$WORK/$stage-2.log" || fail "job $job, in hand at $stage-1 when it was killed, was not done by $stage-2"
    echo "job $job, in hand at the killed $stage-1, done by $stage-2"
  done
done
resent=$( (grep -h "sent again" "$WORK"/*.log || true) | wc -l)
echo "$resent job inputs sent again to a survivor by the interpreters (the clients' are not logged)"
taken=$( (grep -h "done in" "$WORK/interpreter-2.log" || true) | wc -l)
echo "surviving interpreter ran $taken jobs; surviving cc1_builder ran $( (grep -h "done in" "$WORK/cc1-builder-2.log" || true) | wc -l)"
echo "PASS: $same of 20 jobs complete and byte-identical after killing a worker of two stages"
