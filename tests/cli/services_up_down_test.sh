#!/usr/bin/env bash
# `ncbridge up --detach` records where it runs, and the other commands find it with no export
# (no CYCLONEDDS_URI, no NCBRIDGE_DDS_DOMAIN): submit (byte-identical to convert), status,
# controller-sim with a LinuxCNC tool table (up --live-tool-table); up's log holds one line per
# job; a second up on its domain is refused; `down` stops it and its services and removes the
# record; a foreground up killed (SIGKILL) takes its services with it; --domain wins over the record, and with two
# ups running a command must be told which; a stale record (its process gone) is ignored and removed.
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$HERE/../integration/lib.sh"
DOMAIN=$NCBRIDGE_DDS_DOMAIN
DOMAIN2=$(( (DOMAIN + 1) % 231 ))
unset NCBRIDGE_DDS_DOMAIN CYCLONEDDS_URI
export XDG_RUNTIME_DIR="$WORK/run"
mkdir -m 700 "$XDG_RUNTIME_DIR"
N="$BIN/ncbridge"
EX="$SOURCE_DIR/examples/plate"
REC="$XDG_RUNTIME_DIR/ncbridge/up-$DOMAIN.json"
# Running, not a zombie (the background up's parent exited; whoever adopts it may reap it late).
alive() { [[ -r /proc/$1/stat ]] && ! grep -q ') [ZX] ' "/proc/$1/stat"; }
down_on_exit() { "$N" down --domain "$DOMAIN" > /dev/null 2>&1 || true; }
CLEANUP_HOOKS+=(down_on_exit)

mkdir "$WORK/expected"
"$N" convert "$EX/plate.ngc" --tools "$EX/tools.json" --stock "$EX/stock.json" --level cc2 -o "$WORK/expected/plate.stp" 2> /dev/null

timeout 120 "$N" up --detach --domain "$DOMAIN" --workers 1 --output-dir "$WORK/out" \
  --live-tool-table "$EX/tools.tbl" --live-tool-table-units inch --live-stock "$EX/stock.json" > "$WORK/up.out" 2> "$WORK/up.err" \
  || fail "up --detach failed: $(cat "$WORK/up.out" "$WORK/up.err")"
grep -q "^ncbridge up: 4 services on DDS domain $DOMAIN (pid [0-9]*, log " "$WORK/up.out" || fail "up said: $(cat "$WORK/up.out")"
[[ -f "$REC" ]] || fail "no record $REC"
UP_PID=$(sed -n 's/.*"pid": \([0-9]*\).*/\1/p' "$REC")
kill -0 "$UP_PID" || fail "the recorded up (pid $UP_PID) does not run"
LOG=$(sed -n 's/.*"log": "\(.*\)".*/\1/p' "$REC")
SERVICES=$(pgrep -P "$UP_PID" | tr '\n' ' ')
[[ $(wc -w <<<"$SERVICES") == 4 ]] || fail "up runs $(wc -w <<<"$SERVICES") services, not 4"

rc=0
"$N" up --detach --domain "$DOMAIN" > /dev/null 2> "$WORK/second.err" || rc=$?
[[ $rc == 2 ]] && grep -q "already runs on DDS domain $DOMAIN" "$WORK/second.err" || fail "a second up: exit $rc, $(cat "$WORK/second.err")"

# No export: the record says where.
timeout 60 "$N" submit "$EX/plate.ngc" --tools "$EX/tools.json" --stock "$EX/stock.json" --level cc2 --wait -o "$WORK/plate.stp" \
  --job-id plate-1 > /dev/null 2> "$WORK/submit.err" || fail "submit without exports: $(cat "$WORK/submit.err")"
cmp "$WORK/plate.stp" "$WORK/expected/plate.stp" || fail "submit's plate.stp differs from convert's"
timeout 60 "$N" controller-sim "$EX/plate.ngc" --controller mill1 --run-id r1 --tool-table "$EX/tools.tbl" \
  --tool-table-units inch -o "$WORK/run.stp" > /dev/null 2> "$WORK/sim.err" || fail "controller-sim: $(cat "$WORK/sim.err")"
