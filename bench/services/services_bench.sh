#!/usr/bin/env bash
# Whole-program timings of the DDS services against the embedded pipeline (docs/performance.md,
# "Services"). Wall-clock figures, so a benchmark, never a test. Every figure is the median of
# REPEAT runs, services and embedded interleaved, so load from other work hits both alike.
#   bench/services/services_bench.sh BIN_DIR [BATCH] [LARGE_LINES] [REPEAT]
# 1. one large program: `ncbridge convert` vs `ncbridge submit --wait` to one worker per stage
#    (services already up: start-up is not counted);
# 2. a batch of BATCH programs (default 200): `convert` one after the other and two at a time
#    (2 cores), vs one bulk `ncbridge submit` of all of them (one participant) to the services
#    with 1 and with 2 workers per stage. SUBMIT=clients submits them with 10 concurrent
#    single-program clients instead (what the old bench did; also for binaries without bulk submit);
# 3. live capture: time from a controller's RUN_END to its CC1 file (controller-sim reports it).
# Every services output is compared with the embedded one (byte-identical, same SOURCE_DATE_EPOCH).
# `up` is given this script's Cyclone configuration (CYCLONEDDS_URI).
set -euo pipefail
BIN=$(cd "$1" && pwd); BATCH=${2:-200}; LARGE=${3:-100000}; REPEAT=${4:-3}; SUBMIT=${SUBMIT:-bulk}
BATCH_LINES=${BATCH_LINES:-2000}  # G1+G2 pairs per batch program (4008 lines at 2000); LARGE=0 skips part 1, BATCH=0 the rest
# LARGE_SPLIT=N: the large program lifts, moves and plunges again every N pairs, so it is many
# workingsteps (default 0: one huge workingstep)
LARGE_SPLIT=${LARGE_SPLIT:-0}
SHARED=${SHARED:-$(cd "$(dirname "$0")/../../.." && pwd)/shared}
T="$SHARED/corpus/paper/tools.json" S="$SHARED/corpus/paper/stock.json"
W=$(mktemp -d /tmp/ncbridge-bench.XXXXXX)
UP=""
trap '[[ -n $UP ]] && kill $UP 2>/dev/null; wait 2>/dev/null; rm -rf "$W"' EXIT
export NCBRIDGE_DDS_DOMAIN=$(( 20 + $$ % 200 )) SOURCE_DATE_EPOCH=1700000000
# The loopback configuration of deploy/cyclonedds/loopback.xml; DDS_TUNING=0 leaves out its
# large datagrams and writer buffers (Cyclone's defaults, as before they were added).
if [[ ${DDS_TUNING:-1} == 1 ]]; then
  SIZES='<MaxMessageSize>65000B</MaxMessageSize><FragmentSize>62000B</FragmentSize>'
  INTERNAL='<Internal><Watermarks><WhcHigh>8MB</WhcHigh></Watermarks><HeartbeatInterval>10ms</HeartbeatInterval><SocketReceiveBufferSize min="default" max="8MB"/><SocketSendBufferSize min="default" max="8MB"/></Internal>'
else
  SIZES='' INTERNAL=''
fi
cat > "$W/lo.xml" <<XML
<CycloneDDS xmlns="https://cdds.io/config"><Domain id="any">
<General><Interfaces><NetworkInterface name="lo" multicast="true"/></Interfaces>$SIZES</General>
<Discovery><LeaseDuration>1s</LeaseDuration></Discovery><SharedMemory><Enable>false</Enable></SharedMemory>
$INTERNAL
</Domain></CycloneDDS>
XML
export CYCLONEDDS_URI="file://$W/lo.xml"
now() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
gen() {  # K LINES
  echo "G21 G17 G90 G94 G54"; echo "T1 M6"; echo "S$((1000 + $1)) M3"; echo "G0 X0 Y0 Z10"; echo "G1 Z-1 F300"
  awk -v n="$2" -v k="$1" -v every="${3:-0}" 'BEGIN { for (i = 0; i < n; i++) {
    if (every > 0 && i > 0 && i % every == 0) printf "G0 Z10\nG0 X%.3f Y%.3f\nG1 Z-1 F300\n", (i*7+k)%80, (i*3)%50
    printf "G1 X%.3f Y%.3f\nG2 X%.3f Y%.3f I2 J0\n", (i*7+k)%80, (i*3)%50, (i*7+k)%80+4, (i*3)%50 } }'
  echo "G0 Z10"; echo "M5"; echo "M30"
}
up() {  # WORKERS
  "$BIN/ncbridge" up --workers "$1" --log-level warn --live-tools "$T" --live-stock "$S" > "$W/up.log" 2>&1 & UP=$!
  for _ in $(seq 1 50); do
    [[ $("$BIN/ncbridge" status --listen 0.3 2>/dev/null | grep -Ec "^  [a-z0-9_]+ +$1 live") == 4 ]] && return 0
  done
  echo "services did not come up" >&2; exit 1
}
down() { kill "$UP"; wait "$UP" 2>/dev/null || true; UP=""; }
same() {  # A B: byte-identical but for FILE_NAME (the names differ)
  cmp -s <(grep -v FILE_NAME "$1") <(grep -v FILE_NAME "$2") || echo "WARNING: $1 and $2 differ" >&2
}

