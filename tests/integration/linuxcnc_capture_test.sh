#!/usr/bin/env bash
# Live capture from a real controller: LinuxCNC's simulated mill runs headless as an ordinary
# user (it refuses root), the services run, and `ncbridge capture linuxcnc` watches the
# controller. Three runs, started as an operator would (tests/integration/linuxcnc/drive.py):
#   1. the paper's test part, 2. a program with a loop, a subroutine and a tool change: each
#      captured CC1 file equals `ncbridge convert` of the program (but for FILE_NAME), and the
#      blocks published equal the lines LinuxCNC executed (LinuxCNC's own LOG of every block);
#   3. the test part aborted after a second: no file, and a status that says aborted.
# Needs root (to make the controller's user) and LinuxCNC (Debian linuxcnc-uspace).
source "$(dirname "$0")/lib.sh"
if ! command -v linuxcnc > /dev/null; then
  [[ ${CI:-} == true ]] && fail "LinuxCNC is not installed under CI=true (scripts/install-deps.sh --tests installs linuxcnc-uspace)"
  echo "SKIP: LinuxCNC is not installed (Debian package linuxcnc-uspace)"; exit 77
fi
[[ $(id -u) == 0 ]] || { echo "SKIP: needs root to make the controller's user"; exit 77; }

source "$(dirname "$0")/linuxcnc/controller.sh"

# instrument PROGRAM OUT LOG: a copy whose every block (not o-word lines) logs its line number
# through LinuxCNC's LOG comment, so LinuxCNC itself writes the lines it executed.
instrument() {
  awk -v logfile="$3" 'NR == 1 { print "(LOGOPEN," logfile ")" }
    /^[ \t]*$/ || /^[ \t]*[oO][0-9<]/ || /^[ \t]*%/ || /^[ \t]*\(.*\)[ \t]*$/ { print; next }
    { print $0 " (LOG,L" NR ")" }' "$1" > "$2"
}
instrument "$SHARED/corpus/paper/test_part.ngc" "$cfg/nc/test_part.ngc" "$cfg/test_part.log"
cat > "$WORK/flow.ngc" <<'NGC'
(a loop, a subroutine and a tool change, run on the controller)
G21 G17 G90 G94 G54
o100 sub
  G1 X#1 Y#2 F300
  G1 Z[-#3]
  G0 Z5
o100 endsub
T1 M6
G43 H1
S1200 M3
G0 X0 Y0 Z5
#<pass> = 0
o101 while [#<pass> lt 3]
  G1 Z-1 F200
  G1 X[#<pass> * 10 + 10] Y5
  G0 Z5
  #<pass> = [#<pass> + 1]
o101 endwhile
o100 call [7] [8] [1.5]
T2 M6
G43 H2
S800 M3
G0 X30 Y20 Z5
G81 X30 Y20 Z-6 R2 F100
X40
G80
o100 call [20] [#<pass>] [2]
G0 Z10
M5
M30
NGC
instrument "$WORK/flow.ngc" "$cfg/nc/flow.ngc" "$cfg/flow.log"
chown -R "$user" "$cfg"

start_controller

start up "$BIN/ncbridge" up --workers 1 --live-tools "$TOOLS_PAPER" --live-stock "$STOCK_PAPER" --output-dir "$WORK/out"
wait_workers 1
start capture su "$user" -c "$(as_user "$BIN/ncbridge" capture linuxcnc --controller mill1 --runs 3)"
capture_pid=$STARTED_PID

# run_and_wait PROGRAM N [drive options]: runs it; waits for the N-th finished run in capture.log.
run_and_wait() {
  local program=$1 n=$2; shift 2
  su "$user" -c "$(as_user timeout 300 "$python" "$drive" run "$program" "$@")" || fail "driving LinuxCNC failed for $program"
  for _ in $(seq 1 100); do
    (( $(grep -Ec 'completed|ABORTED' "$WORK/capture.log") >= n )) && return 0
    sleep 0.1
  done
  fail "capture did not report run $n: $(cat "$WORK/capture.log")"
}
# wait_file N: the N-th captured file in the step writer's output folder.
wait_file() {
  for _ in $(seq 1 300); do
    (( $(ls "$WORK"/out/mill1-*.stp 2>/dev/null | wc -l) >= $1 )) && return 0
    sleep 0.1
  done
  fail "no file for captured run $1 (status: $("$BIN/ncbridge" status 2>&1 | tail -n 5))"
}

# check_run NAME N: the N-th run's file equals convert's; its blocks equal LinuxCNC's log.
check_run() {
  local name=$1 n=$2
  timeout 60 "$BIN/ncbridge" convert "$cfg/nc/$name.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
    -o "$WORK/$name.stp" 2> "$WORK/convert-$name.log" || fail "convert rejects $name"
  wait_file "$n"
  local file; file=$(ls -t "$WORK"/out/mill1-*.stp | head -n 1)
  diff <(grep -v FILE_NAME "$WORK/$name.stp") <(grep -v FILE_NAME "$file") > "$WORK/diff-$name.log" \
    || fail "the captured file of $name differs from convert's: $(head -n 20 "$WORK/diff-$name.log")"
  # LinuxCNC logged each executed block; a call with arguments is published as one more block
  local executed calls published
  executed=$(wc -l < "$cfg/$name.log")
  calls=$(grep -Ec '^[ \t]*[oO][0-9]+ call \[' "$cfg/nc/$name.ngc" || true)
  published=$(grep 'completed' "$WORK/capture.log" | sed -n "${n}p" | sed -E 's/.*completed: ([0-9]+) blocks/\1/')
  # blocks LinuxCNC ran without logging: the LOGOPEN line and the program's comment lines
  local unlogged; unlogged=$(awk '/^[ \t]*\(.*\)[ \t]*$/' "$cfg/nc/$name.ngc" | wc -l)
  (( published == executed + calls + unlogged )) \
    || fail "$name: $published blocks published, LinuxCNC executed $executed logged blocks + $calls calls + $unlogged comment lines"
  echo "  $name: $published blocks published = $executed executed (LinuxCNC's log) + $calls calls + $unlogged comment lines; CC1 equals convert"
}

run_and_wait "$cfg/nc/test_part.ngc" 1 --feed-scale 100
check_run test_part 1
run_and_wait "$cfg/nc/flow.ngc" 2 --feed-scale 100
check_run flow 2

# An aborted run: no file; the status says aborted.
files_before=$(ls "$WORK"/out/mill1-*.stp | wc -l)
run_and_wait "$cfg/nc/test_part.ngc" 3 --feed-scale 1 --abort-after 1.5
grep -q ABORTED "$WORK/capture.log" || fail "the aborted run was not reported aborted: $(cat "$WORK/capture.log")"
for _ in $(seq 1 50); do
  "$BIN/ncbridge" status --controller mill1 > "$WORK/status.txt" 2>&1 || true
  grep -q "aborted" "$WORK/status.txt" && break
  sleep 0.2
done
grep -q "aborted" "$WORK/status.txt" || fail "status does not say the run was aborted: $(cat "$WORK/status.txt")"
sleep 1
(( $(ls "$WORK"/out/mill1-*.stp | wc -l) == files_before )) || fail "the aborted run made a file"
wait "$capture_pid" || true
echo "PASS: real LinuxCNC: 2 runs captured equal to convert, block counts equal LinuxCNC's own log; an aborted run makes no file"
