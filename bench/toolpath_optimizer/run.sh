#!/usr/bin/env bash
# The toolpath optimizer on every file of ../shared/corpus/arcs against ArcWelder
# (docs/performance.md, "optimize"; the bar is ../shared/corpus/arcs/ANCHOR.md):
#  - motion blocks out of `ncbridge optimize` at the band, counted from the written file the way
#    ANCHOR.md counts them (G0..G3 blocks by modal motion mode), and the largest deviation the
#    optimizer's own checker measured reading the output back; RS274/NGC outputs run by rs274;
#  - the same counts from ArcWelder run here in the same session (without travel arcs as
#    ANCHOR.md's default column, and with travel and 3D arcs) when its console program is given,
#    else ANCHOR.md's;
#  - CPU time (user + sys, best of RUNS) of `ncbridge optimize --no-check` and of ArcWelder, as
#    MB of input a second, and the ratio.
# ArcWelder is not a Debian package: build its console program from its sources outside this
# repository (FormerLurker/ArcWelderLib, tag 1.2.0, `ninja ArcWelderConsole`) and pass its path.
#
#   bench/toolpath_optimizer/run.sh [BUILD_DIR] [RUNS] [ARCWELDER] [TOLERANCE]
#   (defaults: build 3 $ARCWELDER 0.025; NCBRIDGE_SHARED_DIR defaults to ../shared)
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
runs="${2:-3}"
arcwelder="${3:-${ARCWELDER:-}}"
tolerance="${4:-0.025}"
shared="${NCBRIDGE_SHARED_DIR:-$repo/../shared}"
corpus="$shared/corpus/arcs"
ncbridge="$build/bin/ncbridge"
deviation_tool="$build/bin/printer_deviation"   # ArcWelder's outputs through our checker, if built
[[ -x "$ncbridge" ]] || { echo "run.sh: $ncbridge not built (cmake --build $build --target ncbridge)" >&2; exit 1; }
[[ -f "$corpus/ANCHOR.md" ]] || { echo "run.sh: no $corpus/ANCHOR.md (set NCBRIDGE_SHARED_DIR)" >&2; exit 1; }
if [[ -n "$arcwelder" && ! -x "$arcwelder" ]]; then echo "run.sh: $arcwelder is not a program" >&2; exit 1; fi
rs274="$(command -v rs274 || true)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# best_of COMMAND... : the run with the least CPU time (user + sys; perf's task-clock to the
# microsecond where perf runs, else /usr/bin/time's centiseconds); sets best_cpu (s)
use_perf=0
if command -v perf >/dev/null && perf stat -x, -e task-clock -o "$work/probe" true 2>/dev/null; then use_perf=1; fi
best_of() {
  best_cpu=""
  for ((i = 0; i < runs; i++)); do
    if ((use_perf)); then
      perf stat -x, -e task-clock -o "$work/time" "$@" >/dev/null 2>"$work/err" </dev/null || {
        echo "run.sh: $* failed:" >&2; head -n 5 "$work/err" >&2; exit 1; }
      cpu=$(awk -F, '$3 == "task-clock" { printf "%.4f", $1 / 1000 }' "$work/time")
    else
      /usr/bin/time -f "%U %S" -o "$work/time" "$@" >/dev/null 2>"$work/err" </dev/null || {
        echo "run.sh: $* failed:" >&2; head -n 5 "$work/err" >&2; exit 1; }
      read -r user sys <"$work/time"
      cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')
    fi
    if [[ -z "$best_cpu" ]] || awk -v a="$cpu" -v b="$best_cpu" 'BEGIN { exit !(a < b) }'; then best_cpu="$cpu"; fi
  done
}

