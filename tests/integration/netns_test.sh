#!/usr/bin/env bash
# Several hosts: three network namespaces on a bridge (a controller, worker hosts A and B, each
# host running one worker of every stage), made and removed by this test (root needed; skipped
# with a reason otherwise). The controller simulator publishes a program live, block by block;
# mid-run, host A's link is cut; the run must still be converted (by B) and the file reach the
# controller: a CC2 file, byte-identical to `ncbridge convert --level cc2` of the program.
source "$(dirname "$0")/lib.sh"

[[ $(id -u) == 0 ]] || { echo "SKIP: needs root for ip netns"; exit 77; }
command -v ip > /dev/null || { echo "SKIP: iproute2 is not installed"; exit 77; }
n=$(( $$ % 9000 + 1000 ))
br=brn$n net="10.$(( 100 + $$ % 100 )).$(( $$ % 250 )).0"
prefix=${net%.0}
hosts=(c a b)
teardown() {
  for h in "${hosts[@]}"; do ip netns pids "ns$n$h" 2>/dev/null | xargs -r kill -KILL 2>/dev/null || true; done
  for h in "${hosts[@]}"; do ip netns del "ns$n$h" 2>/dev/null || true; done
  ip link del "$br" 2>/dev/null || true
}
CLEANUP_HOOKS+=(teardown)
if ! ip link add "$br" type bridge 2>/dev/null; then echo "SKIP: cannot create a bridge (ip link not permitted)"; exit 77; fi
ip link set "$br" up
i=1
for h in "${hosts[@]}"; do
  ip netns add "ns$n$h" || { echo "SKIP: ip netns not permitted"; exit 77; }
  ip link add "v$n$h" type veth peer name eth0 netns "ns$n$h"
  ip link set "v$n$h" master "$br" up
  ip -n "ns$n$h" addr add "$prefix.$i/24" dev eth0
  ip -n "ns$n$h" link set eth0 up
  ip -n "ns$n$h" link set lo up
  i=$((i + 1))
done

cat > "$WORK/lan.xml" <<XML
<CycloneDDS xmlns="https://cdds.io/config"><Domain id="any">
<General><Interfaces><NetworkInterface name="eth0" multicast="true"/></Interfaces></General>
<Discovery><LeaseDuration>1s</LeaseDuration></Discovery>
<SharedMemory><Enable>false</Enable></SharedMemory>
</Domain></CycloneDDS>
XML
export CYCLONEDDS_URI="file://$WORK/lan.xml"
on() { local h=$1; shift; ip netns exec "ns$n$h" "$@"; }

for h in a b; do
  for stage in interpreter cc1-builder feature-recognizer step-writer; do
    args=()
    [[ $stage == interpreter ]] && args=(--live-tools "$TOOLS_PAPER" --live-stock "$STOCK_PAPER" --live-level cc2)
    start "$stage-$h" ip netns exec "ns$n$h" "$BIN/ncbridge-$stage" --worker-id "$stage-$h" "${args[@]}"
  done
done
workers_seen() { on c "$BIN/ncbridge" status --listen 1.5 2>/dev/null | grep -Ec "^  [a-z0-9_]+ +2 live" || true; }
for _ in $(seq 1 15); do [[ $(workers_seen) == 4 ]] && break; done
[[ $(workers_seen) == 4 ]] || { on c "$BIN/ncbridge" status --listen 1 || true; fail "the controller does not see two workers of each stage"; }

generate_program 3 80 > "$WORK/live.ngc"
mkdir -p "$WORK/expected"
timeout 60 "$BIN/ncbridge" convert "$WORK/live.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --level cc2 \
  -o "$WORK/expected/ctrl1-run1.stp" 2> "$WORK/convert.log" || fail "convert --level cc2 rejects the program" 
blocks=$(grep -c . "$WORK/live.ngc")
# ~2.5 s of blocks; host A is cut off 1 s into the run.
start controller ip netns exec "ns${n}c" "$BIN/ncbridge" controller-sim "$WORK/live.ngc" --controller ctrl1 --run-id run1 \
  --rate 40 --timeout 60 -o "$WORK/ctrl1-run1.stp"
controller=$STARTED_PID
sleep 1
ip link set "v${n}a" down
echo "host A cut off mid-run ($blocks blocks at 40/s)"
wait "$controller" || fail "the controller did not get the run's file"
cmp "$WORK/expected/ctrl1-run1.stp" "$WORK/ctrl1-run1.stp" || fail "the live run's file differs from ncbridge convert --level cc2"
grep -q "CC2 program" "$WORK/ctrl1-run1.stp" || fail "the live run's file is not CC2"
grep -h "ctrl1/run1: done" "$WORK"/*-b.log | head -n 4
echo "PASS: live run converted on host B after host A was cut off; $(tail -n 1 "$WORK/controller.log")"