# 1. One large program.
if (( LARGE > 0 )); then
gen 1 "$LARGE" "$LARGE_SPLIT" > "$W/large.ngc"
up 1
: > "$W/large-embedded.t"; : > "$W/large-services.t"
for _ in $(seq 1 "$REPEAT"); do
  t0=$(now); "$BIN/ncbridge" convert "$W/large.ngc" --tools "$T" --stock "$S" -o "$W/large-embedded.stp" 2>/dev/null; t1=$(now)
  echo "$t1 - $t0" | bc >> "$W/large-embedded.t"
  t0=$(now); "$BIN/ncbridge" submit "$W/large.ngc" --tools "$T" --stock "$S" --wait -o "$W/large-services.stp" > /dev/null 2>&1; t1=$(now)
  echo "$t1 - $t0" | bc >> "$W/large-services.t"
done
down
same "$W/large-embedded.stp" "$W/large-services.stp"
embedded=$(median < "$W/large-embedded.t"); services=$(median < "$W/large-services.t")
printf 'large program (%d lines, %s bytes out): embedded %.2f s, services %.2f s, ratio %.2f  [runs: embedded %s; services %s]\n' \
  "$(wc -l < "$W/large.ngc")" "$(stat -c %s "$W/large-embedded.stp")" "$embedded" "$services" "$(echo "$services / $embedded" | bc -l)" \
  "$(tr '\n' ' ' < "$W/large-embedded.t")" "$(tr '\n' ' ' < "$W/large-services.t")"
fi
(( BATCH > 0 )) || exit 0

# 2. A batch.
mkdir -p "$W/batch" "$W/emb"
for k in $(seq 1 "$BATCH"); do gen "$k" "$BATCH_LINES" > "$W/batch/p$k.ngc"; done
embedded_loop() {
  local t0 t1; t0=$(now)
  for k in $(seq 1 "$BATCH"); do "$BIN/ncbridge" convert "$W/batch/p$k.ngc" --tools "$T" --stock "$S" -o "$W/emb/p$k.stp" 2>/dev/null; done
  t1=$(now); echo "$t1 - $t0" | bc
}
embedded_pair() {  # two converts at a time: what the 2 cores give without DDS
  local t0 t1; t0=$(now)
  seq 1 "$BATCH" | xargs -P 2 -I{} "$BIN/ncbridge" convert "$W/batch/p{}.ngc" --tools "$T" --stock "$S" -o "$W/emb/p{}.stp" 2>/dev/null
  t1=$(now); echo "$t1 - $t0" | bc
}
services_batch() {  # WORKERS (services up already): prints the seconds
  local out="$W/s$1" t0 t1
  rm -rf "$out"; mkdir -p "$out"
  t0=$(now)
  if [[ $SUBMIT == bulk ]]; then
    "$BIN/ncbridge" submit "$W/batch" --tools "$T" --stock "$S" --wait --output-dir "$out" > /dev/null 2> "$W/submit.log" \
      || { tail -n 3 "$W/submit.log" >&2; }
  else
    for c in $(seq 0 9); do
      ( for k in $(seq $((c + 1)) 10 "$BATCH"); do
          "$BIN/ncbridge" submit "$W/batch/p$k.ngc" --tools "$T" --stock "$S" --wait -o "$out/p$k.stp" > /dev/null 2>&1
        done ) &
    done
    wait $(jobs -p | grep -v "^$UP$") 2>/dev/null || true
  fi
  t1=$(now)
  for k in $(seq 1 "$BATCH"); do same "$W/emb/p$k.stp" "$out/p$k.stp"; done
  echo "$t1 - $t0" | bc
}
: > "$W/loop.t"; : > "$W/pair.t"; : > "$W/s1.t"; : > "$W/s2.t"
for _ in $(seq 1 "$REPEAT"); do
  embedded_loop >> "$W/loop.t"
  embedded_pair >> "$W/pair.t"
  up 1; services_batch 1 >> "$W/s1.t"; down
  up 2; services_batch 2 >> "$W/s2.t"; down
done
loop=$(median < "$W/loop.t"); pair=$(median < "$W/pair.t"); b1=$(median < "$W/s1.t"); b2=$(median < "$W/s2.t")
printf 'batch of %d programs (%d lines each, submit=%s): embedded loop %.2f s, embedded 2 at a time %.2f s, services 1 worker/stage %.2f s, 2 workers/stage %.2f s\n' \
  "$BATCH" "$(wc -l < "$W/batch/p1.ngc")" "$SUBMIT" "$loop" "$pair" "$b1" "$b2"
printf '  speed-up 2 vs 1 worker: %.2f; services 1 worker / embedded loop: %.2f; services 2 workers / embedded 2 at a time: %.2f; embedded 2 at a time vs loop: %.2f\n' \
  "$(echo "$b1 / $b2" | bc -l)" "$(echo "$b1 / $loop" | bc -l)" "$(echo "$b2 / $pair" | bc -l)" "$(echo "$loop / $pair" | bc -l)"
printf '  [runs: loop %s; pair %s; 1 worker %s; 2 workers %s]\n' "$(tr '\n' ' ' < "$W/loop.t")" "$(tr '\n' ' ' < "$W/pair.t")" \
  "$(tr '\n' ' ' < "$W/s1.t")" "$(tr '\n' ' ' < "$W/s2.t")"

# 3. Live capture.
up 1
gen 7 2000 > "$W/live.ngc"
for i in 1 2 3; do
  "$BIN/ncbridge" controller-sim "$W/live.ngc" --controller bench --run-id "r$i" -o "$W/live$i.stp" 2>&1 >/dev/null | tail -n 1
done
down
