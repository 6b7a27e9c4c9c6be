#!/usr/bin/env bash
# Bulk submit: one `ncbridge submit` (one DDS participant) publishes 60 programs from a list file
# ("PROGRAM TOOLS STOCK" lines: the corpus and generated ones) plus a folder of programs, to two
# workers per stage; every result is byte-identical to `ncbridge convert`, each worker of a stage
# took a share of the jobs (hashing spreads them; CC1 jobs skip the recognizers), and a bad program in the batch is reported
# with its location while the others still convert (exit status 1).
source "$(dirname "$0")/lib.sh"

make_programs "$WORK/programs" 50
# Unique program names (the output file is named after the program): links named as the test's names.
mkdir -p "$WORK/links" "$WORK/folder" "$WORK/out" "$WORK/results"
while read -r prog tools stock; do
  name=$(name_of "$prog")
  ln -s "$prog" "$WORK/links/${name%.stp}.ngc"
  echo "links/${name%.stp}.ngc $tools $stock" >> "$WORK/list"   # relative to the list's folder
done < "$WORK/programs/list"
for k in $(seq 101 110); do
  generate_program "$k" > "$WORK/folder/f$k.ngc"
  timeout 60 "$BIN/ncbridge" convert "$WORK/folder/f$k.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
    -o "$WORK/programs/expected/f$k.stp" 2>/dev/null || fail "convert f$k"
done
printf 'G21 G90\nG0 X0 Y0 Z5\nG1 X10 Y#<undefined> F100\nM2\n' > "$WORK/folder/zz_bad.ngc"

for stage in interpreter cc1-builder feature-recognizer step-writer; do
  for i in 1 2; do
    args=()
    [[ $stage == step-writer ]] && args=(--output-dir "$WORK/out")
    start_stage "$stage" "$stage-$i" "${args[@]}"
  done
done
wait_workers 2

rc=0
timeout 240 "$BIN/ncbridge" submit --list "$WORK/list" "$WORK/folder" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  --wait --output-dir "$WORK/results" > "$WORK/submit.out" 2> "$WORK/submit.log" || rc=$?
[[ $rc == 1 ]] || fail "bulk submit with one bad program exited $rc, not 1: $(tail -n 5 "$WORK/submit.log")"
[[ $(wc -l < "$WORK/submit.out") == 61 ]] || fail "bulk submit printed $(wc -l < "$WORK/submit.out") job ids, not 61"
grep -q "^61 jobs: 60 done, 1 failed, 0 not done" "$WORK/submit.log" || fail "summary: $(tail -n 1 "$WORK/submit.log")"
grep -Eq "ncbridge: error: .*zz_bad.ngc:3:[0-9]+: .*\(interpreter\)" "$WORK/submit.log" || fail "no located error for the bad program"

same=0
while read -r prog tools stock; do
  name=$(name_of "$prog")
  cmp -s "$WORK/programs/expected/$name" "$WORK/results/${name%.stp}.stp" || fail "$name differs from ncbridge convert"
  same=$((same + 1))
done < "$WORK/programs/list"
for k in $(seq 101 110); do
  cmp -s "$WORK/programs/expected/f$k.stp" "$WORK/results/f$k.stp" || fail "f$k.stp differs from ncbridge convert"
  same=$((same + 1))
done
[[ $(ls "$WORK/out" | wc -l) == 60 ]] || fail "the writers' folder holds $(ls "$WORK/out" | wc -l) files, not 60"
for stage in interpreter cc1-builder feature-recognizer step-writer; do
  n1=$(grep -c "done in" "$WORK/$stage-1.log" || true); n2=$(grep -c "done in" "$WORK/$stage-2.log" || true)
  echo "$stage: worker 1 did $n1 jobs, worker 2 did $n2"
  if [[ $stage == feature-recognizer ]]; then  # CC1 jobs skip the recognizer
    (( n1 == 0 && n2 == 0 )) || fail "the feature recognizers worked on CC1 jobs ($n1 / $n2)"
  else
    (( n1 >= 10 && n2 >= 10 )) || fail "the $stage workers did not share the jobs ($n1 / $n2)"
  fi
done
echo "PASS: $same of 60 bulk-submitted jobs byte-identical to ncbridge convert, jobs shared by both workers of every stage, the bad one located"
