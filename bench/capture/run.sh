#!/usr/bin/env bash
# Live capture beside a real controller (LinuxCNC's simulated mill, headless): what the capture
# costs the controller's machine (CPU of `ncbridge capture linuxcnc` and its status reader, idle
# and while a program runs, beside the controller's own processes) and the capture latency
# (program end on the controller -> the run's CC1 file written by the services), for status
# periods of 5 and 20 ms. Needs root and LinuxCNC (linuxcnc-uspace).
# Usage: bench/capture/run.sh [BUILD_DIR] [RUNS]
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$repo/build}
runs=${2:-3}
export BIN=$build/bin SHARED=$repo/../shared SOURCE_DIR=$repo
source "$repo/tests/integration/lib.sh"
source "$repo/tests/integration/linuxcnc/controller.sh"

cp "$SHARED/corpus/paper/test_part.ngc" "$cfg/nc/test_part.ngc"
chown -R "$user" "$cfg"
start_controller
start up "$BIN/ncbridge" up --workers 1 --live-tools "$TOOLS_PAPER" --live-stock "$STOCK_PAPER" --output-dir "$WORK/out"
wait_workers 1

ticks=$(getconf CLK_TCK)
cpu_of() {  # cpu_of PID...: user+system seconds of the processes
  local total=0 pid
  for pid in "$@"; do
    [[ -r /proc/$pid/stat ]] || continue
    total=$(( total + $(awk '{ print $14 + $15 }' "/proc/$pid/stat") ))
  done
  echo "$total"
}
capture_pids() {  # the capture command and its status reader
  local p; p=$(pgrep -u "$user" -f "ncbridge capture linuxcnc" | head -n 1)
  echo "$p $(pgrep -P "$p" | tr '\n' ' ')"
}
files_of() {  # files_of CONTROLLER: how many files its runs made
  local f=("$WORK"/out/"$1"-*.stp)
  if [[ -e ${f[0]} ]]; then echo "${#f[@]}"; else echo 0; fi
}
controller_pids() { pgrep -u "$user" -f "milltask|rtapi_app|io |halui|linuxcncrsh" | tr '\n' ' '; }

printf "%-9s %-22s %-22s %-24s %s\n" "period" "capture CPU idle" "capture CPU running" "controller CPU running" "run end -> CC1 file"
for period in 5 20; do
  start "capture-$period" su "$user" -c "$(as_user "$BIN/ncbridge" capture linuxcnc --controller "bench$period" --poll-ms "$period")"
  sleep 3
  # shellcheck disable=SC2046
  c0=$(cpu_of $(capture_pids)); sleep 10; c1=$(cpu_of $(capture_pids))
  idle=$(awk -v a="$c0" -v b="$c1" -v t="$ticks" 'BEGIN { printf "%.2f %%", (b - a) / t / 10 * 100 }')
  latencies=()
  run_cpu=0; ctl_cpu=0; run_s=0
  for r in $(seq 1 "$runs"); do
    before=$(files_of "bench$period")
    # shellcheck disable=SC2046
    c0=$(cpu_of $(capture_pids)); k0=$(cpu_of $(controller_pids)); t0=$(date +%s.%N)
    su "$user" -c "$(as_user timeout 300 "$python" "$drive" run "$cfg/nc/test_part.ngc" --feed-scale 100)"
    t1=$(date +%s.%N)
    # shellcheck disable=SC2046
    c1=$(cpu_of $(capture_pids)); k1=$(cpu_of $(controller_pids))
    until (( $(files_of "bench$period") > before )); do sleep 0.002; done
    t2=$(date +%s.%N)
    latencies+=("$(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.0f", (b - a) * 1000 }')")
    run_cpu=$(( run_cpu + c1 - c0 )); ctl_cpu=$(( ctl_cpu + k1 - k0 ))
    run_s=$(awk -v s="$run_s" -v a="$t0" -v b="$t1" 'BEGIN { print s + b - a }')
  done
  median=$(printf '%s\n' "${latencies[@]}" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
  running=$(awk -v c="$run_cpu" -v s="$run_s" -v t="$ticks" 'BEGIN { printf "%.2f %%", c / t / s * 100 }')
  controller=$(awk -v c="$ctl_cpu" -v s="$run_s" -v t="$ticks" 'BEGIN { printf "%.1f %%", c / t / s * 100 }')
  printf "%-9s %-22s %-22s %-24s median %s ms (runs: %s)\n" "${period} ms" "$idle" "$running" "$controller" "$median" "${latencies[*]}"
  pkill -TERM -u "$user" -f "ncbridge capture linuxcnc --controller bench$period" || true
  sleep 1
done
echo "(CPU as a share of one core; the test part at 100x feed, $runs runs each; runs of $(awk -v s="$run_s" -v n="$runs" 'BEGIN { printf "%.1f", s / n }') s)"
