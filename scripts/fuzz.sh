#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (clang, -fsanitize=fuzzer,address,undefined) in the asan
# preset's folder build-asan/ and runs each for SECONDS seconds (default 10 s per target), FUZZ_JOBS targets at
# a time (default: the number of cores; each target is one process, so two cores run two).
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]      (or TECIDO_FUZZ_SECONDS=SECONDS)
# Each target starts from a copy of its seed corpus data/fuzz/<target>/ (data/ is never
# written) in build-asan/corpus/<target>/, which keeps what the fuzzer finds between runs.
# A crash, leak, UBSan report, timeout or out-of-memory is saved under
# build-asan/artifacts/<target>/ and makes the script exit 1 after running every target.
# Bounded work is part of the check: inputs up to MAX_LEN bytes (far past the nesting limit of
# comparisons/io/limits.h) must each run within TIMEOUT seconds and RSS_MB of memory, which a
# reader linear in its input meets with a wide margin and a quadratic one does not.
# Reproduce one with: build-asan/bin/<target> build-asan/artifacts/<target>/crash-<sha1>
# Every finding a target has made is fixed and kept as a regress_* seed in data/fuzz/<target>/,
# which each run replays first.
set -euo pipefail
cd "$(dirname "$0")/.."
SECS=${1:-${TECIDO_FUZZ_SECONDS:-10}}
[ $# -gt 0 ] && shift
JOBS=${JOBS:-$(nproc)}
BUILD=build-asan
if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found (bash scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
  exit 2
fi
# The asan preset's build (clang, ASan + UBSan, -O1): the fuzz targets and the sanitized tests
# share its libraries, compiled once with the coverage instrumentation the fuzzer needs.
cmake --preset asan >/dev/null
if [ $# -gt 0 ]; then TARGETS=("$@"); else mapfile -t TARGETS < "$BUILD/fuzz_targets.txt"; fi
# Named targets: build those only (the reader targets need less than the whole library set).
if [ $# -gt 0 ]; then cmake --build "$BUILD" --target "${TARGETS[@]}" -j "$JOBS"; else cmake --build "$BUILD" --target fuzz -j "$JOBS"; fi
# TECIDO_FUZZ_BUILD_ONLY=1: build and stop (scripts/test.sh times the build and the runs apart).
if [ "${TECIDO_FUZZ_BUILD_ONLY:-0}" = "1" ]; then exit 0; fi

MAX_LEN=${MAX_LEN:-262144} TIMEOUT=${TIMEOUT:-5} RSS_MB=${RSS_MB:-1024}
# The differential targets run the exact referees (GMP), whose cost is not the thing checked and
# which take up to about half a second of CPU on some small inputs (slow_referee_root_refinement);
# libFuzzer's timeout is wall time, so on a busy machine they get more (TIMEOUT_EXACT seconds).
TIMEOUT_EXACT=${TIMEOUT_EXACT:-60}
DEPTH=$(sed -n 's/.*kMaxJsonDepth = \([0-9]*\);.*/\1/p' comparisons/io/limits.h)
if [ -z "$DEPTH" ] || [ "$MAX_LEN" -le $((4 * DEPTH + 64)) ]; then
  echo "fuzz: -max_len=$MAX_LEN cannot reach past the nesting limit ($DEPTH levels)" >&2
  exit 2
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# run_target T: runs target T for SECS seconds; prints its figures, or its finding and exits 1.
run_target() {
  local t=$1 corpus="$BUILD/corpus/$1" artifacts="$BUILD/artifacts/$1" dict=() timeout=$TIMEOUT
  mkdir -p "$corpus" "$artifacts"
  cp -n data/fuzz/"$t"/* "$corpus"/ 2>/dev/null || true
  case "$t" in *_vs_exact | fuzz_selfcollide_continuous) timeout=$TIMEOUT_EXACT ;; esac
  case "$t" in
    fuzz_obj) dict=(-dict=data/fuzz/obj.dict) ;;
    fuzz_options) dict=(-dict=data/fuzz/options.dict) ;;
    fuzz_tritri_vs_exact | fuzz_ccd_vs_exact | fuzz_plane_vs_exact | fuzz_selfcollide_continuous | fuzz_plugin_table) ;;
    fuzz_ccd_queries_csv) dict=(-dict=data/fuzz/csv.dict) ;;
    fuzz_obstacles)  # a JSON value, then OBJ files after lines "%%%"
      dict=(-dict="$BUILD/obstacles.dict") ;;
    *) dict=(-dict=data/fuzz/json.dict) ;;
  esac
  if "$BUILD/bin/$t" "$corpus" "${dict[@]}" -max_total_time="$SECS" -timeout="$timeout" -rss_limit_mb="$RSS_MB" \
      -malloc_limit_mb="$RSS_MB" -max_len="$MAX_LEN" -artifact_prefix="$artifacts/" -print_final_stats=1 \
      >"$BUILD/artifacts/$t.log" 2>&1; then
    echo "fuzz: $t $(grep -E '^stat::(number_of_executed_units|peak_rss_mb|slowest_unit_time_sec)|^#[0-9]+ *DONE' "$BUILD/artifacts/$t.log" | tr '\n' ' ')" >&2
  else
    echo "fuzz: $t FAILED; log $BUILD/artifacts/$t.log, input:" >&2
    grep -E 'Test unit written to|FINDING|ERROR|SUMMARY' "$BUILD/artifacts/$t.log" | head -5 >&2
    return 1
  fi
}

cat data/fuzz/json.dict data/fuzz/obj.dict > "$BUILD/obstacles.dict"
echo '"%%%\x0a"' >> "$BUILD/obstacles.dict"
# FUZZ_JOBS targets at a time (default: the number of cores), each for SECS seconds of its own.
FUZZ_JOBS=${FUZZ_JOBS:-$JOBS}
echo "fuzz: ${#TARGETS[@]} targets, ${SECS} s each, $FUZZ_JOBS at a time" >&2
failed=()
pids=() names=()
# wait_one: waits for the oldest running target and records it if it failed.
wait_one() {
  if ! wait "${pids[0]}"; then failed+=("${names[0]}"); fi
  pids=("${pids[@]:1}") names=("${names[@]:1}")
}
for t in "${TARGETS[@]}"; do
  [ -n "$t" ] || continue
  [ ${#pids[@]} -lt "$FUZZ_JOBS" ] || wait_one
  run_target "$t" &
  pids+=($!) names+=("$t")
done
while [ ${#pids[@]} -gt 0 ]; do wait_one; done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: no findings (${#TARGETS[@]} targets, ${SECS} s each)" >&2
