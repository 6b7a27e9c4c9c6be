#!/usr/bin/env bash
# Live capture from an MTConnect agent: an agent double (mtconnect/agent_double.py: MTConnect
# answers for a recorded run, released as a controller makes them) feeds `ncbridge capture
# mtconnect`; the services turn each run into a file. Runs:
#   lines   the device reports its LineNumber; the program is in --program-dir: the file
#           equals `ncbridge convert` of the program, with answers out of sequence order, the
#           agent's buffer overrun (a small buffer) and dropped connections: nothing lost or doubled;
#   blocks  the device reports Block texts, no program folder: the file equals convert of the
#           blocks executed; with the buffer overrun, the run is marked aborted and makes no file.
source "$(dirname "$0")/lib.sh"
here=$(dirname "$0")/mtconnect
mkdir -p "$WORK/programs" "$WORK/out"

cat > "$WORK/programs/loop.ngc" <<'NGC'
G21 G17 G90 G94 G54
T1 M6
S1000 M3
G0 X0 Y0 Z5
#1 = 0
o1 while [#1 lt 3]
  G1 Z-1 F200
  G1 X[#1 * 10 + 10] Y5
  G0 Z5
  #1 = [#1 + 1]
o1 endwhile
G0 X0 Y0 Z10
M5
M30
NGC
# What the controller reports: mode, program, execution, and the line motion is on.
{
  echo "ControllerMode AUTOMATIC"; echo "Execution READY"; echo "Program loop.ngc"; echo "Execution ACTIVE"
  for l in 4 7 8 9 7 8 9 7 8 9 12; do echo "LineNumber@ABSOLUTE $l"; done
  echo "Execution PROGRAM_COMPLETED"; echo "Execution READY"
} > "$WORK/lines.rec"
# The same run as Block texts (a device whose adapter sends the executing block).
flat="G21 G17 G90 G94 G54|T1 M6|S1000 M3|G0 X0 Y0 Z5|G1 Z-1 F200|G1 X10 Y5|G0 Z5|G1 Z-1 F200|G1 X20 Y5|G0 Z5|G1 Z-1 F200|G1 X30 Y5|G0 Z5|G0 X0 Y0 Z10|M5|M30"
{
  echo "ControllerMode AUTOMATIC"; echo "Execution READY"; echo "Program O1234"; echo "Execution ACTIVE"
  tr '|' '\n' <<<"$flat" | sed 's/^/Block /'
  echo "Execution PROGRAM_COMPLETED"
} > "$WORK/blocks.rec"
tr '|' '\n' <<<"$flat" > "$WORK/flat.ngc"

timeout 60 "$BIN/ncbridge" convert "$WORK/programs/loop.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  -o "$WORK/loop.stp" 2> "$WORK/convert.log" || fail "convert rejects loop.ngc"
timeout 60 "$BIN/ncbridge" convert "$WORK/flat.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  -o "$WORK/flat.stp" 2> "$WORK/convert-flat.log" || fail "convert rejects the flat blocks"

start up "$BIN/ncbridge" up --workers 1 --live-tools "$TOOLS_PAPER" --live-stock "$STOCK_PAPER" --output-dir "$WORK/out"
wait_workers 1

# capture_run NAME RECORDING "DOUBLE OPTIONS" "CAPTURE OPTIONS": one run through the double.
capture_run() {
  local name=$1 recording=$2 double_options=$3 capture_options=$4
  rm -f "$WORK/port-$name"
  # shellcheck disable=SC2086
  start "agent-$name" python3 "$here/agent_double.py" --recording "$recording" --port-file "$WORK/port-$name" $double_options
  local agent_pid=$STARTED_PID
  for _ in $(seq 1 50); do [[ -s "$WORK/port-$name" ]] && break; sleep 0.1; done
  [[ -s "$WORK/port-$name" ]] || fail "the agent double did not start: $(cat "$WORK/agent-$name.log")"
  # shellcheck disable=SC2086
  timeout 120 "$BIN/ncbridge" capture mtconnect "http://127.0.0.1:$(cat "$WORK/port-$name")" --device mill2 \
    --controller "$name" --interval-ms 100 --runs 1 $capture_options > "$WORK/capture-$name.log" 2>&1 \
    || fail "capture $name failed: $(cat "$WORK/capture-$name.log")"
  kill "$agent_pid" 2>/dev/null || true
}
# wait_file NAME: the run's file in the output folder (or fail after 30 s).
wait_file() {
  for _ in $(seq 1 300); do
    ls "$WORK"/out/"$1"-*.stp > /dev/null 2>&1 && return 0
    sleep 0.1
  done
  fail "no file for run $1: $(cat "$WORK/capture-$1.log")"
}
same() {  # same NAME EXPECTED: the run's file equals EXPECTED but for FILE_NAME
  wait_file "$1"
  diff <(grep -v FILE_NAME "$2") <(grep -v FILE_NAME "$(ls "$WORK"/out/"$1"-*.stp)") > "$WORK/diff-$1.log" \
    || fail "$1: the captured file differs from convert's: $(head -n 20 "$WORK/diff-$1.log")"
  echo "  $1: equals convert"
}

capture_run lines-clean "$WORK/lines.rec" "--period-ms 20" "--program-dir $WORK/programs"
same lines-clean "$WORK/loop.stp"
capture_run lines-shuffled "$WORK/lines.rec" "--period-ms 20 --shuffle" "--program-dir $WORK/programs"
same lines-shuffled "$WORK/loop.stp"
capture_run lines-overrun "$WORK/lines.rec" "--period-ms 15 --buffer 3" "--program-dir $WORK/programs"
grep -q "buffer" "$WORK/capture-lines-overrun.log" || fail "lines-overrun: no buffer overrun happened: $(cat "$WORK/capture-lines-overrun.log")"
same lines-overrun "$WORK/loop.stp"
capture_run lines-dropped "$WORK/lines.rec" "--period-ms 20 --drop-every 3" "--program-dir $WORK/programs"
grep -q "retrying" "$WORK/capture-lines-dropped.log" || fail "lines-dropped: no connection was dropped"
same lines-dropped "$WORK/loop.stp"
capture_run blocks-clean "$WORK/blocks.rec" "--period-ms 20 --shuffle --drop-every 4" ""
same blocks-clean "$WORK/flat.stp"

capture_run blocks-overrun "$WORK/blocks.rec" "--period-ms 15 --buffer 3" ""
grep -q "ABORTED" "$WORK/capture-blocks-overrun.log" || fail "blocks-overrun: the run with lost blocks was not aborted: $(cat "$WORK/capture-blocks-overrun.log")"
for _ in $(seq 1 50); do
  "$BIN/ncbridge" status --controller blocks-overrun > "$WORK/status.txt" 2>&1 || true
  grep -q "aborted" "$WORK/status.txt" && break
  sleep 0.2
done
grep -q "aborted" "$WORK/status.txt" || fail "status does not say the run was aborted: $(cat "$WORK/status.txt")"
ls "$WORK"/out/blocks-overrun-*.stp > /dev/null 2>&1 && fail "the run with lost blocks made a file"
echo "PASS: MTConnect capture equals convert with shuffled answers, buffer overruns and dropped connections; lost blocks abort the run"
