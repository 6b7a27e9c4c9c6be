#!/usr/bin/env bash
# Live capture of a program with control flow: controller-sim runs it as a controller would (a
# while loop, an if/else, a subroutine called twice with arguments) and publishes the blocks as
# executed; the services turn the run into a CC1 file equal to `ncbridge convert` of the
# program (but for FILE_NAME), and the number of blocks published is the number executed.
source "$(dirname "$0")/lib.sh"

cat > "$WORK/flow.ngc" <<'NGC'
(a loop, a branch and a subroutine with arguments)
G21 G17 G90 G94 G54
o100 sub
  G1 X#1 Y#2 F200
  G1 Z[-#3]
  G0 Z5
o100 endsub
T1 M6
S1200 M3
G0 X0 Y0 Z5
#<pass> = 0
o101 while [#<pass> lt 3]
  G1 Z-1 F100
  G1 X[#<pass> * 10] Y5
  o102 if [#<pass> eq 1]
    G2 X[#<pass> * 10 + 4] Y5 I2 J0
  o102 else
    G1 Y10
  o102 endif
  G0 Z5
  #<pass> = [#<pass> + 1]
o101 endwhile
o100 call [7] [8] [1.5]
o100 call [20] [#<pass>] [2]
G0 Z10
M5
M30
NGC
# Executed blocks: 6 before the loop (G21, T1, S, G0, #<pass>, and the comment), 3 passes of 5
# (G1, G1, G2 or G1, G0, #<pass>), 2 calls of 1 parameter line + 3 blocks, then G0, M5, M30.
expected_blocks=$(( 6 + 3 * 5 + 2 * 4 + 3 ))

timeout 60 "$BIN/ncbridge" convert "$WORK/flow.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" -o "$WORK/flow.stp" \
  2> "$WORK/convert.log" || fail "convert rejects the program"
start up "$BIN/ncbridge" up --workers 1 --live-tools "$TOOLS_PAPER" --live-stock "$STOCK_PAPER"
wait_workers 1
timeout 60 "$BIN/ncbridge" controller-sim "$WORK/flow.ngc" --controller mill1 --run-id r1 --tools "$TOOLS_PAPER" \
  -o "$WORK/live.stp" > /dev/null 2> "$WORK/sim.log" || fail "controller-sim failed: $(cat "$WORK/sim.log")"
grep -q "^$expected_blocks blocks executed" "$WORK/sim.log" || fail "expected $expected_blocks blocks executed: $(cat "$WORK/sim.log")"
diff <(grep -v FILE_NAME "$WORK/flow.stp") <(grep -v FILE_NAME "$WORK/live.stp") > "$WORK/diff.log" \
  || fail "the live run's file differs from ncbridge convert: $(head -n 20 "$WORK/diff.log")"
echo "PASS: $expected_blocks blocks executed and published (loop, branch, calls expanded); live CC1 equals convert's"
