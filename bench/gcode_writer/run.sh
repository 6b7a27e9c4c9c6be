#!/usr/bin/env bash
# The gcode_writer on the generated benchmark program (bench/interpreter/generate_ngc_program):
# CPU time (user + sys) of `ncbridge gcode --to fanuc` against `ncbridge canon` of the same file
# (target: at most 1.5x), and peak RSS of gcode at 100k and at 1M lines (flat in program length).
# Best of RUNS; output to a file / to /dev/null. Figures go to docs/performance.md ("gcode").
#
#   bench/gcode_writer/run.sh [BUILD_DIR] [RUNS]     (defaults: build 3)
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
runs="${2:-3}"
ncbridge="$build/bin/ncbridge"
generator="$build/bin/generate_ngc_program"
for exe in "$ncbridge" "$generator"; do
  [[ -x "$exe" ]] || { echo "run.sh: $exe not built (cmake --build $build --target ncbridge generate_ngc_program)" >&2; exit 1; }
done
tools="$repo/tests/interpreter/golden/tools/metric.mm.tbl"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# best_of COMMAND... : the run with the least CPU time; sets best_cpu (s) and best_rss_kb
best_of() {
  best_cpu="" best_rss_kb=""
  for ((i = 0; i < runs; i++)); do
    if ! /usr/bin/time -f "%U %S %M" -o "$work/time" "$@" >/dev/null 2>"$work/err" </dev/null; then
      echo "run.sh: $* failed:" >&2; head -n 5 "$work/err" >&2; exit 1
    fi
    read -r user sys rss <"$work/time"
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
    if [[ -z "$best_cpu" ]] || awk -v a="$cpu" -v b="$best_cpu" 'BEGIN { exit !(a < b) }'; then
      best_cpu="$cpu" best_rss_kb="$rss"
    fi
  done
}

echo "best of $runs runs; $(nproc) cores; load $(cut -d' ' -f1-3 /proc/loadavg)"
for lines in 100000 1000000; do
  program="$work/bench_$lines.ngc"
  "$generator" "$lines" 1 >"$program"
  best_of "$ncbridge" canon "$program" --tool-table "$tools" --tool-table-units mm
  canon_cpu="$best_cpu" canon_rss="$best_rss_kb"
  # the program has G64 P0.01, which Fanuc's G64 does not carry: --drop-path-tolerance
  best_of "$ncbridge" gcode "$program" --dialect rs274ngc --to fanuc --drop-path-tolerance \
    --tool-table "$tools" --tool-table-units mm -o "$work/out.nc"
  awk -v n="$lines" -v cc="$canon_cpu" -v cr="$canon_rss" -v gc="$best_cpu" -v gr="$best_rss_kb" \
      -v bytes="$(stat -c %s "$work/out.nc")" 'BEGIN {
    if (cc <= 0) cc = 0.01;
    printf "%8d lines: canon %6.2f s CPU, %6.1f MB peak | gcode --to fanuc %6.2f s CPU, %6.1f MB peak, %5.1f MB written | ratio %.2fx\n",
           n, cc, cr / 1024, gc, gr / 1024, bytes / 1e6, gc / cc }'
done
