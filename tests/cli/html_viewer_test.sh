#!/usr/bin/env bash
# The --html page in a real browser (Debian's Chromium, headless, WebGL by SwiftShader), for
# the plate and a CAM part: recognised (CC2 from a program), a program's CC1 model, and the CC1
# model generated from a CC2 file (toolpaths from the generator drawn on the CC2 features).
# For each page: it loads without a console error and from nothing outside; the 3D view draws
# one line per toolpath and outlined feature of the page's data; every feature kind's colour and
# every workingstep's that spans the drawing is on its canvas; the top view holds every cut,
# rapid and outline of the data; a click on a feature row lights exactly the toolpaths of its
# workingsteps and its outline, and a feature-kind toggle hides exactly the toolpaths of that
# kind (the page's #selftest). A generated page outlines every feature of its CC2 file.
# Under CI a missing Chromium fails.
# Usage: html_viewer_test.sh NCBRIDGE SOURCE_DIR SHARED_DIR
set -euo pipefail
NCBRIDGE=$1
SRC=$2
SHARED=$3
WORK=$(mktemp -d "${TMPDIR:-/tmp}/ncbridge-viewer.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
if ! command -v chromium > /dev/null; then
  [[ "${CI:-}" == true ]] && fail "chromium is not installed (scripts/install-deps.sh --tests)"
  echo "SKIP: chromium is not installed"
  exit 77
fi
browser() {
  timeout 120 chromium --headless --no-sandbox --disable-gpu --use-gl=angle --use-angle=swiftshader \
    --enable-unsafe-swiftshader --hide-scrollbars --window-size=1600,1400 --virtual-time-budget=5000 \
    --user-data-dir="$WORK/profile" "$@"
}
attribute() {  # NAME ATTRIBUTE: a body data attribute of the page's DOM after its scripts ran
  grep -o "data-$2=\"[^\"]*\"" "$WORK/$1.dom" | head -1 | sed "s/data-$2=\"\(.*\)\"/\1/; s/&quot;/\"/g"
}
json_field() {  # JSON FIELD
  python3 -c 'import json,sys; print(json.loads(sys.argv[1])[sys.argv[2]])' "$1" "$2"
}

check_page() {  # NAME [screenshot]: $WORK/NAME.html, written
  local name=$1 page="$WORK/$1.html" shot=${2:-}
  grep -q '<script src=\|<link ' "$page" && fail "$name: the page loads something from outside"
  browser --enable-logging=stderr --v=0 --dump-dom "file://$page#selftest" > "$WORK/$name.dom" 2> "$WORK/$name.console" ||
    fail "$name: chromium failed: $(tail -5 "$WORK/$name.console")"
  if grep -E 'Uncaught|:ERROR:CONSOLE|"Error' "$WORK/$name.console" | grep -v 'GL Driver Message' | grep -q .; then
    fail "$name: console errors: $(grep -E 'Uncaught|:ERROR:CONSOLE' "$WORK/$name.console" | head -5)"
  fi
  local drawn expected
  drawn=$(attribute "$name" view3d)
  [[ "$drawn" =~ ^[0-9]+$ ]] || fail "$name: the 3D view did not draw: '${drawn}'"
  # One line per toolpath and per outlined feature in the page's data.
  local paths cuts rapids outlines
  paths=$(grep -o '{"w":-\?[0-9]*,"r":' "$page" | wc -l)
  cuts=$(grep -o '{"w":-\?[0-9]*,"r":0' "$page" | wc -l)
  rapids=$(grep -o '{"w":-\?[0-9]*,"r":1' "$page" | wc -l)
  outlines=$(grep -o '"col":"#' "$page" | wc -l)
  expected=$((paths + outlines))
  [[ "$drawn" -eq "$expected" && "$drawn" -gt 0 ]] || fail "$name: 3D view drew $drawn lines, the data has $expected"
  local colours
  colours=$(attribute "$name" view3d-colours)
  [[ -n "$colours" ]] || fail "$name: no colour read back from the 3D view"
  if echo "$colours" | grep -q '":0[,}]'; then fail "$name: a colour is missing from the 3D view: $colours"; fi
  local drawn2d
  drawn2d=$(attribute "$name" drawn2d)
  [[ "$(json_field "$drawn2d" cut)" -eq "$cuts" ]] || fail "$name: top view: $drawn2d, the data has $cuts cuts"
  [[ "$(json_field "$drawn2d" rapid)" -eq "$rapids" ]] || fail "$name: top view: $drawn2d, the data has $rapids rapids"
  [[ "$(json_field "$drawn2d" outlines)" -eq "$outlines" ]] || fail "$name: top view: $drawn2d, the data has $outlines outlines"
  local selftest lit
  selftest=$(attribute "$name" selftest)
  lit=$(json_field "$selftest" lit)
  [[ "$lit" -gt 0 && "$lit" -eq "$(json_field "$selftest" expected)" ]] || fail "$name: a feature row lit the wrong toolpaths: $selftest"
  [[ "$(json_field "$selftest" outlineHighlighted)" == True && "$(json_field "$selftest" rowHighlighted)" == True ]] ||
    fail "$name: a feature row did not highlight: $selftest"
  [[ "$(json_field "$selftest" clearedDim)" -eq 0 ]] || fail "$name: a second click left toolpaths dimmed: $selftest"
  [[ "$(json_field "$selftest" hiddenByKind)" -eq "$(json_field "$selftest" kindLines)" ]] ||
    fail "$name: a feature-kind toggle hid the wrong toolpaths: $selftest"
  if [[ -n "$shot" ]]; then
    browser --screenshot="$WORK/$name.png" "file://$page" 2> /dev/null || fail "$name: no screenshot"
    [[ $(stat -c %s "$WORK/$name.png") -gt 20000 ]] || fail "$name: the screenshot is nearly empty"
  fi
  echo "$name: $drawn lines in 3D, top view $drawn2d, colours $colours, row click $selftest"
}

convert() {  # NAME PROGRAM TOOLS STOCK LEVEL
  "$NCBRIDGE" convert "$2" --tools "$3" --stock "$4" --level "$5" -o "$WORK/$1.stp" --html "$WORK/$1.html" -q \
    2> "$WORK/$1.convert.log" || fail "$1: convert: $(cat "$WORK/$1.convert.log")"
}
generated() {  # NAME CC2_NAME: the CC1 model generated from $WORK/CC2_NAME.stp
  "$NCBRIDGE" convert "$WORK/$2.stp" --level cc1 -o "$WORK/$1.stp" --html "$WORK/$1.html" -q 2> "$WORK/$1.convert.log" ||
    fail "$1: convert: $(cat "$WORK/$1.convert.log")"
  # Every feature of the CC2 file is outlined on the generated page.
  local features outlines
  features=$(grep -c "^#[0-9]*=\(ROUND_HOLE\|PLANAR_FACE\|CLOSED_POCKET\|OPEN_POCKET\|SLOT\|STEP\|GENERAL_OUTSIDE_PROFILE\)(" "$WORK/$2.stp" || true)
  outlines=$(grep -o '"col":"#' "$WORK/$1.html" | wc -l)
  [[ "$features" -gt 0 && "$outlines" -eq "$features" ]] || fail "$1: $outlines outlines for the $features features of $2.stp"
  grep -q '<title>ncbridge CC1: ' "$WORK/$1.html" || fail "$1: not a CC1 page"
}

ex="$SRC/examples/plate"
convert plate_cc2 "$ex/plate.ngc" "$ex/tools.json" "$ex/stock.json" cc2
check_page plate_cc2 screenshot
convert plate_cc1 "$ex/plate.ngc" "$ex/tools.json" "$ex/stock.json" cc1
check_page plate_cc1
generated plate_generated plate_cc2
check_page plate_generated
cam="$SHARED/corpus/cam/p04_open_pockets"
convert cam_open_pockets "$cam/part.linuxcnc.ngc" "$cam/tools.json" "$cam/stock.json" cc2
check_page cam_open_pockets
generated cam_open_pockets_generated cam_open_pockets
check_page cam_open_pockets_generated screenshot
# optimize --html: one layer before and after. In the browser: no console error, every output
# arc of the layer drawn as one, the input's motion ends dotted (one more than its motions per
# joined run), the output's too.
check_optimize_page() {  # NAME PROGRAM [optimize options...]
  local name=$1 program=$2
  shift 2
  "$NCBRIDGE" optimize "$program" "$@" -o "$WORK/$name.out" --html "$WORK/$name.html" -q 2> "$WORK/$name.log" ||
    fail "$name: optimize: $(cat "$WORK/$name.log")"
  browser --enable-logging=stderr --v=0 --dump-dom "file://$WORK/$name.html" > "$WORK/$name.dom" 2> "$WORK/$name.console" ||
    fail "$name: chromium failed"
  if grep -E 'Uncaught|:ERROR:CONSOLE' "$WORK/$name.console" | grep -q .; then
    fail "$name: console errors: $(grep -E 'Uncaught|:ERROR:CONSOLE' "$WORK/$name.console" | head -5)"
  fi
  local drawn counts before lines arcs
  drawn=$(attribute "$name" drawn)
  counts=$(grep -o 'data-layer-counts="[^"]*"' "$WORK/$name.html" | sed 's/.*="\(.*\)"/\1/')
  read -r before lines arcs <<< "$counts"
  [[ "$before" -gt 0 ]] || fail "$name: an empty layer: $counts"
  [[ "$(json_field "$drawn" after_arcs)" -eq "$arcs" ]] || fail "$name: $arcs arcs in the layer, $drawn drawn"
  [[ "$(json_field "$drawn" before_dots)" -eq $((before + $(json_field "$drawn" before_runs))) ]] ||
    fail "$name: the input's $before motions in $(json_field "$drawn" before_runs) runs, $drawn drawn"
  [[ "$(json_field "$drawn" after_dots)" -gt "$arcs" ]] || fail "$name: the output's ends are not dotted: $drawn"
  echo "$name: layer counts $counts, drawn $drawn"
}
check_optimize_page optimize_cylinder "$SHARED/corpus/arcs/slic3r129_cylinder.gcode" --flavor marlin
check_optimize_page optimize_pocket_wall "$SRC/examples/optimize/pocket_wall.ngc" --dialect rs274ngc --loops
echo "PASS: the HTML viewer in Chromium"
