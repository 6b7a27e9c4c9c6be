#!/usr/bin/env bash
# Regenerates the reference outputs of the hand-written dialect programs: LinuxCNC's standalone
# `rs274` (Debian package linuxcnc-uspace) run on each part's RS274/NGC version
# (parts/NAME/part.ngc) -> expected/NAME.rs274.canon. The dialect versions of the part must
# move the tool exactly as this reference does (dialects_test.cpp); the reference comes from
# LinuxCNC, not from ncbridge, so the check is not an echo of the implementation.
# CI does not need rs274: the outputs are committed.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if ! command -v rs274 >/dev/null; then
  echo "regenerate: rs274 not installed (apt-get install linuxcnc-uspace); nothing done" >&2
  exit 1
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/home"
for dir in "$here"/parts/*/; do
  name="$(basename "$dir")"
  : >"$work/params.var"
  # rs274 keeps tool data in $HOME/.tool.mmap: a private HOME per run
  (cd "$dir" && HOME="$work/home" timeout 20 rs274 -g -n 2 -t "$here/parts/tools.rs274.tbl" \
      -v "$work/params.var" part.ngc </dev/null >"$here/expected/$name.rs274.canon" 2>"$work/err") || {
    echo "regenerate: rs274 failed on $name:" >&2
    cat "$work/err" >&2
    exit 1
  }
  echo "expected/$name.rs274.canon: $(wc -l <"$here/expected/$name.rs274.canon") calls"
done
# single constructs per dialect: <dialect>/NAME.ngc is the hand-written RS274/NGC equivalent of
# <dialect>/NAME.<ext> -> expected/<dialect>/NAME.rs274.canon
for program in "$here"/{fanuc,mach3,siemens840d,heidenhain}/*.ngc; do
  dialect="$(basename "$(dirname "$program")")"
  name="$(basename "$program" .ngc)"
  mkdir -p "$here/expected/$dialect"
  out="$here/expected/$dialect/$name.rs274.canon"
  : >"$work/params.var"
  (cd "$(dirname "$program")" && HOME="$work/home" timeout 20 rs274 -g -n 2 -t "$here/parts/tools.rs274.tbl" \
      -v "$work/params.var" "$program" </dev/null >"$out" 2>"$work/err") || {
    echo "regenerate: rs274 failed on $program:" >&2
    cat "$work/err" >&2
    exit 1
  }
  echo "expected/$dialect/$name.rs274.canon: $(wc -l <"$out") calls"
done
