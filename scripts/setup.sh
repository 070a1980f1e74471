#!/usr/bin/env bash
# Installs every Debian package tecido uses, and only those missing. Idempotent; needs root
# (or sudo) only when something is missing. Then the viewer's npm packages (web/, `npm ci`) when
# web/node_modules is missing or older than web/package-lock.json (needs the npm registry once).
set -euo pipefail
PKGS=(build-essential cmake ninja-build pkg-config
      libeigen3-dev libfcl-dev libccd-dev libbullet-dev libcgal-dev libgmp-dev libmpfr-dev
      libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev libfmt-dev
      gnuplot-nox clang libclang-rt-14-dev ccache
      pybind11-dev python3-dev python3-numpy python3-pytest chromium)
# node and npm bundle the 3-D viewer (web/, docs/viewer.md): Debian's only where no node is installed.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then PKGS+=(nodejs npm); fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# The viewer's npm packages (three, esbuild, puppeteer-core), pinned by web/package-lock.json.
cd "$(dirname "$0")/../web"
if [ ! -d node_modules ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: npm ci (web/)" >&2
  npm ci --no-audit --no-fund --loglevel=error
fi
