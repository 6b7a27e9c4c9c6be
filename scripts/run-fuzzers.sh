#!/usr/bin/env bash
# Runs every fuzz target in build-fuzz/bin for N seconds each on a copy of its seed corpus:
# tests/fuzz/corpus/NAME/ plus the dialect's own test programs (tests/interpreter/dialects/NAME/,
# without their .ngc RS274/NGC equivalents), so those need no second copy among the seeds.
# Usage: scripts/run-fuzzers.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
shopt -s nullglob
targets=(build-fuzz/bin/fuzz_*)
if ((${#targets[@]} == 0)); then echo "run-fuzzers: no fuzz targets built" >&2; exit 1; fi
failed=0
for t in "${targets[@]}"; do
  name=$(basename "$t")
  seeds="tests/fuzz/corpus/${name#fuzz_}"
  work=$(mktemp -d)
  [[ -d "$seeds" ]] && cp -r "$seeds"/. "$work"/
  if [[ "$name" == fuzz_ap224 ]]; then  # Part 21 seeds, broken Part 21 files, our AP224 parts and RAMP's
    cp tests/fuzz/corpus/part21/* tests/part_reader/data/*.stp "$work"/
    for f in ../shared/corpus/part21-negative/*.stp ../shared/corpus/ap224/*.stp; do [[ -f "$f" ]] && cp "$f" "$work"/; done
  fi
  for program in "tests/interpreter/dialects/${name#fuzz_}"/*; do
    [[ -f "$program" && "$program" != *.ngc ]] && cp "$program" "$work"/
  done
  echo "-- $name for ${seconds}s (seeds: $(ls "$work" | wc -l))"
  if ! "$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=0 \
        -artifact_prefix="build-fuzz/$name-" "$work" >"build-fuzz/$name.log" 2>&1; then
    echo "FAILED: $name (see build-fuzz/$name.log)"; tail -n 40 "build-fuzz/$name.log"; failed=1
  fi
  rm -rf "$work"
done
((failed == 0)) && echo "fuzz: ${#targets[@]} passed, 0 failed" || exit 1
