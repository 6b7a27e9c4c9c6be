#!/usr/bin/env bash
# The README's tour from an installed copy, with the build tree gone: `cmake --install` into a
# temporary prefix, then, in a mount namespace of its own where an empty file system covers the
# build directory (as if it were deleted, without deleting it for the tests beside this one),
# readme_tour_test.sh runs every command of the tour with `build/bin/ncbridge` being the
# installed command. So the installed ncbridge, its services, its schema and its data need
# nothing from the build.
# Usage: installed_tour_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
WORK=$(mktemp -d "${TMPDIR:-/tmp}/ncbridge-installed-tour.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$BUILD" --prefix "$WORK/prefix" > "$WORK/install.log" || fail "cmake --install: $(tail -n 5 "$WORK/install.log")"
# The tour's commands check files against the ISO 14649 schema: the installed one, not the build's.
[[ -f $WORK/prefix/share/ncbridge/iso14649.exp || ${CI:-} != true ]] || fail "no ISO 14649 schema was installed"

if ! unshare --mount true 2> /dev/null; then
  if [[ ${CI:-} == true ]]; then fail "cannot make a mount namespace (unshare --mount) to hide the build tree"; fi
  echo "SKIP: no mount namespace here (unshare --mount needs root or user namespaces)"
  exit 77
fi
# Inside: the build directory is an empty tmpfs; the tour runs with the prefix as its build/.
unshare --mount --propagation private bash -c '
  set -euo pipefail
  mount -t tmpfs -o size=1m ncbridge-build-hidden "$1"
  [[ -z $(ls -A "$1") ]] || { echo "FAIL: the build tree is still visible" >&2; exit 1; }
  "$2/tests/cli/readme_tour_test.sh" "$3" "$2"
' hide "$BUILD" "$SRC" "$WORK/prefix" || fail "the README tour from the installed copy failed (above)"
echo "PASS: the README tour runs from the installed copy with the build tree hidden"
