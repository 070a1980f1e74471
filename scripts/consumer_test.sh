#!/usr/bin/env bash
# The installed package as a user meets it (docs/package.md): builds what `cmake --install` puts
# in place (the libraries and `tecido`, not the tests), installs the build into BUILD/install,
# configures examples/consumer out of tree (BUILD/consumer, a fresh configure each time, so a
# broken export or package configuration fails here) against that prefix only, builds it and runs
# its GoogleTest suite with ctest. Prints its wall time.
#   scripts/consumer_test.sh [BUILD]   BUILD: a configured build directory (default: build)
#   JOBS=N                             parallel jobs (default: the number of cores)
set -euo pipefail
cd "$(dirname "$0")/.."
T0=$(date +%s)
BUILD=$(realpath -m "${1:-build}")
JOBS=${JOBS:-$(nproc)}
PREFIX="$BUILD/install"
CONSUMER="$BUILD/consumer"

cmake --build "$BUILD" -j "$JOBS" --target tecido-package
rm -rf "$PREFIX"
cmake --install "$BUILD" --prefix "$PREFIX" > /dev/null
cmake --fresh -S examples/consumer -B "$CONSUMER" -G Ninja -DCMAKE_PREFIX_PATH="$PREFIX" > /dev/null
cmake --build "$CONSUMER" -j "$JOBS"
ctest --test-dir "$CONSUMER" -j "$JOBS" --output-on-failure
echo "consumer_test: $(($(date +%s) - T0)) s" >&2
