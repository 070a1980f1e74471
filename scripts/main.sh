#!/usr/bin/env bash
# The README's main command: installs what is missing, builds (release) and runs the default
# comparison suite, writing out/report.md and out/report.json. Extra arguments go to `tecido suite`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
JOBS=${JOBS:-$(nproc)}
cmake --preset release >/dev/null
# Only what `suite all` runs: the command line and tecido-bench (the bench suite runs it), not the tests.
cmake --build --preset release -j "$JOBS" --target tecido tecido-bench
exec build/bin/tecido suite all --out out "$@"
