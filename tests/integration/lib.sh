# Shared by the multi-process tests (sourced). Every process gets a timeout; everything a test
# starts is killed by its exit trap. Needs: BIN (the build's bin/), SHARED (../shared), WORK (a
# fresh temporary folder).
set -euo pipefail

: "${BIN:?}" "${SHARED:?}"
WORK=$(mktemp -d /tmp/ncbridge-it.XXXXXX)
PIDS=()
CLEANUP_HOOKS=()

cleanup() {
  local rc=$?
  for hook in "${CLEANUP_HOOKS[@]}"; do eval "$hook" || true; done
  for pid in "${PIDS[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  sleep 0.2
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  if [[ $rc -ne 0 && -d "$WORK" ]]; then
    echo "---- logs (test failed, rc=$rc)"; for f in "$WORK"/*.log; do [[ -f $f ]] && { echo "== $f"; tail -n 30 "$f"; }; done
  fi
  rm -rf "$WORK"
  exit $rc
}
trap cleanup EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

# A DDS domain of this test alone, and the loopback configuration users get
# (deploy/cyclonedds/loopback.xml: multicast on lo, 1 s lease), so the tests run what is shipped.
: "${SOURCE_DIR:?}"
export NCBRIDGE_DDS_DOMAIN=$(( 20 + $$ % 200 ))
export CYCLONEDDS_URI="file://$SOURCE_DIR/deploy/cyclonedds/loopback.xml"
export SOURCE_DATE_EPOCH=1700000000
export NCBRIDGE_TEST_TIMEOUT=${NCBRIDGE_TEST_TIMEOUT:-300}

# start NAME CMD...: runs CMD in the background under a timeout, logging to $WORK/NAME.log;
# sets STARTED_PID.
start() {
  local name=$1; shift
  timeout -s KILL "$NCBRIDGE_TEST_TIMEOUT" "$@" > "$WORK/$name.log" 2>&1 &
  STARTED_PID=$!
  PIDS+=("$STARTED_PID")
}

# The pid of the service itself (the child of `timeout`).
service_pid() { pgrep -P "$1" | head -n 1; }

# start_stage STAGE NAME [ARGS...]: one worker of a stage.
start_stage() {
  local stage=$1 name=$2; shift 2
  start "$name" "$BIN/ncbridge-$stage" --worker-id "$name" "$@"
}

# wait_workers N: until the workers topic shows N live workers in each stage (or 20 s).
wait_workers() {
  local n=$1
  for _ in $(seq 1 40); do
    local out; out=$("$BIN/ncbridge" status --listen "${STATUS_LISTEN:-0.3}" 2>/dev/null || true)
    local ok=1
    for stage in interpreter cc1_builder feature_recognizer step_writer; do
      grep -Eq "^  $stage +$n live" <<<"$out" || ok=0
    done
    [[ $ok == 1 ]] && return 0
    sleep 0.2
  done
  "$BIN/ncbridge" status --listen 0.5 || true
  fail "the services did not come up with $n worker(s) per stage"
}

# The corpus programs with their tools and stock, and generated ones: "program tools stock" lines.
TOOLS_PAPER="$SHARED/corpus/paper/tools.json"
STOCK_PAPER="$SHARED/corpus/paper/stock.json"

# generate_program K LINES: a deterministic program: a contour of K-dependent size with arcs,
# LINES extra zig-zag moves (for longer jobs), and a drilling cycle with the paper's tools.
generate_program() {
  local k=$1 lines=${2:-0}
  echo "(generated program $k)"
  echo "G21 G17 G90 G94 G54"
  echo "T1 M6"
  echo "S$((1000 + k * 100)) M3"
  echo "G0 X0 Y0 Z10"
  echo "G1 Z-$((k % 3 + 1)) F$((200 + k * 10))"
  echo "G1 X$((20 + k)) Y0"
  echo "G2 X$((20 + k)) Y$((10 + 2 * k)) I0 J$((5 + k))"
  echo "G1 X0 Y$((10 + 2 * k))"
  echo "G3 X0 Y0 I0 J-$((5 + k))"
  local i
  for ((i = 0; i < lines; i++)); do
    echo "G1 X$((i % 40)).$((i % 7)) Y$(((i * 3) % 25)).$((i % 5))"
  done
  echo "G0 Z10"
  echo "T2 M6"
  echo "S800 M3"
  echo "G81 X$((10 + k)) Y10 Z-$((5 + k % 4)) R2 F100"
  echo "X$((30 + k)) Y$((12 + k))"
  echo "G80"
  echo "G0 Z10"
  echo "M5"
  echo "M30"
}

# name_of PROGRAM: the output name a test uses for a program (unique within a list).
name_of() { local p=$1; echo "$(basename "$(dirname "$p")")_$(basename "${p%.*}").stp"; }

# convert_into DIR PROGRAM TOOLS STOCK: `ncbridge convert` into DIR/expected/NAME.
convert_into() {
  local dir=$1 prog=$2 tools=$3 stock=$4 name
  name=$(name_of "$prog")
  timeout 120 "$BIN/ncbridge" convert "$prog" --tools "$tools" --stock "$stock" -o "$dir/expected/$name" \
    2> "$WORK/convert-$name.log"
}

# make_programs DIR COUNT [LINES]: DIR/list ("program tools stock" per line) of COUNT programs
# with `ncbridge convert`'s output of each in DIR/expected/: the corpus programs the embedded
# pipeline converts (paper, FreeCAD parts), then generated ones.
make_programs() {
  local dir=$1 count=$2 lines=${3:-0}
  mkdir -p "$dir/expected"
  : > "$dir/list"
  local candidates=("$SHARED/corpus/paper/face_mill.ngc $TOOLS_PAPER $STOCK_PAPER"
                    "$SHARED/corpus/paper/test_part.ngc $TOOLS_PAPER $STOCK_PAPER")
  for p in "$SHARED"/corpus/cam/p0*; do candidates+=("$p/part.nc $p/tools.json $p/stock.json"); done
  for c in "${candidates[@]}"; do
    # shellcheck disable=SC2086
    if convert_into "$dir" $c; then echo "$c" >> "$dir/list"; else echo "(corpus program skipped: convert rejects it: $c)"; fi
  done
  local have k=1
  have=$(wc -l < "$dir/list")
  while (( have < count )); do
    generate_program "$k" "$lines" > "$dir/gen$k.ngc"
    convert_into "$dir" "$dir/gen$k.ngc" "$TOOLS_PAPER" "$STOCK_PAPER" || fail "convert rejects generated program $k"
    echo "$dir/gen$k.ngc $TOOLS_PAPER $STOCK_PAPER" >> "$dir/list"
    k=$((k + 1)); have=$((have + 1))
  done
}
