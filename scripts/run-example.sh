#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, convert the example program.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
mkdir -p out
set -x
build/bin/ncbridge canon examples/face_mill/face_mill.ngc --tools examples/face_mill/tools.json
