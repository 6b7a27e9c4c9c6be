#!/bin/sh
# Re-runs LinuxCNC's rs274 (package linuxcnc-uspace) on every case program here and stores
# what it prints: NAME.canon (the canonical calls) and, when it stops on an error, NAME.error
# (the message, then the offending block). The tool table is read in inches by rs274.
set -eu
cd "$(dirname "$0")"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for program in *.ngc; do
  name=${program%.ngc}
  : > "$work/rs274.var"
  rs274 -g -n 2 -t tools.tbl -v "$work/rs274.var" "$program" < /dev/null \
    > "$name.canon" 2> "$work/stderr" || true
  grep -v '^executing$' "$work/stderr" > "$name.error" || true
  [ -s "$name.error" ] || rm -f "$name.error"
done
