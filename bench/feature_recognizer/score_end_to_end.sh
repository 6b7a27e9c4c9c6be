#!/bin/sh
# Recognition quality end to end: every corpus program with its comments stripped goes through
# `ncbridge convert --level cc2` (our interpreter, cc1_builder, recogniser); the reports are
# scored against truth by feature_recognition_score --reports.
#   usage: bench/feature_recognizer/score_end_to_end.sh [BUILD_DIR] [SHARED_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
shared=${2:-$here/../../../shared}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run() {  # case program dir
  sed -e 's/([^)]*)//g' -e 's/;.*$//' "$2" > "$work/$1.ngc"
  "$build/bin/ncbridge" convert "$work/$1.ngc" --tools "$3/tools.json" --stock "$3/stock.json" --level cc2 \
    -o "$work/$1.stp" --report "$work/$1.json" 2>/dev/null
}
cam=$shared/corpus/cam
paper=$shared/corpus/paper
run p01_block_reference   "$cam/p01_block_reference/part.nc"            "$cam/p01_block_reference"
run p02_plate_center_zero "$cam/p02_plate_center_zero/part.linuxcnc.ngc" "$cam/p02_plate_center_zero"
run p03_bracket_steps     "$cam/p03_bracket_steps/part.nc"              "$cam/p03_bracket_steps"
run p04_open_pockets      "$cam/p04_open_pockets/part.linuxcnc.ngc"     "$cam/p04_open_pockets"
run p05_slots             "$cam/p05_slots/part.nc"                      "$cam/p05_slots"
run paper_face_mill       "$paper/face_mill.ngc"                        "$paper"
run paper_test_part       "$paper/test_part.ngc"                        "$paper"
for part in "$here"/../../tests/cc2/parts/p*/; do  # hand-designed parts (tests/cc2/parts)
  run "$(basename "$part")" "$part/part.ngc" "$part"
done
"$build/bin/feature_recognition_score" --reports "$work" "$here/../.." "$shared"
