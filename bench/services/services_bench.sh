#!/usr/bin/env bash
# Whole-program timings of the DDS services against the embedded pipeline (docs/performance.md,
# "Services"). Wall-clock figures, so a benchmark, never a test.
#   bench/services/services_bench.sh BIN_DIR [BATCH] [LARGE_LINES]
# 1. one large program: `ncbridge convert` vs `ncbridge submit --wait` to one worker per stage;
# 2. a batch of BATCH programs (default 200): convert in a loop, vs the services with 1 and 2
#    workers per stage (all jobs submitted at once, 10 submit clients);
# 3. live capture: time from a controller's RUN_END to its CC2 file (controller-sim reports it).
set -euo pipefail
BIN=$(cd "$1" && pwd); BATCH=${2:-200}; LARGE=${3:-200000}
SHARED=${SHARED:-$(cd "$(dirname "$0")/../../.." && pwd)/shared}
T="$SHARED/corpus/paper/tools.json" S="$SHARED/corpus/paper/stock.json"
W=$(mktemp -d /tmp/ncbridge-bench.XXXXXX)
UP=""
trap '[[ -n $UP ]] && kill $UP 2>/dev/null; wait 2>/dev/null; rm -rf "$W"' EXIT
export NCBRIDGE_DDS_DOMAIN=$(( 20 + $$ % 200 )) SOURCE_DATE_EPOCH=1700000000
cat > "$W/lo.xml" <<XML
<CycloneDDS xmlns="https://cdds.io/config"><Domain id="any">
<General><Interfaces><NetworkInterface name="lo" multicast="true"/></Interfaces></General>
<Discovery><LeaseDuration>1s</LeaseDuration></Discovery><SharedMemory><Enable>false</Enable></SharedMemory>
</Domain></CycloneDDS>
XML
export CYCLONEDDS_URI="file://$W/lo.xml"
now() { date +%s.%N; }
gen() {  # K LINES
  echo "G21 G17 G90 G94 G54"; echo "T1 M6"; echo "S$((1000 + $1)) M3"; echo "G0 X0 Y0 Z10"; echo "G1 Z-1 F300"
  awk -v n="$2" -v k="$1" 'BEGIN { for (i = 0; i < n; i++) printf "G1 X%.3f Y%.3f\nG2 X%.3f Y%.3f I2 J0\n", (i*7+k)%80, (i*3)%50, (i*7+k)%80+4, (i*3)%50 }'
  echo "G0 Z10"; echo "M5"; echo "M30"
}
up() { "$BIN/ncbridge" up --workers "$1" --log-level warn --live-tools "$T" --live-stock "$S" > "$W/up.log" 2>&1 & UP=$!; sleep 2; }
down() { kill "$UP"; wait "$UP" 2>/dev/null || true; UP=""; }

gen 1 "$LARGE" > "$W/large.ngc"
t0=$(now); "$BIN/ncbridge" convert "$W/large.ngc" --tools "$T" --stock "$S" -o "$W/large-embedded.stp" 2>/dev/null; t1=$(now)
embedded=$(echo "$t1 - $t0" | bc)
up 1
t0=$(now); "$BIN/ncbridge" submit "$W/large.ngc" --tools "$T" --stock "$S" --wait -o "$W/large-services.stp" > /dev/null 2>&1; t1=$(now)
services=$(echo "$t1 - $t0" | bc)
cmp -s <(grep -v FILE_NAME "$W/large-embedded.stp") <(grep -v FILE_NAME "$W/large-services.stp") || echo "WARNING: large outputs differ"
printf 'large program (%d lines, %s bytes out): embedded %.2f s, services %.2f s, ratio %.2f\n' \
  "$(wc -l < "$W/large.ngc")" "$(stat -c %s "$W/large-embedded.stp")" "$embedded" "$services" "$(echo "$services / $embedded" | bc -l)"
down

mkdir -p "$W/batch"
for k in $(seq 1 "$BATCH"); do gen "$k" 2000 > "$W/batch/p$k.ngc"; done
t0=$(now); for k in $(seq 1 "$BATCH"); do "$BIN/ncbridge" convert "$W/batch/p$k.ngc" --tools "$T" --stock "$S" -o "$W/batch/p$k.stp" 2>/dev/null; done; t1=$(now)
batch_embedded=$(echo "$t1 - $t0" | bc)
batch_services() {  # WORKERS
  up "$1"
  local t0 t1
  t0=$(now)
  for c in $(seq 0 9); do
    ( for k in $(seq $((c + 1)) 10 "$BATCH"); do
        "$BIN/ncbridge" submit "$W/batch/p$k.ngc" --tools "$T" --stock "$S" --wait -o "$W/batch/s$k.stp" > /dev/null 2>&1
      done ) &
  done
  wait $(jobs -p | grep -v "^$UP$") 2>/dev/null || true
  t1=$(now)
  down
  echo "$t1 - $t0" | bc
}
b1=$(batch_services 1); b2=$(batch_services 2)
printf 'batch of %d programs (%d lines each): embedded loop %.2f s, services 1 worker/stage %.2f s, 2 workers/stage %.2f s, speed-up 2 vs 1: %.2f\n' \
  "$BATCH" "$(wc -l < "$W/batch/p1.ngc")" "$batch_embedded" "$b1" "$b2" "$(echo "$b1 / $b2" | bc -l)"

up 1
gen 7 2000 > "$W/live.ngc"
for i in 1 2 3; do
  "$BIN/ncbridge" controller-sim "$W/live.ngc" --controller bench --run-id "r$i" -o "$W/live$i.stp" 2>&1 >/dev/null | tail -n 1
done
down
