#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release) with every core.
# Usage: scripts/build.sh [PRESET] [extra cmake --build args...]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"; shift || true
# ccache: rewrite absolute paths relative to the checkout so every clone shares the cache.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" --parallel "$(nproc)" "$@"
