#!/bin/sh
# Toolpath generation against recognition, its inverse, on the same part: generate_milling_program
# makes a faced block with a grid of contour-parallel pockets and G81 hole pairs; `ncbridge
# convert --level cc2` recognises it (CC2: features and operations), then `ncbridge convert
# CC2 --level cc1` generates its toolpaths. For each size: features, the wall and CPU time
# (user + system: the machine is shared, so CPU time is the steadier figure) and peak RSS of
# both runs (/usr/bin/time), and the ratio of their CPU times (docs/toolpaths.md, "Performance").
#   usage: bench/toolpath_generator/run.sh [BUILD_DIR] [LINES...]   default LINES: 20000 100000
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
[ $# -gt 0 ] && shift
sizes=${*:-20000 100000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%8s %9s %14s %12s %12s %14s %12s %12s %9s\n' lines features recognition_s rec_cpu_s rec_peak_MB generation_s gen_cpu_s gen_peak_MB cpu_ratio
for n in $sizes; do
  dir="$work/$n"
  "$build/bin/generate_milling_program" "$n" "$dir" > /dev/null
  cd "$dir"
  /usr/bin/time -f '%e %U %S %M' -o rec.txt "$build/bin/ncbridge" convert part.ngc --tools tools.json --stock stock.json \
    --level cc2 -o part_cc2.stp 2>/dev/null
  /usr/bin/time -f '%e %U %S %M' -o gen.txt "$build/bin/ncbridge" convert part_cc2.stp --level cc1 -o part_cc1.stp 2>/dev/null
  features=$(grep -c -E "=(CLOSED_POCKET|OPEN_POCKET|ROUND_HOLE|PLANAR_FACE|SLOT|STEP|GENERAL_OUTSIDE_PROFILE)\(" part_cc2.stp || true)
  python3 - "$n" "$features" <<'PY'
import sys
n, features = sys.argv[1], sys.argv[2]
rw, ru, rs, rm = open("rec.txt").read().split()[-4:]
gw, gu, gs, gm = open("gen.txt").read().split()[-4:]
rc, gc = float(ru) + float(rs), float(gu) + float(gs)
print("%8s %9s %14.2f %12.2f %12.0f %14.2f %12.2f %12.0f %9.2f" % (
    n, features, float(rw), rc, int(rm) / 1024, float(gw), gc, int(gm) / 1024, gc / rc if rc > 0 else float("nan")))
PY
  cd "$work"
done
