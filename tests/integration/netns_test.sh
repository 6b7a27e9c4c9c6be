#!/usr/bin/env bash
# Several hosts: four network namespaces on a bridge (a client/controller C, worker hosts A, B
# and D, each running two workers of every stage), made and removed by this test (root needed;
# skipped with a reason otherwise).
# 1. A batch of CC2 jobs submitted from C is spread over every worker (a job's input goes to its
#    owner only); mid-batch, once each of D's workers has jobs, every process of host D is
#    killed; every job must complete, byte-identical to `ncbridge convert --level cc2`, its
#    input sent again to a survivor, and every worker of the three hosts must have run jobs.
# 2. The controller simulator publishes a program live, block by block; mid-run, host A's link
#    is cut; the run must still be converted (by B) and the file reach the controller: a CC2
#    file, byte-identical to `ncbridge convert --level cc2` of the program.
source "$(dirname "$0")/lib.sh"

[[ $(id -u) == 0 ]] || { echo "SKIP: needs root for ip netns"; exit 77; }
command -v ip > /dev/null || { echo "SKIP: iproute2 is not installed"; exit 77; }
n=$(( $$ % 9000 + 1000 ))
br=brn$n net="10.$(( 100 + $$ % 100 )).$(( $$ % 250 )).0"
prefix=${net%.0}
hosts=(c a b d)
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

for h in a b d; do
  for stage in interpreter cc1-builder feature-recognizer step-writer; do
    args=()
    [[ $stage == interpreter ]] && args=(--live-tools "$TOOLS_PAPER" --live-stock "$STOCK_PAPER" --live-level cc2)
    for i in 1 2; do
      start "$stage-$h$i" ip netns exec "ns$n$h" "$BIN/ncbridge-$stage" --worker-id "$stage-$h$i" "${args[@]}"
    done
  done
done
workers_seen() {  # N: how many stages C sees with N live workers
  on c "$BIN/ncbridge" status --listen 1.5 2>/dev/null | grep -Ec "^  [a-z0-9_]+ +$1 live" || true
}
for _ in $(seq 1 20); do [[ $(workers_seen 6) == 4 ]] && break; done
[[ $(workers_seen 6) == 4 ]] || { on c "$BIN/ncbridge" status --listen 1 || true; fail "C does not see six workers of each stage"; }

# 1. A batch over three hosts; host D killed mid-batch.
batch=48
mkdir -p "$WORK/batch/expected" "$WORK/batch/out"
: > "$WORK/batch/list"
for k in $(seq 1 "$batch"); do
  generate_program "$k" 3000 > "$WORK/batch/gen$k.ngc"
  timeout 60 "$BIN/ncbridge" convert "$WORK/batch/gen$k.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" --level cc2 \
    -o "$WORK/batch/expected/gen$k.stp" 2> "$WORK/convert-gen$k.log" || fail "convert --level cc2 rejects generated program $k"
  echo "gen$k.ngc $TOOLS_PAPER $STOCK_PAPER" >> "$WORK/batch/list"
done
start batch ip netns exec "ns${n}c" "$BIN/ncbridge" submit --list "$WORK/batch/list" --level cc2 --wait \
  --output-dir "$WORK/batch/out" --timeout 120
batch_pid=$STARTED_PID
d_busy() {  # how many of D's workers have started a job
  local count=0 f
  for f in "$WORK"/*-d[12].log; do grep -q ": started" "$f" && count=$((count + 1)); done
  echo "$count"
}
for _ in $(seq 1 600); do [[ $(d_busy) == 8 ]] && break; sleep 0.02; done
[[ $(d_busy) == 8 ]] || fail "not every worker of host D got a job ($(d_busy) of 8)"
done_before=$(ls "$WORK/batch/out" | wc -l)
ip netns pids "ns${n}d" | xargs -r kill -KILL
echo "host D's workers killed with $done_before of $batch files written"
(( done_before < batch )) || fail "the batch was over before host D was killed"
wait "$batch_pid" || { tail -n 5 "$WORK/batch.log"; fail "the batch did not complete after host D was killed"; }
for k in $(seq 1 "$batch"); do
  cmp -s "$WORK/batch/expected/gen$k.stp" "$WORK/batch/out/gen$k.stp" || fail "gen$k.stp differs from ncbridge convert --level cc2"
done
for h in a b d; do
  for stage in interpreter cc1-builder feature-recognizer step-writer; do
    line="$stage on $h:"
    for i in 1 2; do
      jobs=$(grep -c ": started" "$WORK/$stage-$h$i.log" || true)
      (( jobs > 0 )) || fail "$stage-$h$i ran no job"
      line+=" $jobs"
    done
    echo "$line jobs started"
  done
done
resent=$(grep -h "sent again" "$WORK"/*.log | wc -l)
(( resent > 0 )) || fail "no job input of host D's workers was sent again to a survivor"
echo "batch: $batch jobs byte-identical to convert --level cc2 over 3 hosts, every worker ran jobs, $resent inputs sent again after host D died"

# 2. A live run; host A cut off mid-run.
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
grep -h "ctrl1/run1: done" "$WORK"/*-b[12].log | head -n 4
echo "PASS: a batch over three hosts survives one host's death byte-identical; live run converted on host B after host A was cut off; $(tail -n 1 "$WORK/controller.log")"
