#!/usr/bin/env bash
# Bad input: a malformed program (interpreter), a truncated Job payload (interpreter), a
# truncated canonical batch (cc1_builder), and a message of the wrong type on the workingsteps
# (feature_recognizer) and features (step_writer) topics each give an ERROR status naming the
# job and stage (and for the program, its file:line:column); every service is still alive after,
# and a good job still converts.
source "$(dirname "$0")/lib.sh"
: "${INJECT:?}"

for stage in interpreter cc1-builder feature-recognizer step-writer; do
  start_stage "$stage" "$stage"
  eval "PID_${stage//-/_}=$STARTED_PID"
done
wait_workers 1

printf 'G21 G90\nG0 X0 Y0 Z5\nG1 X10 Y#<undefined> F100\nM2\n' > "$WORK/bad.ngc"
if timeout 60 "$BIN/ncbridge" submit "$WORK/bad.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id bad-program \
     --wait -o "$WORK/bad.stp" > "$WORK/submit-bad.log" 2>&1; then
  fail "a malformed program was accepted"
fi
grep -Eq "ncbridge: error: .*bad.ngc:3:[0-9]+: .*\(interpreter\)" "$WORK/submit-bad.log" || fail "no located error for the bad program: $(cat "$WORK/submit-bad.log")"

timeout 30 "$INJECT" truncated-job bad-truncated-job || fail "inject truncated-job"
timeout 30 "$INJECT" truncated-batch bad-truncated-batch || fail "inject truncated-batch"
timeout 30 "$INJECT" wrong-type bad-type-workingsteps workingsteps || fail "inject wrong-type workingsteps"
timeout 30 "$INJECT" wrong-type bad-type-features features || fail "inject wrong-type features"

expect_error() {  # JOB STAGE
  for _ in $(seq 1 50); do
    grep -Eq "^  $1 .*$2:ERROR" <<<"$("$BIN/ncbridge" status --listen 0.3)" && return 0
  done
  "$BIN/ncbridge" status --listen 0.5
  fail "no ERROR status from $2 for $1"
}
expect_error bad-program interpreter
expect_error bad-truncated-job interpreter
expect_error bad-truncated-batch cc1_builder
expect_error bad-type-workingsteps feature_recognizer
expect_error bad-type-features step_writer
"$BIN/ncbridge" status --listen 0.5 | grep ERROR

for stage in interpreter cc1_builder feature_recognizer step_writer; do
  pid=$(service_pid "$(eval echo "\$PID_$stage")")
  [[ -n $pid ]] && kill -0 "$pid" || fail "the $stage service died"
done
timeout 60 "$BIN/ncbridge" convert "$SHARED/corpus/paper/face_mill.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  -o "$WORK/expected.stp" 2>/dev/null
timeout 60 "$BIN/ncbridge" submit "$SHARED/corpus/paper/face_mill.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  --wait -o "$WORK/expected.stp.out" > "$WORK/submit-good.log" 2>&1 || fail "a good job after the bad ones failed"
# FILE_NAME.name differs (the output names differ): compare the rest.
diff <(grep -v FILE_NAME "$WORK/expected.stp") <(grep -v FILE_NAME "$WORK/expected.stp.out") > /dev/null \
  || fail "the good job's file differs from ncbridge convert"
echo "PASS: 5 bad inputs, 5 located ERROR statuses, 4 services alive, the next job converts"
