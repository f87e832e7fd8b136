#!/usr/bin/env bash
# What CI runs: install what is missing, build everything with warnings as errors and
# AddressSanitizer + UndefinedBehaviorSanitizer into build-asan/, run the whole test suite
# except the `large` tests; then the libFuzzer targets (clang, build-fuzz/), each for a
# bounded time over its seed corpus; then the `large` tests (peak RSS of a streaming convert
# of a 16384 x 8192 map), which only mean something without ASan, from a Release build
# (build-large/), with the Python module's tests. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step's wall time goes to stderr, so that a slow run says where its time went.
step() {
  local start=$SECONDS
  "$@"
  echo "test.sh: $((SECONDS - start)) s: $*" >&2
}

step ./scripts/install-deps.sh
# Ninja: it compiles a target's objects while the libraries it links are still being built,
# which Make's per-target recursion does not. A build directory that an earlier run made with
# another generator is made anew.
export CMAKE_GENERATOR=Ninja
for dir in build-asan build-fuzz build-large; do
  if [[ -f $dir/CMakeCache.txt ]] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$dir/CMakeCache.txt"; then
    rm -rf "$dir"
  fi
done
# -g1: line tables for the sanitizers' reports, without the full debug info that makes the
# build and link slower (CI should stay under 15 minutes on two cores).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DSHPACK_WERROR=ON -DSHPACK_SANITIZE=ON -DSHPACK_UNITY_BUILD=ON -DSHPACK_BUILD_BENCH=OFF  # the benchmarks are not run here
step cmake --build build-asan -j"$(nproc)"
step ctest --test-dir build-asan --output-on-failure -j2 -LE large

# -O1 -g1: the flags libFuzzer's documentation and OSS-Fuzz build fuzz targets with.
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DSHPACK_FUZZ_SECONDS=10 -DSHPACK_UNITY_BUILD=ON -DSHPACK_BUILD_FUZZERS=ON -DSHPACK_BUILD_TESTS=OFF -DSHPACK_BUILD_BENCH=OFF
step cmake --build build-fuzz -j"$(nproc)" --target shpack_fuzzers
step ctest --test-dir build-fuzz --output-on-failure -j2 -L fuzz

# The same Release build holds the Python module (python/), tested with Debian's
# /usr/bin/python3 and NumPy against the command it was built with, and installed from it
# (label python): shpack_installable is everything `cmake --install` copies.
# -O1 and glue code at -O0: the large test measures memory, not speed; -O1 built this tree
# in 0.8 of -O3's time (153 against 190 s) and glue at -O0 in 124 s, one run each, before the
# unity batches, with which this step took 133 s of a fresh clone's CI.
cmake -S . -B build-large -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DSHPACK_GLUE_O0=ON \
  -DSHPACK_UNITY_BUILD=ON -DSHPACK_WERROR=ON -DSHPACK_BUILD_BENCH=OFF -DSHPACK_BUILD_PYTHON=ON
step cmake --build build-large -j"$(nproc)" --target shpack_installable shpack_large_tests
step ctest --test-dir build-large --output-on-failure -j2 -L 'large|python'
