#!/usr/bin/env bash
# What a worker costs (docs/performance.md, "Scale-out"): the same batch of BATCH generated
# programs (4,008 lines each) submitted at once (`ncbridge submit --list ... --level cc1 --wait`)
# to `ncbridge up --workers N` for each N of COUNTS, on loopback (deploy/cyclonedds/loopback.xml).
# For each N it reports, over the batch only (start-up and discovery not counted):
#  - the CPU seconds (user + system) of all service processes together, from /proc/PID/stat
#    before and after, and that as a ratio to the first N (the reference, same session);
#  - the bytes each worker received on its sockets (mean and max per stage), counted by a
#    preloaded shim (libncbridge_net_counters.so: recvmsg/recvfrom), and the client's CPU.
# Every N's output folder must be byte-identical to the first N's (else the script fails).
# CPU and bytes, not wall time: 2 cores cannot show a speed-up past 2 processes, but they show
# what each worker costs.
#   bench/scaleout/run.sh BIN_DIR [BATCH] [COUNTS]        e.g. build/bin 200 "1 2 4 8"
# NET_COUNTERS_LIB: the shim (default BIN_DIR/../lib/libncbridge_net_counters.so; give it when
# BIN_DIR is another build, e.g. an older one for before figures). LINES: G1+G2 pairs a program.
set -euo pipefail
BIN=$(cd "$1" && pwd); BATCH=${2:-200}; COUNTS=${3:-"1 2 4 8"}; LINES=${LINES:-2000}
HERE=$(cd "$(dirname "$0")" && pwd)
LIB=${NET_COUNTERS_LIB:-$BIN/../lib/libncbridge_net_counters.so}
[[ -f $LIB ]] || { echo "no $LIB: build the ncbridge_net_counters target" >&2; exit 2; }
LIB=$(cd "$(dirname "$LIB")" && pwd)/$(basename "$LIB")
SHARED=${SHARED:-$(cd "$HERE/../../.." && pwd)/shared}
T="$SHARED/corpus/paper/tools.json" S="$SHARED/corpus/paper/stock.json"
W=$(mktemp -d /tmp/ncbridge-scaleout.XXXXXX)
UP=""
trap '[[ -n $UP ]] && kill $UP 2>/dev/null; wait 2>/dev/null; rm -rf "$W"' EXIT
export NCBRIDGE_DDS_DOMAIN=$(( 20 + $$ % 200 )) SOURCE_DATE_EPOCH=1700000000
export CYCLONEDDS_URI="file://$HERE/../../deploy/cyclonedds/loopback.xml"
TICK=$(getconf CLK_TCK)

gen() {  # K: the services bench's batch program (4008 lines at LINES=2000)
  echo "G21 G17 G90 G94 G54"; echo "T1 M6"; echo "S$((1000 + $1)) M3"; echo "G0 X0 Y0 Z10"; echo "G1 Z-1 F300"
  awk -v n="$LINES" -v k="$1" 'BEGIN { for (i = 0; i < n; i++)
    printf "G1 X%.3f Y%.3f\nG2 X%.3f Y%.3f I2 J0\n", (i*7+k)%80, (i*3)%50, (i*7+k)%80+4, (i*3)%50 }'
  echo "G0 Z10"; echo "M5"; echo "M30"
}
mkdir -p "$W/programs"
: > "$W/list"
for k in $(seq 1 "$BATCH"); do
  gen "$k" > "$W/programs/p$k.ngc"
  echo "programs/p$k.ngc $T $S" >> "$W/list"
done
input_bytes=$(cat "$W"/programs/*.ngc | wc -c)

# snapshot PIDS...: "pid stage cpu_ticks received_bytes received_datagrams" per process.
snapshot() {
  local pid stage ticks
  for pid in "$@"; do
    stage=$(tr '\0' '\n' < "/proc/$pid/cmdline" | head -n 1)
    stage=${stage##*/ncbridge-}
    ticks=$(sed 's/^.*) //' "/proc/$pid/stat" | awk '{ print $12 + $13 }')
    read -r rb rn _ < <(od -An -t u8 -N 32 -w32 "$W/net/$pid" 2>/dev/null || echo "0 0 0 0")
    echo "$pid $stage $ticks $rb $rn"
  done
}

