#!/usr/bin/env bash
# `plan` on the NIST CTC parts and ANC101 (../shared/corpus/brep): for each, plan_timing RUNS
# times in fresh processes, the run with the least total time kept (the repeatable figure on a
# shared machine), as one table row: Open CASCADE's read, the plain model, recognition,
# planning, the CC2 text, peak RSS. Figures go to docs/performance.md, "Planning STEP parts".
#
#   bench/part_reader/run.sh [BUILD_DIR] [RUNS]     (defaults: build 5)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
runs="${2:-5}"
timing="$build/bin/plan_timing"
[[ -x "$timing" ]] || { echo "run.sh: $timing not built (cmake --build $build --target plan_timing)" >&2; exit 1; }
corpus="$repo/../shared/corpus/brep"
echo "| part | size | planned | OCCT read | model | recognition | planning | CC2 text | peak RSS |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for part in nist_ctc_01_asme1_ap242-e1 nist_ctc_03_asme1_ap242-e2 nist_ctc_05_asme1_ap242-e1 asitus_ANC101; do
  file="$corpus/$part.stp"
  best=""
  for ((i = 0; i < runs; i++)); do
    line=$("$timing" "$file" "$here/tools.json")
    total=$(awk '{for (i = 1; i < NF; i++) if ($i == "total_ms") print $(i + 1)}' <<<"$line")
    if [[ -z "$best" ]] || awk -v a="$total" -v b="$best_total" 'BEGIN { exit !(a < b) }'; then best="$line" best_total="$total"; fi
  done
  size=$(( $(stat -c %s "$file") / 1024 ))
  awk -v name="$part" -v size="$size" '{
    for (i = 1; i < NF; i += 2) v[$i] = $(i + 1)
    printf "| %s | %d KB | %d features, %d workingsteps | %.0f ms | %.0f ms | %.1f ms | %.2f ms | %.2f ms | %.1f MB |\n",
      name, size, v["features"], v["workingsteps"], v["occt_read_ms"], v["model_ms"], v["recognition_ms"], v["plan_ms"], v["cc2_ms"],
      v["peak_rss_kb"] / 1024 }' <<<"$best"
done
