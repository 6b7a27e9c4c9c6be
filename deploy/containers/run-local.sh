#!/usr/bin/env bash
# What compose.yaml describes, with plain podman (no podman-compose needed):
#   run-local.sh up OUT_DIR [NAME] [DOMAIN]   network NAME (internal) + the five service containers
#   run-local.sh down [NAME]                  removes them and the network
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
export CONTAINERS_CONF=${CONTAINERS_CONF:-$here/containers.conf}
image=${NCBRIDGE_IMAGE:-localhost/ncbridge:latest}
case "${1:-}" in
up)
  out=$(cd "$2" && pwd); name=${3:-ncbridge}; domain=${4:-0}
  podman network create --internal "$name" > /dev/null
  run() {
    local cname=$1; shift
    podman run -d --name "$name-$cname" --network "$name" -e NCBRIDGE_DDS_DOMAIN="$domain" "$@" > /dev/null
  }
  run interpreter --entrypoint /usr/bin/ncbridge-interpreter "$image"
  run interpreter-2 --entrypoint /usr/bin/ncbridge-interpreter "$image"
  run cc1-builder --entrypoint /usr/bin/ncbridge-cc1-builder "$image"
  run feature-recognizer --entrypoint /usr/bin/ncbridge-feature-recognizer "$image"
  run step-writer -v "$out:/out" --entrypoint /usr/bin/ncbridge-step-writer "$image" --output-dir /out
  ;;
down)
  name=${2:-ncbridge}
  for c in interpreter interpreter-2 cc1-builder feature-recognizer step-writer; do
    podman rm -f -t 2 "$name-$c" > /dev/null 2>&1 || true
  done
  podman network rm -f "$name" > /dev/null 2>&1 || true
  ;;
*) echo "usage: $0 up OUT_DIR [NAME] [DOMAIN] | down [NAME]" >&2; exit 2 ;;
esac
