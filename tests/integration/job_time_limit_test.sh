#!/usr/bin/env bash
# Job time limit: with `ncbridge up --max-job-seconds 2`, a job whose interpretation takes
# longer (900,000 loop iterations of 24 computed parameters and a move: about 12 s of CPU in a
# release build; recognition is bounded now, so it is the interpreter that must be slow) is
# stopped with an ERROR status naming it, leaves no file, and every service goes on: the next job converts as
# `ncbridge convert` converts it.
source "$(dirname "$0")/lib.sh"

start up "$BIN/ncbridge" up --max-job-seconds 2
UP_PID=$STARTED_PID
wait_workers 1

# A loop of computed moves, each iteration 24 parameters of trigonometry (1 call in 26 lines).
{
  printf 'G21 G90 G17 G94 G54\nT1 M6\nS6000 M3\nG0 X0 Y0 Z5\nG1 Z-1 F300\n#1 = 0\no100 while [#1 LT 900000]\n'
  for k in $(seq 1 24); do
    printf '#%d = [SIN[#1 * %d] * 40 + COS[#1 / %d] * 30 + SQRT[ABS[#1 - %d]] MOD 7]\n' $((k + 10)) $k $k $k
  done
  printf 'G1 X[100 + #11] Y[75 + #34] F1200\n#1 = [#1 + 1]\no100 endwhile\nG0 Z10\nM5\nM30\n'
} > "$WORK/slow.ngc"
printf '[{"number": 1, "name": "ENDMILL_D6", "type": "flat_end_mill", "diameter": 6, "length": 40}]\n' > "$WORK/tools.json"
printf '{"units": "mm", "shape": "block", "min": [-10, -10, -30], "max": [210, 160, 0]}\n' > "$WORK/stock.json"

started=$(date +%s)
if timeout 120 "$BIN/ncbridge" submit "$WORK/slow.ngc" --tools "$WORK/tools.json" --stock "$WORK/stock.json" \
     --level cc2 --job-id slow-job --wait -o "$WORK/slow.stp" > "$WORK/submit-slow.log" 2>&1; then
  fail "a job over the time limit converted: $(cat "$WORK/submit-slow.log")"
fi
cat "$WORK/submit-slow.log"
grep -q "job slow-job ran longer than the job time limit (2 s, --max-job-seconds) and was stopped" "$WORK/submit-slow.log" \
  || fail "no time-limit error naming the job"
[[ ! -e "$WORK/slow.stp" ]] || fail "the stopped job left a file"
(( $(date +%s) - started < 60 )) || fail "the job was not stopped soon after its limit"

up=$(service_pid "$UP_PID")
[[ -n $up ]] && kill -0 "$up" || fail "ncbridge up is gone"
children=$(pgrep -a -P "$up")
for stage in interpreter cc1-builder feature-recognizer step-writer; do
  grep -q "ncbridge-$stage" <<<"$children" || fail "the $stage service is gone: $children"
done
timeout 60 "$BIN/ncbridge" convert "$SHARED/corpus/paper/face_mill.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  --level cc2 -o "$WORK/expected.stp" 2>/dev/null
timeout 60 "$BIN/ncbridge" submit "$SHARED/corpus/paper/face_mill.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  --level cc2 --wait -o "$WORK/good.stp" > "$WORK/submit-good.log" 2>&1 || fail "the job after the stopped one failed"
diff <(grep -v FILE_NAME "$WORK/expected.stp") <(grep -v FILE_NAME "$WORK/good.stp") > /dev/null \
  || fail "the next job's file differs from ncbridge convert"
echo "PASS: the job over --max-job-seconds stopped with an error naming it, no file; the next job converts"
