#!/usr/bin/env bash
# The Python module's tests (python/tests, pytest) against the build tree: the module from
# BUILD/python (PYTHONPATH), the command line from BUILD/bin/tecido, the interpreter the module was
# built for (CMake's Python_EXECUTABLE, /usr/bin/python3 by default). ctest runs the same suite as
# Python.pytest. Extra arguments go to pytest (-k NAME, -x, ...).
#   BUILD_DIR=DIR   the build folder (default: build, the release preset's)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
PY=$(sed -n 's/^Python_EXECUTABLE:FILEPATH=//p' "$BUILD/CMakeCache.txt" 2>/dev/null || true)
PY=${PY:-/usr/bin/python3}
if ! ls "$BUILD"/python/tecido*.so >/dev/null 2>&1; then
  echo "python_test: no module in $BUILD/python (configure with TECIDO_PYTHON=ON, build the target tecido_python)" >&2
  exit 2
fi
PYTHONPATH="$BUILD/python" TECIDO_BIN="$BUILD/bin/tecido" exec "$PY" -m pytest -q -p no:cacheprovider python/tests "$@"
