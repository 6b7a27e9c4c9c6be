#!/bin/sh
# Regenerates the canonical-call text of the recognition corpus with LinuxCNC's standalone
# rs274 (Debian package linuxcnc-uspace). Comments are stripped from every program first:
# recognition must never see the CAM's operation names. Tests read the committed output and do
# not need rs274.
#   usage: tests/feature_recognizer/data/regenerate.sh [path/to/shared]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
shared=${1:-$here/../../../../shared}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# tools.json -> LinuxCNC tool table; rs274's machine is in inches, so lengths are mm/25.4.
tool_table() {
  python3 - "$1" <<'PY'
import json, sys
tools = json.load(open(sys.argv[1]))
tools = tools["tools"] if isinstance(tools, dict) else tools
for t in tools:
    print("T%d P%d D%.6f Z%.6f" % (t["number"], t["number"], t["diameter"] / 25.4, t.get("length", 0) / 25.4))
PY
}

run() {  # program tools.json output
  sed -e 's/([^)]*)//g' -e 's/;.*$//' "$1" > "$work/program.ngc"
  tool_table "$2" > "$work/tools.tbl"
  : > "$work/copy.var"
  (cd "$work" && rs274 -g -n 2 -t tools.tbl -v copy.var program.ngc </dev/null) \
    | sed -e 's/executing$//' > "$3"
  echo "wrote $3 ($(wc -l < "$3") calls)"
}

cam=$shared/corpus/cam
run "$cam/p01_block_reference/part.nc"          "$cam/p01_block_reference/tools.json"  "$here/p01_block_reference.canon"
run "$cam/p02_plate_center_zero/part.linuxcnc.ngc" "$cam/p02_plate_center_zero/tools.json" "$here/p02_plate_center_zero.canon"
run "$cam/p03_bracket_steps/part.nc"            "$cam/p03_bracket_steps/tools.json"    "$here/p03_bracket_steps.canon"
run "$cam/p04_open_pockets/part.linuxcnc.ngc"   "$cam/p04_open_pockets/tools.json"     "$here/p04_open_pockets.canon"
run "$cam/p05_slots/part.nc"                    "$cam/p05_slots/tools.json"            "$here/p05_slots.canon"
paper=$shared/corpus/paper
run "$paper/face_mill.ngc" "$paper/tools.json" "$here/paper_face_mill.canon"
run "$paper/test_part.ngc" "$paper/tools.json" "$here/paper_test_part.canon"
# The hand-designed parts (tests/cc2/parts/make_parts.py), written without comments.
for part in "$here"/../../cc2/parts/p*/; do
  name=$(basename "$part")
  run "$part/part.ngc" "$part/tools.json" "$here/$name.canon"
done
