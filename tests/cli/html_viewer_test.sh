#!/usr/bin/env bash
# convert --html's page in a real browser (Debian's Chromium, headless, WebGL by SwiftShader):
# for the plate and a CAM part (CC2), the page loads without a console error, the 3D view draws
# one line per toolpath and feature of the page's data, every workingstep's and feature kind's
# colour is on its canvas, and a screenshot is taken. Under CI a missing Chromium fails.
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

check_page() {  # NAME PROGRAM TOOLS STOCK [convert options...]
  local name=$1 program=$2 tools=$3 stock=$4
  shift 4
  "$NCBRIDGE" convert "$program" --tools "$tools" --stock "$stock" --level cc2 -o "$WORK/$name.stp" \
    --html "$WORK/$name.html" "$@" 2> "$WORK/$name.convert.log" || fail "$name: convert: $(cat "$WORK/$name.convert.log")"
  grep -q '<script src=\|<link ' "$WORK/$name.html" && fail "$name: the page loads something from outside"
  browser --enable-logging=stderr --v=0 --dump-dom "file://$WORK/$name.html" > "$WORK/$name.dom" 2> "$WORK/$name.console" ||
    fail "$name: chromium failed: $(tail -5 "$WORK/$name.console")"
  if grep -E 'Uncaught|:ERROR:CONSOLE|"Error' "$WORK/$name.console" | grep -v 'GL Driver Message' | grep -q .; then
    fail "$name: console errors: $(grep -E 'Uncaught|:ERROR:CONSOLE' "$WORK/$name.console" | head -5)"
  fi
  local drawn expected
  drawn=$(grep -o 'data-view3d="[^"]*"' "$WORK/$name.dom" | head -1 | sed 's/data-view3d="\(.*\)"/\1/')
  [[ "$drawn" =~ ^[0-9]+$ ]] || fail "$name: the 3D view did not draw: '${drawn}'"
  # One line per toolpath and per feature in the page's data.
  expected=$(( $(grep -o '"w":[0-9]*,"r":' "$WORK/$name.html" | wc -l) + $(grep -o '"col":"#' "$WORK/$name.html" | wc -l) ))
  [[ "$drawn" -eq "$expected" && "$drawn" -gt 0 ]] || fail "$name: 3D view drew $drawn lines, the data has $expected"
  local colours
  colours=$(grep -o "data-view3d-colours=\"[^\"]*\"" "$WORK/$name.dom" | sed 's/&quot;/"/g')
  [[ -n "$colours" ]] || fail "$name: no colour read back from the 3D view"
  if echo "$colours" | grep -q '":0[,}]'; then fail "$name: a colour is missing from the 3D view: $colours"; fi
  browser --screenshot="$WORK/$name.png" "file://$WORK/$name.html" 2> /dev/null || fail "$name: no screenshot"
  [[ $(stat -c %s "$WORK/$name.png") -gt 20000 ]] || fail "$name: the screenshot is nearly empty"
  echo "$name: $drawn lines in 3D, colours $colours"
}

ex="$SRC/examples/plate"
check_page plate "$ex/plate.ngc" "$ex/tools.json" "$ex/stock.json"
cam="$SHARED/corpus/cam/p04_open_pockets"
check_page cam_open_pockets "$cam/part.linuxcnc.ngc" "$cam/tools.json" "$cam/stock.json"
echo "PASS: the HTML viewer in Chromium"
