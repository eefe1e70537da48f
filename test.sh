#!/usr/bin/env bash
# Same setup as run.sh (packages, Release build), then the whole test suite.
# GUI and GL tests run on a virtual X server with Mesa's software OpenGL.
set -euo pipefail
cd "$(dirname "$0")"
./run.sh --build-only --with-test-tools

# Third-party checkers of our exports (Khronos glTF validator), pinned by the lock file.
if [ ! -d tests/tools/node_modules/gltf-validator ]; then
  (cd tests/tools && npm ci --no-audit --no-fund --loglevel=error)
fi

BUILD_DIR=${RIGSMITH_BUILD_DIR:-build}
export LIBGL_ALWAYS_SOFTWARE=1
start=$(date +%s)
xvfb-run -a -s "-screen 0 1600x1000x24" \
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)" --timeout 120 "$@"
echo "test suite: $(( $(date +%s) - start )) s"

# The readers (templates, shapes, guides) and the malformed-input corpus again
# under AddressSanitizer + UBSan: a separate small build of core and its tests.
if [ "${RIGSMITH_SKIP_ASAN:-0}" != "1" ]; then
  start=$(date +%s)
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DRIGSMITH_ASAN=ON -DRIGSMITH_BUILD_GUI=OFF > /dev/null
  cmake --build build-asan --target rigsmith-core-tests
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    ./build-asan/tests/rigsmith-core-tests --gtest_brief=1
  echo "AddressSanitizer core tests: $(( $(date +%s) - start )) s"
fi

# libFuzzer over every file reader (guides, manifests, conditions, shapes, skin weights, skin chunks):
# a separate small clang build of the core layers they need, with ASan + UBSan,
# each target run for RIGSMITH_FUZZ_SECONDS (30) over its corpus in
# tests/fuzz/<target>/corpus. Skipped when clang is missing (run.sh
# --with-test-tools installs it).
if [ "${RIGSMITH_SKIP_FUZZ:-0}" != "1" ] && command -v clang++ >/dev/null; then
  start=$(date +%s)
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DRIGSMITH_FUZZ=ON \
    -DRIGSMITH_BUILD_GUI=OFF -DRIGSMITH_BUILD_TESTS=OFF > /dev/null
  cmake --build build-fuzz --target fuzz-targets
  tests/fuzz/run.sh build-fuzz "${RIGSMITH_FUZZ_SECONDS:-30}"
  echo "fuzzing: $(( $(date +%s) - start )) s"
elif [ "${RIGSMITH_SKIP_FUZZ:-0}" != "1" ]; then
  echo "fuzzing skipped: clang++ not found (./run.sh --build-only --with-test-tools installs it)"
fi
