#!/usr/bin/env bash
# DDS Security (deploy/security/): services and an authorised client with certificates of the
# test CA convert a program; a participant without security, and one whose certificate comes
# from another CA, can neither publish a program (no service matches them) nor read the
# results (status shows no worker and no job).
source "$(dirname "$0")/lib.sh"
: "${SOURCE_DIR:?}"
command -v openssl > /dev/null || { echo "SKIP: openssl is not installed"; exit 77; }
lib=/usr/lib/x86_64-linux-gnu/libddsc0debian
[[ -f $lib/libdds_security_auth.so ]] || { echo "SKIP: Cyclone's DDS Security plugins are not installed ($lib)"; exit 77; }

bash "$SOURCE_DIR/deploy/security/make-test-pki.sh" "$WORK/pki" services client > /dev/null
bash "$SOURCE_DIR/deploy/security/make-test-pki.sh" "$WORK/rogue" client > /dev/null   # same name, other CA
plain_uri=$CYCLONEDDS_URI
export CYCLONEDDS_URI="file://$SOURCE_DIR/deploy/security/security.xml"
export NCBRIDGE_DDS_SECURITY_DIR="$WORK/pki" NCBRIDGE_DDS_SECURITY_LIB=$lib NCBRIDGE_DDS_INTERFACE=lo
NCBRIDGE_DDS_IDENTITY=services
export NCBRIDGE_DDS_IDENTITY
for stage in interpreter cc1-builder feature-recognizer step-writer; do start_stage "$stage" "$stage"; done

P="$SHARED/corpus/paper"
# Authentication handshakes take a while: listen longer than on a plain bus.
NCBRIDGE_DDS_IDENTITY=client STATUS_LISTEN=2 wait_workers 1
timeout 60 "$BIN/ncbridge" convert "$P/face_mill.ngc" --tools "$P/tools.json" --stock "$P/stock.json" -o "$WORK/expected.stp" 2>/dev/null
NCBRIDGE_DDS_IDENTITY=client timeout 60 "$BIN/ncbridge" submit "$P/face_mill.ngc" --tools "$P/tools.json" \
  --stock "$P/stock.json" --job-id secured --wait -o "$WORK/secured.stp" > "$WORK/submit-secured.log" 2>&1 \
  || fail "the authorised client could not convert"
diff <(grep -v FILE_NAME "$WORK/expected.stp") <(grep -v FILE_NAME "$WORK/secured.stp") > /dev/null || fail "secured result differs"

intruder() {  # NAME ENV...: submit and status as a participant the services must not accept
  local name=$1; shift
  if env "$@" timeout 30 "$BIN/ncbridge" submit "$P/face_mill.ngc" --tools "$P/tools.json" --stock "$P/stock.json" \
       --job-id "intruder-$name" --wait --timeout 3 -o "$WORK/$name.stp" > "$WORK/submit-$name.log" 2>&1; then
    fail "$name published a program and got a result"
  fi
  [[ ! -f "$WORK/$name.stp" ]] || fail "$name got a file"
  local seen; seen=$(env "$@" timeout 30 "$BIN/ncbridge" status --listen 2 2>&1 || true)
  grep -q "secured" <<<"$seen" && fail "$name read the status of a secured job"
  grep -Eq "interpreter +0 live" <<<"$seen" || fail "$name sees the workers: $seen"
  grep -q "jobs: 0" <<<"$seen" || fail "$name sees jobs: $seen"
  echo "$name: rejected ($(tail -n 1 "$WORK/submit-$name.log"))"
}
intruder unauthenticated CYCLONEDDS_URI="$plain_uri"
intruder other-ca NCBRIDGE_DDS_IDENTITY=client NCBRIDGE_DDS_SECURITY_DIR="$WORK/rogue"
# The job the intruders tried must not have reached the services either.
NCBRIDGE_DDS_IDENTITY=client "$BIN/ncbridge" status --listen 1 | grep -q intruder && fail "an intruder's job reached the services"
echo "PASS: authorised client converts; unauthenticated and foreign-CA participants can neither publish nor read"
