#!/bin/sh
# Recognition time against program size, for several families of input
# (generate_recognition_program FAMILY LINES DIR):
#   milling      a faced block with a grid of contour-parallel pockets and G81 hole pairs
#   interpreter  the interpreter benchmark's program: random long cuts of a 6 mm end mill at
#                random depths across a 220 x 180 block (dense overlapping cuts)
#   random       random walks of six tools at random depths, arcs, helices, drilling
#   adaptive     pockets roughed by trochoidal adaptive clearing, finished with a smaller tool
# For each family and size it times `ncbridge convert --level cc2`: the report's
# feature_recognizer share (wall), the process's wall and CPU time (user + system: the machine is
# shared, so CPU time is the steadier figure) and peak RSS (/usr/bin/time); recognition_cpu is the
# recogniser alone on one thread (recognition_cpu_time on the program's CC1 file: workingsteps,
# recognize, CC2 model); approximate counts the features made past the work limit
# (docs/recognition.md, "Bounded cost").
#   usage: bench/feature_recognizer/run.sh [BUILD_DIR] [FAMILY:LINES...]
#   default: milling:1000000 interpreter:20000 interpreter:200000 interpreter:1000000
#            random:1000000 adaptive:1000000
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
[ $# -gt 0 ] && shift
runs=${*:-milling:1000000 interpreter:20000 interpreter:200000 interpreter:1000000 random:1000000 adaptive:1000000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-12s %8s %9s %12s %14s %9s %9s %16s %8s\n' family lines features approximate recognition_s wall_s cpu_s recognition_cpu peak_MB
for run in $runs; do
  family=${run%%:*} n=${run#*:}
  dir="$work/$family-$n"
  "$build/bin/generate_recognition_program" "$family" "$n" "$dir" > /dev/null
  cd "$dir"
  /usr/bin/time -f '%e %U %S %M' -o time.txt "$build/bin/ncbridge" convert part.ngc --tools tools.json --stock stock.json \
    --level cc2 -o part.stp --report report.json 2>/dev/null
  "$build/bin/ncbridge" convert part.ngc --tools tools.json --stock stock.json --level cc1 -o part1.stp 2>/dev/null
  "$build/bin/recognition_cpu_time" part1.stp > cpu.txt
  python3 - "$family" "$n" <<'PY'
import json, sys
r = json.load(open("report.json"))
wall, user, system, rss = open("time.txt").read().split()[-4:]
recognition_cpu = float(open("cpu.txt").read().split()[7])  # "... total S features N"
approximate = sum(1 for f in r["features"] if f.get("approximate"))
print("%-12s %8s %9d %12d %14.2f %9.2f %9.2f %16.2f %8.0f" % (sys.argv[1], sys.argv[2], len(r["features"]), approximate,
      r["timings_ms"]["feature_recognizer"] / 1000, float(wall), float(user) + float(system), recognition_cpu,
      int(rss) / 1024))
PY
  cd - > /dev/null
  rm -rf "$dir"
done
