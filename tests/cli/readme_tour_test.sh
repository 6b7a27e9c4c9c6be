#!/usr/bin/env bash
# The README's tour, run exactly as written: every command of its shell blocks (section "A tour"),
# from a copy of the repository root (links to the checkout's files, `build` to this build) after
# the example that scripts/run-example.sh makes (its commands after the build step). Every
# command must succeed, the files the tour names must appear, and the checkout must not gain a
# file. The services run on a DDS domain of their own (NCBRIDGE_DDS_DOMAIN), so tests running
# beside this one are not disturbed.
# Usage: readme_tour_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
WORK=$(mktemp -d "${TMPDIR:-/tmp}/ncbridge-tour.XXXXXX")
cleanup() {
  # An `up` the tour left behind (a command failed before `ncbridge down`) is stopped with its services.
  "$BUILD/bin/ncbridge" down > /dev/null 2>&1 || true
  rm -rf "$WORK"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

ROOT="$WORK/repo"
mkdir "$ROOT"
shopt -s dotglob nullglob
for entry in "$SRC"/*; do
  name=$(basename "$entry")
  case "$name" in build | build-* | out | .git) continue ;; esac
  ln -s "$entry" "$ROOT/$name"
done
ln -s "$BUILD" "$ROOT/build"
touch "$WORK/started"

# The script: run-example.sh's commands after its build, then the tour's shell blocks as they are.
{
  echo 'set -euo pipefail'
  echo 'trap '\''for j in $(jobs -p); do kill $j 2>/dev/null; done'\'' EXIT'
  sed -n '/^scripts\/build.sh/,$p' "$SRC/scripts/run-example.sh" | tail -n +2
  awk '/^## /{tour = ($0 == "## A tour")} tour && /^```/{inside = !inside && ($0 == "```sh"); next} tour && inside' "$SRC/README.md"
} > "$WORK/tour.sh"
commands=$(grep -c '^build/bin/ncbridge' "$WORK/tour.sh" || true)
[[ "$commands" -ge 20 ]] || fail "only $commands ncbridge commands found in README.md's tour: $(cat "$WORK/tour.sh")"
grep -q '^build/bin/ncbridge up ' "$WORK/tour.sh" || fail "the tour has no ncbridge up"
grep -q '^build/bin/ncbridge down' "$WORK/tour.sh" || fail "the tour has no ncbridge down"
if grep -q 'CYCLONEDDS_URI\|NCBRIDGE_DDS_DOMAIN' "$WORK/tour.sh"; then fail "the tour exports the bus: up's record should do"; fi

# The services on a domain of their own (tests beside this one are not disturbed), and `up`'s
# record in a folder of this run: the tour's commands find the services through it, as a user's do.
export NCBRIDGE_DDS_DOMAIN=$((120 + $$ % 100))
unset CYCLONEDDS_URI
export XDG_RUNTIME_DIR="$WORK/run"
mkdir -m 700 "$XDG_RUNTIME_DIR"
status=0
(cd "$ROOT" && bash -x "$WORK/tour.sh") > "$WORK/tour.log" 2>&1 || status=$?
if [[ $status -ne 0 ]]; then
  cat "$WORK/tour.log" >&2
  fail "the README's tour stops (status $status) at the last command above"
fi

# What the tour says it makes.
for f in out/plate_cc1.stp out/plate_cc2.stp out/plate.html plate.stp plate.json plate.html plate_cc2.stp part.stp \
  plate.nc plate.tap plate.mpf plate.h plate.ngc bracket_cc2.stp bracket.json bracket.html block_cc2.stp plate_generated.html \
  out/plate.stp out/plate_tnc.stp out/services/plate.stp out/services/plate_tnc.stp plate_later.stp; do
  [[ -s "$ROOT/$f" && ! -L "$ROOT/$f" ]] || fail "the tour did not make $f"
done
grep -q "FILE_SCHEMA" "$ROOT/out/plate_tnc.stp" || fail "out/plate_tnc.stp is not a Part 21 file"
grep -q "identical" "$WORK/tour.log" || fail "diff of the tour's two CC2 files did not say identical"
cmp -s "$ROOT/plate_later.stp" "$ROOT/out/services/plate.stp" || fail "the fetched plate_later.stp is not the step writers' plate.stp"
# `ncbridge down` stopped up, which stopped its services, and its record is gone.
[[ -z "$(ls -A "$XDG_RUNTIME_DIR/ncbridge" 2>/dev/null | grep -v '\.log$')" ]] \
  || fail "ncbridge down left up's record: $(ls "$XDG_RUNTIME_DIR/ncbridge")"

# Nothing written into the checkout.
written=$(find "$SRC" \( -path "$SRC/build" -o -path "$SRC/build-*" -o -path "$SRC/.git" \) -prune \
  -o -newer "$WORK/started" -type f -print)
[[ -z "$written" ]] || fail "the tour wrote into the checkout: $written"
echo "PASS: README tour, $commands commands ($(grep -c '^+ build/bin/ncbridge' "$WORK/tour.log") run)"