# motion_blocks FILE: G0..G3 blocks by modal motion mode, as ANCHOR.md counts them (a block with
# axis words and no G word continues the mode; comments, blank lines and % aside).
motion_blocks() {
  awk '{
    line = toupper($0)
    sub(/;.*/, "", line)
    gsub(/\([^)]*\)/, "", line)
    gsub(/[ \t\r]/, "", line)
    if (line == "" || line == "%") next
    motion = 0; other = 0; rest = line
    while (match(rest, /G[0-9]+(\.[0-9]+)?/)) {
      word = substr(rest, RSTART + 1, RLENGTH - 1); code = word + 0
      rest = substr(rest, RSTART + RLENGTH)
      if (word ~ /\./) continue
      if (code <= 3) { motion = 1; mode = code }
      else if (code == 33 || code == 38 || code == 73 || code == 74 || code == 76 || (code >= 80 && code <= 89)) { other = 1; mode = code == 80 ? -1 : 4 }
      else if (code == 4 || code == 10 || code == 28 || code == 30 || code == 52 || code == 53 || code == 92 || code == 65) other = 1
    }
    axes = (" " line) ~ /[^A-Z][XYZABCUVW][-+.0-9=[#]/
    if (motion || (axes && !other && mode != "" && mode >= 0 && mode <= 3)) n++
  } END { print n + 0 }' "$1"
}

# anchor FILE COLUMN: ArcWelder's figure in ANCHOR.md (3: motion out by default; 5: reduction
# with travel + 3D arcs, turned into blocks from the input count in column 2)
anchor() {
  awk -F'|' -v f="$1" -v c="$2" '
    function num(s) { gsub(/[^0-9.]/, "", s); return s + 0 }
    $2 ~ f {
      if (c == 3) { print num($4); exit }
      split($3, parts, "(")
      inb = num(parts[1]); if (parts[2] != "") inb += num(parts[2])
      printf "%d\n", inb * (1 - num($6) / 100) + 0.5; exit
    }' "$corpus/ANCHOR.md"
}