printf '%d programs, %d lines each, %.1f MB of program text; CPU and bytes over the batch only\n' \
  "$BATCH" "$(wc -l < "$W/programs/p1.ngc")" "$(echo "$input_bytes / 1000000" | bc -l)"
printf '| workers per stage | wall s | service CPU s | CPU vs %s | client CPU s | MB received per worker: interpreter | cc1_builder | feature_recognizer | step_writer |\n' "$(awk '{print $1}' <<<"$COUNTS")"
printf '|---|---|---|---|---|---|---|---|---|\n'
reference_cpu=""
first=""
for n in $COUNTS; do
  rm -rf "$W/net" "$W/out"; mkdir -p "$W/net" "$W/out"
  NCBRIDGE_NET_COUNTERS="$W/net" LD_PRELOAD="$LIB" "$BIN/ncbridge" up --workers "$n" --log-level warn > "$W/up.log" 2>&1 &
  UP=$!
  ok=0
  for _ in $(seq 1 60); do
    if [[ $("$BIN/ncbridge" status --listen 0.3 2>/dev/null | grep -Ec "^  [a-z0-9_]+ +$n live") == 4 ]]; then ok=1; break; fi
  done
  [[ $ok == 1 ]] || { echo "services did not come up with $n workers" >&2; cat "$W/up.log" >&2; exit 1; }
  sleep 1
  mapfile -t pids < <(pgrep -P "$UP")
  snapshot "$UP" "${pids[@]}" > "$W/before"
  TIMEFORMAT='%R %U %S'
  { time (cd "$W" && NCBRIDGE_NET_COUNTERS="$W/net" LD_PRELOAD="$LIB" "$BIN/ncbridge" submit --list "$W/list" --level cc1 \
      --wait --output-dir "$W/out" > "$W/submit.log" 2>&1) ; } 2> "$W/time"
  snapshot "$UP" "${pids[@]}" > "$W/after"
  kill "$UP"; wait "$UP" 2>/dev/null || true; UP=""
  grep -q "$BATCH jobs: $BATCH done" "$W/submit.log" || { echo "the batch did not complete with $n workers:" >&2; tail -n 5 "$W/submit.log" >&2; exit 1; }
  if [[ -z $first ]]; then
    first=$n; mv "$W/out" "$W/reference"
  else
    diff -rq "$W/reference" "$W/out" > /dev/null || { echo "outputs with $n workers differ from those with $first" >&2; exit 1; }
  fi
  read -r wall cu cs < "$W/time"
  cpu=$(join <(sort "$W/before") <(sort "$W/after") | awk -v t="$TICK" '{ s += $7 - $3 } END { printf "%.2f", s / t }')
  [[ -n $reference_cpu ]] || reference_cpu=$cpu
  per_stage=$(join <(sort "$W/before") <(sort "$W/after") | awk '
    { st = $2; if (st == "ncbridge") next; b = $8 - $4; sum[st] += b; cnt[st]++; if (b > max[st]) max[st] = b }
    END { split("interpreter cc1-builder feature-recognizer step-writer", order, " ")
          for (i = 1; i <= 4; i++) { s = order[i]; printf "%s%.2f (max %.2f)", (i > 1 ? " | " : ""), sum[s] / cnt[s] / 1e6, max[s] / 1e6 } }')
  printf '| %d | %.1f | %.2f | %.2f | %.2f | %s |\n' "$n" "$wall" "$cpu" "$(echo "$cpu / $reference_cpu" | bc -l)" \
    "$(echo "$cu + $cs" | bc -l)" "$per_stage"
done
