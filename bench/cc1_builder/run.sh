#!/usr/bin/env bash
# Times `ncbridge convert` (interpreter -> cc1_builder -> step_writer, streamed) on the generated
# RS274/NGC program: wall and CPU time, peak RSS and MB/s of program text, best of RUNS by CPU time
# (the repeatable figure on a shared machine), without --report; the peak RSS of a program a tenth
# as long (flat memory: the two should be close); then one run with --report for each stage's
# share. Figures go to docs/performance.md, "CC1 conversion".
#
#   bench/cc1_builder/run.sh [BUILD_DIR] [LINES] [RUNS]     (defaults: build 1000000 3)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
lines="${2:-1000000}"
runs="${3:-3}"
ncbridge="$build/bin/ncbridge"
generator="$build/bin/generate_ngc_program"
for exe in "$ncbridge" "$generator"; do
  [[ -x "$exe" ]] || { echo "run.sh: $exe not built (cmake --build $build --target ncbridge generate_ngc_program)" >&2; exit 1; }
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
program="$work/bench_${lines}.ngc"
"$generator" "$lines" 1 >"$program"
bytes=$(stat -c %s "$program")
convert=("$ncbridge" convert "$program" --tools "$here/tools.json" --stock "$here/stock.json" -o "$work/out.stp")

best_cpu=""
for ((i = 0; i < runs; i++)); do
  /usr/bin/time -f "%e %U %S %M" -o "$work/time" "${convert[@]}" 2>"$work/err" </dev/null \
    || { echo "run.sh: convert failed:" >&2; head -n 5 "$work/err" >&2; exit 1; }
  read -r s user sys rss <"$work/time"
  cpu=$(awk -v u="$user" -v y="$sys" 'BEGIN { print u + y }')
  if [[ -z "$best_cpu" ]] || awk -v a="$cpu" -v b="$best_cpu" 'BEGIN { exit !(a < b) }'; then
    best_cpu="$cpu" best_s="$s" best_user="$user" best_sys="$sys" best_rss="$rss"
  fi
done
out_bytes=$(stat -c %s "$work/out.stp")
tenth=$((lines / 10))
"$generator" "$tenth" 1 >"$work/tenth.ngc"
/usr/bin/time -f "%M" -o "$work/time" "$ncbridge" convert "$work/tenth.ngc" --tools "$here/tools.json" \
  --stock "$here/stock.json" -o "$work/tenth.stp" 2>/dev/null </dev/null
tenth_rss=$(cat "$work/time")

awk -v s="$best_s" -v u="$best_user" -v y="$best_sys" -v rss="$best_rss" -v b="$bytes" -v l="$lines" -v o="$out_bytes" \
    -v t="$tenth" -v trss="$tenth_rss" 'BEGIN {
  printf "program: %d lines, %.1f MB; output %.1f MB (%.0f bytes per line)\n", l, b / 1e6, o / 1e6, o / l
  printf "wall %.2f s (user %.2f s, sys %.2f s), %.1f MB/s (wall), %.1f MB/s (CPU), peak RSS %.1f MB\n",
         s, u, y, b / 1e6 / s, b / 1e6 / (u + y), rss / 1024
  printf "peak RSS at %d lines: %.1f MB\n", t, trss / 1024 }'

/usr/bin/time -f "%M" -o "$work/time" "${convert[@]}" --report "$work/report.json" 2>/dev/null </dev/null
python3 - "$work/report.json" "$(cat "$work/time")" <<'PY'
import json, os, sys
r = json.load(open(sys.argv[1]))
print("with --report: peak RSS %.1f MB, report %.1f MB" % (int(sys.argv[2]) / 1024, os.path.getsize(sys.argv[1]) / 1e6))
t = r["timings_ms"]
stages = [k for k in ("read_inputs", "interpreter", "cc1_builder", "step_writer", "output") if k in t]
total = sum(t[k] for k in stages)
print("with --report: workingsteps and rapids: %d, canonical calls: %d" % (len(r["workingsteps"]), r["canonical_calls"]))
for k in stages:
    print("  %-12s %8.0f ms  %5.1f %%" % (k, t[k], 100 * t[k] / total))
PY
