#!/usr/bin/env bash
# The README's test command: installs what is missing, builds (release), runs every test with
# ctest, then builds the asan preset (ASan + UBSan) and runs the whole test suite again under it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
JOBS=${JOBS:-$(nproc)}
cmake --preset release >/dev/null
cmake --build --preset release -j "$JOBS"
ctest --preset release -j "$JOBS"
if [ "${TECIDO_SKIP_ASAN:-0}" != "1" ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$JOBS"
  ctest --preset asan -j "$JOBS"
fi
# Fuzzing (scripts/fuzz.sh: clang, libFuzzer + ASan + UBSan, about a minute) on CI, or when asked
# for with TECIDO_FUZZ_SECONDS=N (seconds per target).
if [ "${CI:-}" = "true" ] || [ -n "${TECIDO_FUZZ_SECONDS:-}" ]; then
  bash scripts/fuzz.sh
fi
