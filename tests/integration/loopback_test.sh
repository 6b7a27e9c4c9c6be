#!/usr/bin/env bash
# Multi-process on loopback: `ncbridge up` starts one worker per stage as real processes;
# 20 programs (the corpus and generated ones) are submitted at once, and every result must be
# byte-identical to `ncbridge convert` of the same input (same SOURCE_DATE_EPOCH).
# `ncbridge status` then lists the four workers and the 20 jobs done.
source "$(dirname "$0")/lib.sh"

make_programs "$WORK/programs" 20
mkdir -p "$WORK/out" "$WORK/results"
start up "$BIN/ncbridge" up --workers 1 --output-dir "$WORK/out"
wait_workers 1

submits=()
while read -r prog tools stock; do
  name=$(name_of "$prog")
  timeout 120 "$BIN/ncbridge" submit "$prog" --tools "$tools" --stock "$stock" --job-id "${name%.stp}" \
    --wait -o "$WORK/results/$name" > "$WORK/submit-$name.log" 2>&1 &
  submits+=($!)
done < "$WORK/programs/list"
failed=0
for pid in "${submits[@]}"; do wait "$pid" || failed=$((failed + 1)); done
(( failed == 0 )) || fail "$failed submissions failed"

same=0
while read -r prog tools stock; do
  name=$(name_of "$prog")
  cmp -s "$WORK/programs/expected/$name" "$WORK/results/$name" || fail "$name differs from ncbridge convert"
  cmp -s "$WORK/programs/expected/$name" "$WORK/out/$name" || fail "$name in the writer's folder differs"
  same=$((same + 1))
done < "$WORK/programs/list"
[[ $(ls "$WORK/out" | wc -l) == 20 ]] || fail "the writer's folder holds $(ls "$WORK/out" | wc -l) files, not 20"

status=$("$BIN/ncbridge" status --listen 1)
echo "$status"
[[ $(grep -c "step_writer:done" <<<"$status") == 20 ]] || fail "status does not list 20 jobs done"
echo "PASS: $same of 20 programs byte-identical to ncbridge convert"
