#!/usr/bin/env bash
# The browser tests (web/test/run_all.mjs): the pages tecido writes (a run's index.html, report.html,
# the disagreement views, a hostile cases file's view) opened from disk in headless Chromium
# (Debian's chromium, driven by puppeteer-core) and checked: no console error, a drawn WebGL
# canvas, one row per check of report.json, a frame slider that moves the cloth, user text shown
# as text. Needs build/bin/tecido (built with the viewer bundle). Screenshots: build/browser-tests/screenshots.
# Skipped, saying why, only when the browser cannot be found (TECIDO_CHROMIUM or /usr/bin/chromium),
# and never on CI (CI=true: a missing browser or node fails).
#   BUILD=DIR   the build folder (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
if ! command -v node >/dev/null; then
  # On CI scripts/setup.sh installs node: its absence there is a failure, not a skip.
  if [ "${CI:-}" = "true" ]; then echo "browser tests FAILED (CI=true): node is not installed" >&2; exit 1; fi
  echo "browser tests SKIPPED: node is not installed (bash scripts/setup.sh installs it)" >&2
  exit 0
fi
if [ ! -d web/node_modules ] || [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then
  (cd web && npm ci --no-audit --no-fund --loglevel=error)
fi
if [ ! -f "$BUILD/web/tecido-viewer.js" ]; then
  echo "browser tests: $BUILD/web/tecido-viewer.js is missing (cmake --build $BUILD --target tecido-viewer)" >&2
  exit 2
fi
exec node web/test/run_all.mjs "$BUILD/bin/tecido" "$BUILD/browser-tests"
