#!/usr/bin/env bash
# The README's main command: installs what is missing, builds (release) and runs the default
# comparison suite, writing out/report.md and out/report.json. Extra arguments go to `tecido suite`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
JOBS=${JOBS:-$(nproc)}
cmake --preset release >/dev/null
cmake --build --preset release -j "$JOBS"
exec build/bin/tecido suite all --out out "$@"
