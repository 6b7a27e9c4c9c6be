#!/usr/bin/env bash
# Streaming between stages: a long program's canonical batches reach the cc1_builder while the
# interpreter is still at work (the cc1_builder starts the job before the interpreter is done), and the streamed result is byte-identical to `ncbridge convert`, for CC1 and for CC2
# (the model crosses the workingsteps and features topics as a shell and chunks).
source "$(dirname "$0")/lib.sh"

generate_program 3 60000 > "$WORK/long.ngc"
timeout 120 "$BIN/ncbridge" convert "$WORK/long.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" -o "$WORK/long.stp" \
  2> "$WORK/convert.log"
part="$SHARED/corpus/cam/p01_block_reference"
timeout 120 "$BIN/ncbridge" convert "$part/part.nc" --tools "$part/tools.json" --stock "$part/stock.json" --level cc2 \
  -o "$WORK/part.stp" 2> "$WORK/convert-cc2.log"

mkdir -p "$WORK/services"   # same file names as convert's: FILE_NAME.name is the output's name
start up "$BIN/ncbridge" up --workers 1 --log-level info   # the stages' own lines, read below
wait_workers 1

timeout 120 "$BIN/ncbridge" submit "$WORK/long.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id long \
  --wait -o "$WORK/services/long.stp" 2> "$WORK/submit-long.log" > /dev/null || fail "the long job failed: $(cat "$WORK/submit-long.log")"
cmp -s "$WORK/long.stp" "$WORK/services/long.stp" || fail "the streamed CC1 file differs from ncbridge convert"
# The services' own log (one clock, ms): the cc1_builder started the job before the interpreter
# finished it. (The client's status lines cannot tell: statuses of different stages may reach it
# in any order.)
builder_started=$(grep -h "cc1_builder\[.*job long: started" "$WORK/up.log" | cut -d' ' -f1)
interpreter_done=$(grep -h "interpreter\[.*job long: done in" "$WORK/up.log" | cut -d' ' -f1)
[[ -n $builder_started && -n $interpreter_done ]] || fail "no start/done lines in the services' log"
[[ $builder_started < $interpreter_done ]] || fail "the cc1_builder started ($builder_started) only after the interpreter was done ($interpreter_done)"

timeout 120 "$BIN/ncbridge" submit "$part/part.nc" --tools "$part/tools.json" --stock "$part/stock.json" --level cc2 \
  --job-id part-cc2 --wait -o "$WORK/services/part.stp" 2> "$WORK/submit-cc2.log" > /dev/null || fail "the CC2 job failed"
cmp -s "$WORK/part.stp" "$WORK/services/part.stp" || fail "the streamed CC2 file differs from ncbridge convert --level cc2"
echo "PASS: cc1_builder started at $builder_started, before the interpreter was done at $interpreter_done; CC1 and CC2 byte-identical"
