#!/usr/bin/env bash
# Containers: builds the FROM-scratch image with podman (deploy/containers/), runs what
# compose.yaml describes (run-local.sh: one worker per stage and a second interpreter on an
# internal network), submits a job from a client container and gets the file, identical (but
# for FILE_NAME) to `ncbridge convert`. Skips, saying why, when podman cannot run containers.
source "$(dirname "$0")/lib.sh"
: "${SOURCE_DIR:?}"
if ! command -v podman > /dev/null; then
  [[ ${CI:-} == true ]] && fail "podman is not installed under CI=true (scripts/install-deps.sh --tests installs it)"
  echo "SKIP: podman is not installed (scripts/install-deps.sh --tests)"; exit 77
fi
D="$SOURCE_DIR/deploy/containers"
export CONTAINERS_CONF="$D/containers.conf"
tag="localhost/ncbridge-test:$$"
export NCBRIDGE_IMAGE=$tag
net="ncbt$$"
CLEANUP_HOOKS+=("bash '$D/run-local.sh' down '$net'; podman rmi -f '$tag' > /dev/null 2>&1")
timeout 120 bash "$D/build-image.sh" "$BIN" "$tag" || { echo "SKIP: podman cannot build images here"; exit 77; }
if ! timeout 60 podman run --rm --network none "$tag" --version > "$WORK/run.log" 2>&1; then
  echo "SKIP: podman cannot run containers here: $(tail -n 1 "$WORK/run.log")"; exit 77
fi
mkdir -p "$WORK/out" "$WORK/job"
cp "$SHARED/corpus/paper/face_mill.ngc" "$TOOLS_PAPER" "$STOCK_PAPER" "$WORK/job/"
timeout 60 bash "$D/run-local.sh" up "$WORK/out" "$net" 7
timeout 120 podman run --rm --network "$net" -e NCBRIDGE_DDS_DOMAIN=7 -e SOURCE_DATE_EPOCH -v "$WORK/job:/work" "$tag" \
  submit face_mill.ngc --tools tools.json --stock stock.json --job-id in-a-container --wait --timeout 60 -o face_mill.stp \
  > "$WORK/submit.log" 2>&1 || fail "the containerised submit failed"
timeout 60 "$BIN/ncbridge" convert "$WORK/job/face_mill.ngc" --tools "$TOOLS_PAPER" --stock "$STOCK_PAPER" \
  -o "$WORK/expected.stp" 2>/dev/null
diff <(grep -v FILE_NAME "$WORK/expected.stp") <(grep -v FILE_NAME "$WORK/job/face_mill.stp") > /dev/null \
  || fail "the container's file differs from ncbridge convert"
[[ -f "$WORK/out/face_mill.stp" ]] || fail "the step writer container did not write into its output folder"
echo "PASS: image built, five service containers, a containerised submit got its file"
