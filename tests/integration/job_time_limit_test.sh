#!/usr/bin/env bash
# Job time limit: with `ncbridge up --max-job-seconds 2`, a CC2 job whose recognition takes
# longer (200,000 lines of random long cuts at random depths: about 4 s of CPU in a release
# build, well over the limit however fast recognition gets) is stopped with an ERROR status
# naming it, leaves no file, and every service goes on: the next job converts as
# `ncbridge convert` converts it.
source "$(dirname "$0")/lib.sh"

start up "$BIN/ncbridge" up --max-job-seconds 2
UP_PID=$STARTED_PID
wait_workers 1

# Random strokes of a 6 mm end mill across a 200 x 150 plate, a new depth every 20 lines.
awk 'BEGIN { srand(7); print "G21 G90 G17 G94 G54"; print "T1 M6"; print "S6000 M3"; print "G0 X0 Y0 Z5";
             for (i = 0; i < 200000; i++) {
               if (i % 20 == 0) { printf "G0 Z5\nG1 Z-%.3f F300\n", 0.5 + 9 * rand(); i += 2 }
               printf "G1 X%.3f Y%.3f F1200\n", 200 * rand(), 150 * rand() }
             print "G0 Z10"; print "M5"; print "M30" }' > "$WORK/slow.ngc"
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
