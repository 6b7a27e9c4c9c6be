#!/usr/bin/env bash
# Builds the ncbridge services image (Containerfile) from a build's bin/ folder:
#   build-image.sh BIN_DIR [TAG]      (default tag: localhost/ncbridge:latest)
# root/ gets the five executables, every library ldd lists (with the dynamic loader), the
# DDS Security plugins and the Cyclone configurations of deploy/cyclonedds/.
set -euo pipefail
bin=$(cd "$1" && pwd)
tag=${2:-localhost/ncbridge:latest}
here=$(cd "$(dirname "$0")" && pwd)
export CONTAINERS_CONF=${CONTAINERS_CONF:-$here/containers.conf}
ctx=$(mktemp -d /tmp/ncbridge-image.XXXXXX)
trap 'rm -rf "$ctx"' EXIT
mkdir -p "$ctx/root/usr/bin" "$ctx/root/etc/ncbridge" "$ctx/root/tmp" "$ctx/root/out"
exes=(ncbridge ncbridge-interpreter ncbridge-cc1-builder ncbridge-feature-recognizer ncbridge-step-writer)
for e in "${exes[@]}"; do cp "$bin/$e" "$ctx/root/usr/bin/"; done
plugins=(/usr/lib/x86_64-linux-gnu/libddsc0debian/*.so)
for f in "${exes[@]/#/$bin/}" "${plugins[@]}"; do
  [[ -e $f ]] || continue
  ldd "$f" | grep -Eo '/[^ ]+' | while read -r lib; do
    mkdir -p "$ctx/root$(dirname "$lib")"
    cp -L -n "$lib" "$ctx/root$lib"
  done
done
for p in "${plugins[@]}"; do [[ -e $p ]] && { mkdir -p "$ctx/root$(dirname "$p")"; cp -L "$p" "$ctx/root$p"; }; done
cp -r "$here/../cyclonedds" "$ctx/root/etc/ncbridge/cyclonedds"
cp "$here/Containerfile" "$ctx/"
podman build -q -t "$tag" "$ctx" > /dev/null
echo "$tag: $(du -sh "$ctx/root" | cut -f1) of executables and libraries"
