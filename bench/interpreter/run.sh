#!/usr/bin/env bash
# Times `ncbridge canon` on the generated 1M-line RS274/NGC program, and LinuxCNC's rs274 on the
# same file where it is installed; output goes to /dev/null for both. Prints lines/s, MB/s and
# peak RSS of each (best of RUNS), and the speed ratio. Figures go to docs/performance.md.
#
#   bench/interpreter/run.sh [BUILD_DIR] [LINES] [RUNS]     (defaults: build 1000000 3)
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
lines="${2:-1000000}"
runs="${3:-3}"
ncbridge="$build/bin/ncbridge"
generator="$build/bin/generate_ngc_program"
for exe in "$ncbridge" "$generator"; do
  [[ -x "$exe" ]] || { echo "run.sh: $exe not built (cmake --build $build --target ncbridge generate_ngc_program)" >&2; exit 1; }
done
tools="$repo/tests/interpreter/golden/tools"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
program="$work/bench_${lines}.ngc"
"$generator" "$lines" 1 >"$program"
bytes=$(stat -c %s "$program")

# best_of NAME COMMAND... : runs the command RUNS times, keeps the fastest; sets best_s, best_rss_kb
best_of() {
  local name="$1"; shift
  best_s="" best_rss_kb=""
  for ((i = 0; i < runs; i++)); do
    if ! /usr/bin/time -f "%e %M" -o "$work/time" "$@" >/dev/null 2>"$work/err" </dev/null; then
      echo "run.sh: $name failed:" >&2; grep -v '^executing$' "$work/err" | head -n 5 >&2; exit 1
    fi
    read -r s rss <"$work/time"
    if [[ -z "$best_s" ]] || awk -v a="$s" -v b="$best_s" 'BEGIN { exit !(a < b) }'; then
      best_s="$s" best_rss_kb="$rss"
    fi
  done
}

report() {  # NAME SECONDS RSS_KB
  awk -v name="$1" -v s="$2" -v rss="$3" -v lines="$lines" -v bytes="$bytes" 'BEGIN {
    if (s <= 0) s = 0.01;
    printf "%-9s %8.2f s  %12.0f lines/s  %8.2f MB/s  peak RSS %7.1f MB\n",
           name, s, lines / s, bytes / 1e6 / s, rss / 1024 }'
}

echo "program: $lines lines, $(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1e6 }') MB (generate_ngc_program $lines 1); best of $runs runs; $(nproc) cores"
best_of ncbridge "$ncbridge" canon "$program" --tool-table "$tools/metric.mm.tbl" --tool-table-units mm
ours_s="$best_s"
report ncbridge "$best_s" "$best_rss_kb"

if command -v rs274 >/dev/null; then
  mkdir -p "$work/home"
  : >"$work/params.var"
  best_of rs274 env HOME="$work/home" rs274 -g -n 2 -t "$tools/metric.rs274.tbl" -v "$work/params.var" "$program"
  report rs274 "$best_s" "$best_rss_kb"
  awk -v a="$best_s" -v b="$ours_s" 'BEGIN { if (b <= 0) b = 0.01; printf "ratio: ncbridge is %.2fx the speed of rs274\n", a / b }'
  ours_calls=$("$ncbridge" canon "$program" --tool-table "$tools/metric.mm.tbl" --tool-table-units mm </dev/null | wc -l)
  : >"$work/params.var"
  their_calls=$(HOME="$work/home" rs274 -g -n 2 -t "$tools/metric.rs274.tbl" -v "$work/params.var" "$program" </dev/null 2>/dev/null | wc -l)
  echo "calls printed: ncbridge $ours_calls, rs274 $their_calls"
else
  echo "rs274: not installed (Debian package linuxcnc-uspace); no comparison"
fi
