#!/usr/bin/env bash
# Times `ncbridge convert` (interpreter -> cc1_builder -> step_writer) on the generated RS274/NGC
# program: wall time, peak RSS, MB/s of program text, and each stage's share from the --report
# timings (best of RUNS by wall time). Figures go to docs/performance.md, "CC1 conversion".
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

best_s=""
for ((i = 0; i < runs; i++)); do
  /usr/bin/time -f "%e %M" -o "$work/time" "$ncbridge" convert "$program" --tools "$here/tools.json" \
    --stock "$here/stock.json" -o "$work/out.stp" --report "$work/report.json" 2>"$work/err" </dev/null \
    || { echo "run.sh: convert failed:" >&2; head -n 5 "$work/err" >&2; exit 1; }
  read -r s rss <"$work/time"
  if [[ -z "$best_s" ]] || awk -v a="$s" -v b="$best_s" 'BEGIN { exit !(a < b) }'; then
    best_s="$s" best_rss="$rss"
    cp "$work/report.json" "$work/best.json"
    out_bytes=$(stat -c %s "$work/out.stp")
  fi
done

awk -v s="$best_s" -v rss="$best_rss" -v b="$bytes" -v l="$lines" -v o="$out_bytes" 'BEGIN {
  printf "program: %d lines, %.1f MB; output %.1f MB\n", l, b / 1e6, o / 1e6
  printf "wall %.2f s, %.1f MB/s, peak RSS %.0f MB\n", s, b / 1e6 / s, rss / 1024 }'
python3 - "$work/best.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
t = r["timings_ms"]
total = t["total"]
print("workingsteps and rapids: %d, canonical calls: %d" % (len(r["workingsteps"]), r["canonical_calls"]))
for k in ("read_inputs", "interpreter", "cc1_builder", "step_writer", "output"):
    print("  %-12s %8.0f ms  %5.1f %%" % (k, t[k], 100 * t[k] / total))
PY
