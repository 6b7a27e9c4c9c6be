#!/usr/bin/env bash
# Results leave the bus once delivered: a client that waited for its job says so (a "delivered"
# status) and the step writer drops the file, so a reader that comes later is not sent it (every
# new client would otherwise receive every file kept, up to --retain-mb). A job nobody waited
# for keeps its file on the bus, under the retention policy.
source "$(dirname "$0")/lib.sh"

start up "$BIN/ncbridge" up
wait_workers 1
generate_program 1 > "$WORK/a.ngc"
generate_program 2 > "$WORK/b.ngc"
timeout 60 "$BIN/ncbridge" submit "$WORK/a.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id waited \
  --wait -o "$WORK/a.stp" > /dev/null 2>&1 || fail "the waited job failed"
[[ -s "$WORK/a.stp" ]] || fail "no file for the waited job"
timeout 60 "$BIN/ncbridge" submit "$WORK/b.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id unwaited \
  > /dev/null 2>&1 || fail "the job without --wait was not taken"
for _ in $(seq 1 50); do
  "$BIN/ncbridge" status --listen 0.3 2>/dev/null | grep -q "unwaited.*step_writer:done" && break
  sleep 0.2
done
late=$("$BIN/bus_inject" results-of unwaited)
echo "$late"
grep -Eq "^unwaited: [1-9][0-9]* pieces, last$" <<<"$late" || fail "the file nobody waited for is not kept on the bus"
late=$("$BIN/bus_inject" results-of waited)
echo "$late"
grep -q "^waited: 0 pieces$" <<<"$late" || fail "a late reader is still sent the file its client already has"
echo "PASS: a delivered file left the bus, one nobody waited for is kept"
