#!/usr/bin/env bash
# Retention: finished jobs do not stay on the bus for ever. With --retain-jobs 2 every worker
# keeps the statuses (and the step writer the results) of its last 2 jobs over: after 4 jobs a
# late reader (`ncbridge status`) sees 2 jobs, the last two; with --retain-for 8 they are gone
# once 8 s have passed. The bounds are given to `ncbridge up`, which hands them to every service.
source "$(dirname "$0")/lib.sh"

start up "$BIN/ncbridge" up --retain-jobs 2 --retain-for 8
wait_workers 1
for k in 1 2 3 4; do
  generate_program "$k" > "$WORK/r$k.ngc"
  timeout 60 "$BIN/ncbridge" submit "$WORK/r$k.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --job-id "kept$k" \
    --wait -o "$WORK/r$k.stp" > /dev/null 2>&1 || fail "job $k failed"
done
status=$("$BIN/ncbridge" status --listen 1)
echo "$status"
grep -q "^jobs: 2$" <<<"$status" || fail "a late reader sees $(grep '^jobs:' <<<"$status"), not the last 2 jobs"
grep -q "kept3" <<<"$status" && grep -q "kept4" <<<"$status" || fail "the 2 jobs kept are not the last two"
sleep 9
status=$("$BIN/ncbridge" status --listen 1)
grep -q "^jobs: 0$" <<<"$status" || fail "jobs older than --retain-for are still on the bus: $status"
echo "PASS: 2 of 4 jobs kept (the last two), none after --retain-for"