grep -q "FILE_SCHEMA" "$WORK/run.stp" || fail "controller-sim wrote no Part 21 file"
"$N" status --listen 1 > "$WORK/status.txt"
grep -q "^workers (DDS domain $DOMAIN)" "$WORK/status.txt" || fail "status did not find the domain: $(cat "$WORK/status.txt")"
grep -Eq "^  plate-1 .*step_writer:done" "$WORK/status.txt" || fail "status does not list plate-1 done: $(cat "$WORK/status.txt")"
for _ in $(seq 1 50); do grep -Eq "^[0-9:]{8} mill1/r1: done$" "$LOG" && break; sleep 0.1; done
[[ $(grep -Ec "^[0-9:]{8} plate-1: done$" "$LOG") == 1 && $(grep -c "plate-1" "$LOG") == 1 ]] || fail "up's log does not hold one line for plate-1: $(cat "$LOG")"
grep -Eq "^[0-9:]{8} mill1/r1: done$" "$LOG" || fail "up's log has no line for the run: $(cat "$LOG")"
if grep -q "job plate-1: started" "$LOG"; then fail "up's log holds the services' per-stage lines without -v"; fi

# The user's word wins over the record.
"$N" status --domain "$DOMAIN2" --listen 0.3 > "$WORK/status_other.txt"
grep -q "^workers (DDS domain $DOMAIN2)" "$WORK/status_other.txt" || fail "--domain did not win: $(cat "$WORK/status_other.txt")"
# A second up, in the foreground on another domain: the commands no longer guess which.
start fg "$N" up --domain "$DOMAIN2"
for _ in $(seq 1 100); do [[ -f "$XDG_RUNTIME_DIR/ncbridge/up-$DOMAIN2.json" ]] && break; sleep 0.1; done
[[ -f "$XDG_RUNTIME_DIR/ncbridge/up-$DOMAIN2.json" ]] || fail "the foreground up wrote no record: $(cat "$WORK/fg.log")"
rc=0
"$N" status --listen 0.2 > /dev/null 2> "$WORK/several.err" || rc=$?
[[ $rc == 2 ]] && grep -q "several .ncbridge up. run on this machine (DDS domains" "$WORK/several.err" \
  || fail "status with two ups: exit $rc, $(cat "$WORK/several.err")"
# Killed (SIGKILL): its services follow it, its record is stale: ignored, then removed.
FG=$(service_pid "$STARTED_PID")
FG_SERVICES=$(pgrep -P "$FG" | tr '\n' ' ')
[[ $(wc -w <<<"$FG_SERVICES") == 4 ]] || fail "the foreground up runs $(wc -w <<<"$FG_SERVICES") services, not 4"
kill -KILL "$FG"
for pid in $FG_SERVICES; do
  for _ in $(seq 1 100); do alive "$pid" || break; sleep 0.1; done
  ! alive "$pid" || fail "service $pid still runs 10 s after its up was killed"
done
"$N" status --listen 0.2 > "$WORK/after_kill.txt" 2>&1 || fail "status after an up was killed: $(cat "$WORK/after_kill.txt")"
grep -q "^workers (DDS domain $DOMAIN)" "$WORK/after_kill.txt" || fail "status did not take the live up: $(cat "$WORK/after_kill.txt")"
[[ ! -f "$XDG_RUNTIME_DIR/ncbridge/up-$DOMAIN2.json" ]] || fail "the killed up's record was not removed"

timeout 60 "$N" down > "$WORK/down.out" 2>&1 || fail "down: $(cat "$WORK/down.out")"
grep -q "stopped ncbridge up on DDS domain $DOMAIN" "$WORK/down.out" || fail "down said: $(cat "$WORK/down.out")"
! alive "$UP_PID" || fail "up still runs after down"
for pid in $SERVICES; do ! alive "$pid" || fail "service $pid still runs after down"; done
[[ ! -e "$REC" ]] || fail "down left the record"
[[ ! -e "$XDG_RUNTIME_DIR/ncbridge/up-$DOMAIN-cyclonedds.xml" ]] || fail "up left its Cyclone configuration"
"$N" down > "$WORK/down2.out" 2>&1 || fail "down with nothing running failed"
grep -q "no ncbridge up runs" "$WORK/down2.out" || fail "down with nothing running said: $(cat "$WORK/down2.out")"

# A stale record: its process is gone. Ignored (no service answers on a domain nobody runs) and removed.
true & dead=$!
wait "$dead"
printf '{"pid": %d, "start_time": 1, "domain": %d, "cyclonedds_uri": "file:///nonexistent.xml"}\n' "$dead" "$DOMAIN" > "$REC"
rc=0
timeout 60 "$N" status --listen 0.2 > "$WORK/stale.txt" 2>&1 || rc=$?
[[ $rc == 0 ]] || fail "status with a stale record: exit $rc, $(cat "$WORK/stale.txt")"
[[ ! -e "$REC" ]] || fail "the stale record was not removed"
echo "PASS: up --detach found without exports, one log line per job, down, stale record"