echo "tolerance $tolerance mm; best of $runs runs; $(nproc) cores; load $(cut -d' ' -f1-3 /proc/loadavg)"
best_of "$ncbridge" --version
startup="$best_cpu"
echo "ncbridge's start (ncbridge --version): $(awk -v c="$startup" 'BEGIN { printf "%.1f", c * 1000 }') ms CPU, in every run below"
if [[ -n "$arcwelder" ]]; then echo "ArcWelder: $arcwelder (measured here)"; else echo "ArcWelder: not given, ANCHOR.md's figures"; fi
echo
echo "| file | input blocks | ours | ArcWelder | ours/ArcWelder | ArcWelder +travel +3D | largest deviation (mm) | ours MB/s (start excluded) | ArcWelder MB/s | speed ratio | ArcWelder's largest deviation (mm), spans out of the band |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
failed=0
for input in "$corpus"/*.gcode "$corpus"/*.ngc "$corpus"/*.nc; do
  [[ -f "$input" ]] || continue
  name="$(basename "$input")"
  case "$name" in
    *.gcode) kind=(--flavor marlin) ext=gcode ;;
    *.ngc) kind=(--dialect rs274ngc) ext=ngc ;;
    *) kind=(--dialect fanuc) ext=nc ;;
  esac
  out="$work/out.$ext"
  if ! "$ncbridge" optimize "$input" "${kind[@]}" --tolerance "$tolerance" -o "$out" --report "$work/report.json" 2>"$work/err"; then
    echo "run.sh: ncbridge optimize $name failed:" >&2; head -n 5 "$work/err" >&2; exit 1
  fi
  blocks_in=$(jq '.input_counts.motion_blocks' "$work/report.json")
  ours=$(motion_blocks "$out")
  if [[ "$ours" != "$(jq '.output_counts.motion_blocks' "$work/report.json")" ]]; then
    echo "run.sh: $name: the report says $(jq '.output_counts.motion_blocks' "$work/report.json") motion blocks out, the file has $ours" >&2
    failed=1
  fi
  deviation=$(jq '.deviation.largest_mm' "$work/report.json")
  if awk -v d="$deviation" -v t="$tolerance" 'BEGIN { exit !(d > t) }'; then
    echo "run.sh: $name: deviation $deviation mm over the band" >&2; failed=1
  fi
  if [[ "$ext" == ngc && -n "$rs274" ]]; then
    mkdir -p "$work/home" && : >"$work/params.var"
    if ! HOME="$work/home" "$rs274" -g -n 2 -v "$work/params.var" "$out" >/dev/null 2>"$work/rs274.err" ||
       grep -qv '^executing$' "$work/rs274.err"; then
      echo "run.sh: rs274 refuses the optimized $name:" >&2; head -n 3 "$work/rs274.err" >&2; failed=1
    fi
  fi
  best_of "$ncbridge" optimize "$input" "${kind[@]}" --tolerance "$tolerance" --no-check -o "$work/timed.$ext"
  ours_cpu="$best_cpu"
  bytes=$(stat -c %s "$input")
  if [[ -n "$arcwelder" ]]; then
    resolution=$(awk -v t="$tolerance" 'BEGIN { print 2 * t }')
    # ArcWelder 1.2.0's console switches flip its defaults: travel arcs are on unless -y is
    # given, 3D arcs off unless -z is. ANCHOR.md's default column is without travel arcs.
    "$arcwelder" "$input" "$work/aw.gcode" --resolution-mm="$resolution" -y >/dev/null 2>&1
    aw=$(motion_blocks "$work/aw.gcode")
    "$arcwelder" "$input" "$work/aw3d.gcode" --resolution-mm="$resolution" -z >/dev/null 2>&1
    aw3d=$(motion_blocks "$work/aw3d.gcode")
    best_of "$arcwelder" "$input" "$work/aw.gcode" --resolution-mm="$resolution" -y
    aw_cpu="$best_cpu"
    aw_dev="-"
    if [[ "$ext" == gcode && -x "$deviation_tool" ]]; then
      aw_dev=$("$deviation_tool" "$input" "$work/aw.gcode" "$tolerance" |
               sed -E 's/^largest ([0-9.]+) mm.* ([0-9]+) spans out of the band.*/\1, \2/') || true
    fi
  else
    aw=$(anchor "$name" 3) aw3d=$(anchor "$name" 5) aw_cpu="" aw_dev="-"
  fi
  awk -v st="$startup" -v f="$name" -v bi="$blocks_in" -v o="$ours" -v a="$aw" -v a3="$aw3d" -v d="$deviation" \
      -v b="$bytes" -v oc="$ours_cpu" -v ac="$aw_cpu" -v ad="$aw_dev" -v anchor_mbs="$(awk -F'|' -v f="$name" '$2 ~ f { gsub(/ /, "", $7); print $7 }' "$corpus/ANCHOR.md")" '
    function commas(n,   s) { s = sprintf("%d", n); while (s ~ /[0-9][0-9][0-9][0-9]/) sub(/[0-9][0-9][0-9]([,]|$)/, ",&", s); return s }
    BEGIN {
      if (oc <= 0) oc = 0.001
      ours_mbs = b / 1e6 / oc
      steady = oc - st > 0.0005 ? sprintf("%.1f", b / 1e6 / (oc - st)) : "-"
      if (ac != "") { if (ac <= 0) ac = 0.001; aw_mbs = sprintf("%.1f", b / 1e6 / ac); ratio = sprintf("%.2fx", ac / oc) }
      else { aw_mbs = anchor_mbs " (ANCHOR.md)"; ratio = sprintf("%.2fx", ours_mbs / anchor_mbs) }
      printf "| %s | %s | %s | %s | %.3f | %s | %.4f | %.1f (%s) | %s | %s | %s |\n", f, commas(bi), commas(o), commas(a), o / a, commas(a3), d, ours_mbs, steady, aw_mbs, ratio, ad
    }'
done

# Steady throughput: the slicer files one after another in one file (the start amortised).
cat "$corpus"/*.gcode >"$work/all.gcode"
bytes=$(stat -c %s "$work/all.gcode")
best_of "$ncbridge" optimize "$work/all.gcode" --flavor marlin --tolerance "$tolerance" --no-check -o "$work/all_out.gcode"
ours_cpu="$best_cpu"
if [[ -n "$arcwelder" ]]; then
  best_of "$arcwelder" "$work/all.gcode" "$work/all_aw.gcode" --resolution-mm="$(awk -v t="$tolerance" 'BEGIN { print 2 * t }')" -y
  aw_cpu="$best_cpu"
else
  aw_cpu=""
fi
awk -v b="$bytes" -v oc="$ours_cpu" -v ac="$aw_cpu" 'BEGIN {
  printf "\nall slicer files in one (%.1f MB): ours %.3f s CPU (%.1f MB/s)", b / 1e6, oc, b / 1e6 / oc
  if (ac != "") printf ", ArcWelder %.3f s (%.1f MB/s), ratio %.2fx", ac, b / 1e6 / ac, ac / oc
  printf "\n" }'
exit "$failed"
