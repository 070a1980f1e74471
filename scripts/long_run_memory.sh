#!/usr/bin/env bash
# The long-run memory figures of docs/limits.md ("Long runs"): peak resident memory of `tecido run` on
# data/scenes/long_run_cloth.json (a windblown 16 x 16 cloth over a floor, with drag and
# self-collision, gia+edge3, checked after every step), measured by /usr/bin/time -v, three ways:
#   with self-collision          the scene as written
#   without self-collision       the same scene without its "self_collision" line
#   with self-collision, --out   also writing frames (OBJ, about 100) and result.json
# Usage: bash scripts/long_run_memory.sh [STEPS]   (default 1000000 steps = 2000 s simulated;
# about 3 minutes per run on an idle core). Builds build/bin/tecido first when it is missing.
# Prints one line per run: peak resident set size in MiB (1024^2 bytes), wall time, exit status.
set -euo pipefail
cd "$(dirname "$0")/.."
STEPS=${1:-1000000}
if [ ! -x /usr/bin/time ]; then
  echo "long_run_memory.sh: /usr/bin/time is missing (Debian package: time)" >&2
  exit 2
fi
if [ ! -x build/bin/tecido ]; then
  cmake --preset release >/dev/null
  cmake --build --preset release -j "${JOBS:-$(nproc)}" --target tecido
fi
scene=data/scenes/long_run_cloth.json
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grep -v '"self_collision"' "$scene" >"$work/no_self_collision.json"

# measure LABEL ARGS...: runs `tecido run ARGS` under /usr/bin/time -v and prints the figure.
measure() {
  local label=$1
  shift
  local status=0
  /usr/bin/time -v -o "$work/time.txt" build/bin/tecido run "$@" --steps "$STEPS" >/dev/null || status=$?
  local kb wall
  kb=$(sed -n 's/^[[:space:]]*Maximum resident set size (kbytes): //p' "$work/time.txt")
  wall=$(sed -n 's/^[[:space:]]*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt")
  awk -v l="$label" -v kb="$kb" -v w="$wall" -v s="$status" -v n="$STEPS" \
    'BEGIN { printf "%-32s %d steps: peak RSS %.1f MiB, wall %s, exit %d\n", l, n, kb / 1024, w, s }'
}

measure "with self-collision" "$scene"
measure "without self-collision" "$work/no_self_collision.json"
measure "with self-collision, --out" "$scene" --out "$work/out"
