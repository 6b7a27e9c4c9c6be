#!/bin/sh
# Recognition time against program size: generates realistic 2.5D programs (a faced block with a
# grid of contour-parallel pockets and drilled hole pairs, generate_milling_program) of each
# size and times `ncbridge convert --level cc2` on them: the report's feature_recognizer share,
# wall time, CPU time (user + system: the machine is shared, so CPU time is the steadier figure)
# and peak RSS (/usr/bin/time); recognition_cpu is the recogniser alone on one thread
# (recognition_cpu_time on the program's CC1 file: workingsteps, recognize, CC2 model).
#   usage: bench/feature_recognizer/run.sh [BUILD_DIR] [LINES...]   (default 1000 10000 100000 1000000)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
[ $# -gt 0 ] && shift
sizes=${*:-1000 10000 100000 1000000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%8s %8s %8s %14s %10s %10s %14s %10s\n' lines features pockets recognition_s wall_s cpu_s recognition_cpu peak_MB
for n in $sizes; do
  pockets=$("$build/bin/generate_milling_program" "$n" "$work/$n" | cut -d' ' -f1)
  cd "$work/$n"
  /usr/bin/time -f '%e %U %S %M' -o time.txt "$build/bin/ncbridge" convert part.ngc --tools tools.json --stock stock.json \
    --level cc2 -o part.stp --report report.json 2>/dev/null
  "$build/bin/ncbridge" convert part.ngc --tools tools.json --stock stock.json --level cc1 -o part1.stp 2>/dev/null
  "$build/bin/recognition_cpu_time" part1.stp > cpu.txt
  python3 - "$n" "$pockets" <<'PY'
import json, sys
r = json.load(open("report.json"))
wall, user, system, rss = open("time.txt").read().split()[-4:]
recognition_cpu = float(open("cpu.txt").read().split()[7])  # "... total S features N"
print("%8s %8d %8s %14.2f %10.2f %10.2f %14.2f %10.0f" % (sys.argv[1], len(r["features"]), sys.argv[2],
      r["timings_ms"]["feature_recognizer"] / 1000, float(wall), float(user) + float(system), recognition_cpu,
      int(rss) / 1024))
PY
  cd - > /dev/null
done
