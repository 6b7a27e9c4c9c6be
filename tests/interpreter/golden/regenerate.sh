#!/usr/bin/env bash
# Regenerates the golden canonical outputs with LinuxCNC's standalone interpreter `rs274`
# (Debian package linuxcnc-uspace). CI does not need it: the outputs are committed.
#
#   tests/interpreter/golden/regenerate.sh            every case in cases.txt, plus the checks below
#   tests/interpreter/golden/regenerate.sh NAME...    only these cases
#
# It also (re)writes the inch tool tables rs274 reads for the shared corpus programs from their
# tools.json (mm), and checks that rs274 rejects every tests/interpreter/errors/*.ngc program,
# recording its messages in tests/interpreter/errors/rs274-messages.txt for reference.
#
# rs274 notes: -g is required; a bad -t file is silently ignored; it rewrites the -v file at exit
# (we give it a throw-away one); it keeps tool data in $HOME/.tool.mmap, shared by every rs274
# running as the same user, so each run gets a private HOME; o<name> call files are searched in
# the working directory.
set -euo pipefail
shopt -s nullglob
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
shared="${NCBRIDGE_SHARED_DIR:-$repo/../shared}"
shared="$(cd "$shared" && pwd)"

if ! command -v rs274 >/dev/null; then
  echo "regenerate: rs274 not installed (apt-get install linuxcnc-uspace); nothing done" >&2
  exit 1
fi

rs274_seconds=20
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/home" "$work/cwd"

resolve() {  # a cases.txt path -> absolute path
  case "$1" in
    @shared/*) echo "$shared/${1#@shared/}" ;;
    *) echo "$here/$1" ;;
  esac
}

# rs274 PROGRAM TABLE DIR -> stdout = canonical calls; returns rs274's status, stderr in $work/err
run_rs274() {
  : >"$work/params.var"
  (cd "$3" && HOME="$work/home" timeout "$rs274_seconds" rs274 -g -n 2 -t "$2" -v "$work/params.var" "$1" \
      </dev/null 2>"$work/err")
}

# Inch tool tables for the shared corpus programs, from their tools.json (mm).
json_to_inch_table() {
  jq -r '(if type == "array" then . else .tools end)[] |
         "T\(.number) P\(.number) D\(.diameter / 25.4 * 1e9 | round / 1e9) Z\(.length / 25.4 * 1e9 | round / 1e9) ;\(.name)"' "$1"
}
json_to_inch_table "$shared/corpus/paper/tools.json" >"$here/tools/paper.rs274.tbl"
for part in "$shared"/corpus/cam/*/; do
  name="$(basename "$part")"
  json_to_inch_table "$part/tools.json" >"$here/tools/cam_$name.rs274.tbl"
done

failed=0
count=0
while read -r name rest; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  if (($# > 0)); then
    wanted=0
    for w in "$@"; do [[ "$w" == "$name" ]] && wanted=1; done
    ((wanted)) || continue
  fi
  program="programs/$name.ngc" table="tools/metric.rs274.tbl" subdir=""
  for kv in $rest; do
    case "$kv" in
      program=*) program="${kv#program=}" ;;
      rs274-tools=*) table="${kv#rs274-tools=}" ;;
      subroutine-path=*) subdir="${kv#subroutine-path=}" ;;
    esac
  done
  dir="$work/cwd"
  [[ -n "$subdir" ]] && dir="$(resolve "$subdir")"
  if run_rs274 "$(resolve "$program")" "$(resolve "$table")" "$dir" >"$work/out" &&
     ! grep -qv '^executing$' "$work/err"; then
    mv "$work/out" "$here/expected/$name.canon"
    count=$((count + 1))
  else
    echo "regenerate: rs274 rejected $name:" >&2
    sed 's/^/    /' "$work/err" >&2
    failed=1
  fi
done <"$here/cases.txt"
echo "regenerate: wrote $count golden outputs"

if (($# == 0)); then
  errors="$repo/tests/interpreter/errors"
  messages="$errors/rs274-messages.txt"
  echo "# What rs274 says about each error program (reference only; made by golden/regenerate.sh)" >"$messages"
  for program in "$errors"/*.ngc; do
    status=0
    run_rs274 "$program" "$here/tools/metric.rs274.tbl" "$work/cwd" >/dev/null || status=$?
    if ((status == 0)); then
      echo "regenerate: rs274 accepted error program $(basename "$program")" >&2
      failed=1
    elif ((status == 124)); then  # endless loops: rs274 never stops, ncbridge must
      echo "$(basename "$program"): (rs274 did not finish in ${rs274_seconds}s)" >>"$messages"
      continue
    fi
    echo "$(basename "$program"): $(grep -v '^executing$' "$work/err" | head -n 1)" >>"$messages"
  done
fi
exit "$failed"
