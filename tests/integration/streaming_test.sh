#!/usr/bin/env bash
# Streaming between stages: a long program's canonical batches reach the cc1_builder while the
# interpreter is still at work (the cc1_builder reports RUNNING before the interpreter reports
# DONE), and the streamed result is byte-identical to `ncbridge convert`, for CC1 and for CC2
# (the model crosses the workingsteps and features topics as a shell and chunks).
source "$(dirname "$0")/lib.sh"

generate_program 3 60000 > "$WORK/long.ngc"
timeout 120 "$BIN/ncbridge" convert "$WORK/long.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" -o "$WORK/long.stp" \
  2> "$WORK/convert.log"
part="$SHARED/corpus/cam/p01_block_reference"
timeout 120 "$BIN/ncbridge" convert "$part/part.nc" --tools "$part/tools.json" --stock "$part/stock.json" --level cc2 \
  -o "$WORK/part.stp" 2> "$WORK/convert-cc2.log"

mkdir -p "$WORK/services"   # same file names as convert's: FILE_NAME.name is the output's name
start up "$BIN/ncbridge" up --workers 1
wait_workers 1

# Not a terminal: submit prints every status line as it comes, in order.
timeout 120 "$BIN/ncbridge" submit "$WORK/long.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id long \
  --wait -o "$WORK/services/long.stp" 2> "$WORK/submit-long.log" > /dev/null || fail "the long job failed: $(cat "$WORK/submit-long.log")"
cmp -s "$WORK/long.stp" "$WORK/services/long.stp" || fail "the streamed CC1 file differs from ncbridge convert"
builder_running=$(grep -n "^cc1_builder: running" "$WORK/submit-long.log" | head -n 1 | cut -d: -f1)
interpreter_done=$(grep -n "^interpreter: done" "$WORK/submit-long.log" | head -n 1 | cut -d: -f1)
[[ -n $builder_running && -n $interpreter_done ]] || fail "statuses missing: $(cat "$WORK/submit-long.log")"
(( builder_running < interpreter_done )) || fail "the cc1_builder started only after the interpreter was done: $(cat "$WORK/submit-long.log")"

timeout 120 "$BIN/ncbridge" submit "$part/part.nc" --tools "$part/tools.json" --stock "$part/stock.json" --level cc2 \
  --job-id part-cc2 --wait -o "$WORK/services/part.stp" 2> "$WORK/submit-cc2.log" > /dev/null || fail "the CC2 job failed"
cmp -s "$WORK/part.stp" "$WORK/services/part.stp" || fail "the streamed CC2 file differs from ncbridge convert --level cc2"
echo "PASS: cc1_builder running (status line $builder_running) before the interpreter was done (line $interpreter_done); CC1 and CC2 byte-identical"
