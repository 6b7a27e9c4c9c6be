#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, convert the example program to STEP-NC
# (CC1: workingsteps with explicit toolpaths; CC2: recognised features), then check both files.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
mkdir -p out
ex=examples/plate
set -x
build/bin/ncbridge convert "$ex/plate.ngc" --tools "$ex/tools.json" --stock "$ex/stock.json" \
  --level cc1 -o out/plate_cc1.stp --report out/plate_cc1.json
build/bin/ncbridge convert "$ex/plate.ngc" --tools "$ex/tools.json" --stock "$ex/stock.json" \
  --level cc2 -o out/plate_cc2.stp --report out/plate_cc2.json --html out/plate.html
build/bin/ncbridge check out/plate_cc1.stp
build/bin/ncbridge check out/plate_cc2.stp
