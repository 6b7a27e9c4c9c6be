#!/usr/bin/env bash
# The documentation's pictures, made from ncbridge's own pages by headless Chromium and made
# small (pngquant, optipng): one per toolpath strategy (docs/toolpaths.md, from the CC2 files in
# examples/toolpaths/), the viewer (docs/cli.md), the planned parts (docs/plan.md) and one layer
# before and after the optimizer (docs/optimize.md). Rerun it after a change to what they show.
# Usage: scripts/make-doc-pictures.sh [NCBRIDGE] [SHARED_DIR]
#   (defaults: build/bin/ncbridge, ../shared; run from the repository root; needs chromium,
#   pngquant and optipng: scripts/install-deps.sh --tests)
set -euo pipefail
cd "$(dirname "$0")/.."
NCBRIDGE=${1:-build/bin/ncbridge}
SHARED=${2:-../shared}
OUT=docs/images
for tool in chromium pngquant optipng; do
  command -v "$tool" > /dev/null || { echo "make-doc-pictures: $tool is missing (scripts/install-deps.sh --tests)" >&2; exit 1; }
done
[[ -x "$NCBRIDGE" ]] || { echo "make-doc-pictures: no $NCBRIDGE (build it first)" >&2; exit 1; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/ncbridge-pictures.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
mkdir -p "$OUT"

# shot PAGE PICTURE WIDTH HEIGHT [SCALE]: the page (with its #mode) as OUT/PICTURE.png, WIDTH x
# HEIGHT pixels; SCALE < 1 lays the page out in a larger window and shrinks it.
shot() {
  local page=$1 picture=$2 width=$3 height=$4 scale=${5:-1}
  local window_w window_h
  window_w=$(awk "BEGIN{printf \"%d\", $width / $scale}")
  window_h=$(awk "BEGIN{printf \"%d\", $height / $scale}")
  timeout 120 chromium --headless --no-sandbox --disable-gpu --use-gl=angle --use-angle=swiftshader \
    --enable-unsafe-swiftshader --hide-scrollbars --window-size="$window_w,$window_h" --force-device-scale-factor="$scale" \
    --virtual-time-budget=5000 --user-data-dir="$WORK/profile" --screenshot="$WORK/shot.png" "file://$page" 2> /dev/null
  pngquant --force --quality=60-90 --speed 1 --output "$OUT/$picture.png" "$WORK/shot.png"
  optipng -quiet -o5 "$OUT/$picture.png"
  echo "$OUT/$picture.png: $(stat -c %s "$OUT/$picture.png") bytes"
}

# One picture per strategy: the CC2 file's toolpaths generated, the top view alone.
for cc2 in examples/toolpaths/*.stp; do
  name=$(basename "$cc2" .stp)
  "$NCBRIDGE" convert "$cc2" --level cc1 -o "$WORK/$name.stp" --html "$WORK/$name.html" -q
  shot "$WORK/$name.html#picture" "toolpaths_$name" 800 600
done
"$NCBRIDGE" convert examples/toolpaths/holes_milled_and_peck_drilled.stp --level cc1 -o "$WORK/holes.stp" --html "$WORK/holes.html" -q
shot "$WORK/holes.html#picture3d" toolpaths_holes_milled_and_peck_drilled_3d 800 600

# The viewer: the plate recognised (the whole page), a CAM part's generated toolpaths (3D).
ex=examples/plate
"$NCBRIDGE" convert $ex/plate.ngc --tools $ex/tools.json --stock $ex/stock.json --level cc2 -o "$WORK/plate.stp" \
  --html "$WORK/plate.html" -q
shot "$WORK/plate.html" viewer_plate 800 600 0.5
cam="$SHARED/corpus/cam/p04_open_pockets"
"$NCBRIDGE" convert "$cam/part.linuxcnc.ngc" --tools "$cam/tools.json" --stock "$cam/stock.json" --level cc2 \
  -o "$WORK/p04_cc2.stp" -q
"$NCBRIDGE" convert "$WORK/p04_cc2.stp" --level cc1 -o "$WORK/p04_cc1.stp" --html "$WORK/p04_cc1.html" -q
shot "$WORK/p04_cc1.html" viewer_cam_generated 800 600 0.5
shot "$WORK/p04_cc1.html#picture3d" viewer_cam_generated_3d 800 600

# Planned parts (their features and the toolpaths generated for them).
p02="$SHARED/corpus/cam/p02_plate_center_zero"
"$NCBRIDGE" plan "$p02/part.step" --stock "$p02/stock.json" --tools "$p02/tools.json" -o "$WORK/p02.stp" --html "$WORK/p02.html"
shot "$WORK/p02.html#picture" plan_p02 800 600
"$NCBRIDGE" plan tests/part_reader/data/paper_block_ap224.stp --tools examples/part/tools.json -o "$WORK/block.stp" \
  --html "$WORK/block.html"
shot "$WORK/block.html#picture" plan_paper_block_ap224 800 600

# The optimizer: the slicer's cylinder and the example pocket wall, a middle layer before and after.
"$NCBRIDGE" optimize "$SHARED/corpus/arcs/slic3r129_cylinder.gcode" --flavor marlin -o "$WORK/cylinder.gcode" \
  --html "$WORK/cylinder.html" -q
shot "$WORK/cylinder.html#picture" optimize_cylinder_layer 800 480 0.65
"$NCBRIDGE" optimize examples/optimize/pocket_wall.ngc --dialect rs274ngc --loops -o "$WORK/pocket_wall.ngc" \
  --html "$WORK/pocket_wall.html" -q
shot "$WORK/pocket_wall.html#picture" optimize_pocket_wall_layer 800 480 0.65
