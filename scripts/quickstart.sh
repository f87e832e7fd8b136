#!/usr/bin/env bash
# From a fresh Debian 12 machine to a Unity SH JSON file: install what is missing, build
# Release into build/, convert one of the bundled maps and show the result.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSHPACK_BUILD_TESTS=OFF -DSHPACK_BUILD_BENCH=OFF
cmake --build build -j"$(nproc)"
build/cli/shpack convert data/hdri/courtyard.exr -o build/courtyard.json
cat build/courtyard.json
