#!/usr/bin/env bash
# What flushing outputs to the disk costs (docs/design.md §11, "Durable outputs"): runs
# `tecido suite ARGS` (default: all --quick) under strace, counting only fsync calls and the wall
# time spent inside them (--seccomp-bpf: the other system calls are not stopped, so the run is
# timed nearly as it runs without strace), and prints that time beside the run's own wall time.
# A measurement, printed, never asserted: it depends on the disk and on what else the machine does.
#   bash scripts/fsync_cost.sh [SUITE ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v strace >/dev/null; then
  echo "fsync_cost: installing strace" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends strace >/dev/null
fi
[ -x build/bin/tecido ] || { cmake --preset release >/dev/null && cmake --build --preset release --target tecido; }
[ $# -gt 0 ] || set -- all --quick
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
t0=$(date +%s.%N)
rc=0
strace -f --seccomp-bpf -w -c -e trace=fsync -o "$OUT/strace.txt" build/bin/tecido suite "$@" --out "$OUT/run" \
  >/dev/null 2>"$OUT/stderr.txt" || rc=$?
t1=$(date +%s.%N)
# strace -c's table: "% time  seconds  usecs/call  calls  errors syscall"
read -r secs calls < <(awk '$NF == "fsync" {print $2, $4}' "$OUT/strace.txt")
printf 'fsync_cost: suite %s: %s fsync calls, %.2f s inside them, of %.1f s wall (exit %d)\n' \
  "$*" "${calls:-0}" "${secs:-0}" "$(echo "$t1 - $t0" | bc)" "$rc"
