#!/usr/bin/env bash
# What CI runs: install what is missing, build everything with warnings as errors and
# AddressSanitizer + UndefinedBehaviorSanitizer into build-asan/, run the whole test suite.
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHPACK_WERROR=ON -DSHPACK_SANITIZE=ON
cmake --build build-asan -j"$(nproc)"
ctest --test-dir build-asan --output-on-failure -j2
