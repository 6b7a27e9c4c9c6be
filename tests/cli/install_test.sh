#!/usr/bin/env bash
# ncbridge installed and packaged: `cmake --install` into a temporary prefix (the build and the
# source stay as they are), then, from another directory, the installed copy converts the
# example and checks the result against the schema it installed; the man page renders; bash
# completion completes commands, options and choices; a project builds against the package
# config (find_package(ncbridge)); `cpack -G DEB` makes a package with the command, the services,
# the man page, the completion and the libraries, without the ISO schema.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD=$1 SOURCE=$2
WORK=$(mktemp -d /tmp/ncbridge-install.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

P=$WORK/prefix
cmake --install "$BUILD" --prefix "$P" > "$WORK/install.log" || fail "cmake --install: $(tail -n 5 "$WORK/install.log")"
for f in bin/ncbridge bin/ncbridge-interpreter share/man/man1/ncbridge.1 share/bash-completion/completions/ncbridge \
         share/ncbridge/examples/plate/plate.ngc share/ncbridge/cyclonedds/loopback.xml share/doc/ncbridge/docs/cli.md \
         include/ncbridge/interpreter/interpreter.hpp lib/cmake/ncbridge/ncbridgeConfig.cmake; do
  [[ -e $P/$f ]] || fail "not installed: $f"
done

# The installed copy, elsewhere.
mkdir "$WORK/elsewhere" && cd "$WORK/elsewhere"
ex=$P/share/ncbridge/examples/plate
"$P/bin/ncbridge" convert "$ex/plate.ngc" --tools "$ex/tools.json" --stock "$ex/stock.json" --level cc2 \
  -o plate.stp --report plate.json --html plate.html 2> convert.log || fail "convert: $(cat convert.log)"
grep -q "plate.stp: CC2, 6 features" convert.log || fail "convert said: $(cat convert.log)"
if [[ -f $P/share/ncbridge/iso14649.exp ]]; then
  "$P/bin/ncbridge" -v check plate.stp 2> check.log || fail "check: $(cat check.log)"
  grep -qF "ncbridge: schema: $P/share/ncbridge/iso14649.exp" check.log || fail "check used another schema: $(cat check.log)"
  grep -q "0 errors" check.log || fail "check: $(cat check.log)"
elif [[ ${CI:-} == true ]]; then
  fail "no ISO 14649 schema was installed (NCBRIDGE_ISO14649_SCHEMA_SOURCE)"
fi
[[ $("$P/bin/ncbridge" --version) == "ncbridge "* ]] || fail "--version"

# The man page: renders without warnings, lists every command with its options.
groff -man -Tutf8 -ww -z "$P/share/man/man1/ncbridge.1" 2> groff.log && [[ ! -s groff.log ]] || fail "groff: $(cat groff.log)"
page=$(man -l "$P/share/man/man1/ncbridge.1" 2>/dev/null)
for command in $("$P/bin/ncbridge" --help | awk '/^Subcommands:/ {s = 1; next} s && /^  [a-z]/ {print $1}'); do
  grep -q "^   $command\$" <<<"$page" || fail "the man page has no section for $command"
done
grep -q -- "--heidenhain-feed-units" <<<"$page" || fail "the man page lacks convert's options"

# Bash completion.
if [[ -f /usr/share/bash-completion/bash_completion ]]; then
  completions=$(PATH=$P/bin:$PATH bash -c '
    source /usr/share/bash-completion/bash_completion
    source "$1/share/bash-completion/completions/ncbridge"
    t() { COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); COMP_LINE="${COMP_WORDS[*]}"; COMP_POINT=${#COMP_LINE}
          COMPREPLY=(); _ncbridge; echo "${COMPREPLY[*]}"; }
    t ncbridge conv; t ncbridge convert --lev; t ncbridge convert --level ""; t ncbridge -q diff --tol
    t ncbridge dow; t ncbridge submit --det; t ncbridge plan --tool-table-u' _ "$P")
  [[ $completions == $'convert\n--level\ncc1 cc2\n--tolerance\ndown\n--detach\n--tool-table-units' ]] || fail "bash completion gave: $completions"
elif [[ ${CI:-} == true ]]; then
  fail "bash-completion is not installed (scripts/install-deps.sh --tests)"
fi

# A project built against the installed libraries.
cmake -S "$SOURCE/tests/cli/install_consumer" -B "$WORK/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$P" > consumer.log 2>&1 &&
  cmake --build "$WORK/consumer" >> consumer.log 2>&1 || fail "the consumer project: $(tail -n 20 consumer.log)"
calls=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["canonical_calls"])' <(
  "$P/bin/ncbridge" -q convert "$ex/plate.ngc" --tools "$ex/tools.json" --stock "$ex/stock.json" -o /dev/null --report -))
out=$("$WORK/consumer/consumer" "$ex/plate.ngc" "$ex/tools.json" "$ex/stock.json")
[[ $out == "$calls calls, "* ]] || fail "the consumer printed '$out', convert saw $calls calls"

# The Debian package.
cpack -G DEB --config "$BUILD/CPackConfig.cmake" -B "$WORK/deb" -D CPACK_DEBIAN_COMPRESSION_TYPE=gzip > cpack.log 2>&1 ||
  fail "cpack: $(tail -n 10 cpack.log)"
deb=$(ls "$WORK"/deb/ncbridge_*.deb)
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/ncbridge ./usr/bin/ncbridge-step-writer ./usr/share/man/man1/ncbridge.1 \
         ./usr/share/bash-completion/completions/ncbridge ./usr/lib/libncbridge_interpreter.a \
         ./usr/lib/cmake/ncbridge/ncbridgeConfig.cmake ./usr/share/ncbridge/cyclonedds/loopback.xml; do
  grep -qxF "$f" <<<"$contents" || fail "the package lacks $f"
done
! grep -q "iso14649.exp" <<<"$contents" || fail "the package carries the ISO 14649 schema"
dpkg-deb -f "$deb" Depends | grep -q "libyaml-cpp" || fail "Depends: $(dpkg-deb -f "$deb" Depends)"
echo "PASS: installed to a prefix, converted and checked from it elsewhere, man page, completion, find_package, $(basename "$deb")"
