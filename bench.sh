#!/usr/bin/env bash
# Builds Release and runs rigsmith-bench, the benchmark executable every
# performance figure comes from. Extra arguments go to Google Benchmark, e.g.
#   ./bench.sh --benchmark_format=json --benchmark_filter=Build
set -euo pipefail
cd "$(dirname "$0")"
./run.sh --build-only
exec "${RIGSMITH_BUILD_DIR:-build}/tests/bench/rigsmith-bench" "$@"
