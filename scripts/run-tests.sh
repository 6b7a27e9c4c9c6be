#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, run the whole test suite:
# the release build's tests, the same suite under ASan/UBSan, and every fuzz target for a bounded time.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
jobs=$(nproc)

echo "== release build and tests"
scripts/build.sh release
ctest --preset release --parallel "$jobs"

echo "== ASan/UBSan build and tests"
scripts/build.sh asan
ctest --preset asan --parallel "$jobs"

echo "== fuzz targets (libFuzzer, bounded time, committed seed corpora)"
scripts/build.sh fuzz
scripts/run-fuzzers.sh "${NCBRIDGE_FUZZ_SECONDS:-30}"
