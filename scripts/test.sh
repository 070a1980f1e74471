#!/usr/bin/env bash
# The README's test command: installs what is missing, builds (release), runs every test with
# ctest, then builds the asan preset (ASan + UBSan) and runs the tests again under it (all but the
# 13 that repeat a run another test makes, to compare two runs: the band-perturbation tests and the
# determinism tests; CMakePresets.json's asan test filter), then (on CI,
# or when TECIDO_FUZZ_SECONDS is set) builds and runs the fuzz targets. Each stage's wall time is
# printed as it ends ("stage: NAME S s") and all of them again at the end, so a CI log shows where
# the time goes.
#   TECIDO_SKIP_ASAN=1   skip the sanitizer build and its tests
#   JOBS=N               parallel jobs (default: the number of cores)
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-$(nproc)}
STAGES=()
T_ALL=$(date +%s)

# stage NAME COMMAND...: runs COMMAND, prints its wall time, stops the script if it failed.
stage() {
  local name=$1 t0 rc=0
  shift
  t0=$(date +%s)
  echo "stage: $name ..." >&2
  "$@" || rc=$?
  STAGES+=("$(printf '%-16s %5d s' "$name" $(($(date +%s) - t0)))")
  echo "stage: $name $(($(date +%s) - t0)) s (exit $rc)" >&2
  if [ $rc -ne 0 ]; then
    summary
    exit $rc
  fi
}

summary() {
  echo "stage times (wall, $JOBS jobs):" >&2
  printf '  %s\n' "${STAGES[@]}" >&2
  echo "  total            $(printf '%5d' $(($(date +%s) - T_ALL))) s" >&2
}

stage apt bash scripts/setup.sh
stage configure cmake --preset release
stage release-build cmake --build --preset release -j "$JOBS"
stage release-tests ctest --preset release -j "$JOBS"
# The pages (report.html, the 3-D views) in headless Chromium: web/test/, docs/viewer.md.
stage browser-tests bash scripts/browser_test.sh
if [ "${TECIDO_SKIP_ASAN:-0}" != "1" ]; then
  stage asan-configure cmake --preset asan
  stage asan-build cmake --build --preset asan -j "$JOBS"
  stage asan-tests ctest --preset asan -j "$JOBS"
fi
# Fuzzing (scripts/fuzz.sh: clang, libFuzzer + ASan + UBSan) on CI, or when asked for with
# TECIDO_FUZZ_SECONDS=N (seconds per target). fuzz.sh prints its own build and run stages.
if [ "${CI:-}" = "true" ] || [ -n "${TECIDO_FUZZ_SECONDS:-}" ]; then
  stage fuzz-build env TECIDO_FUZZ_BUILD_ONLY=1 bash scripts/fuzz.sh
  stage fuzzing bash scripts/fuzz.sh
fi
summary
