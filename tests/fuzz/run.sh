#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build for SECONDS each over its corpus
# in the repository (tests/fuzz/<target>/corpus, read only: what the run
# discovers goes to BUILD_DIR/fuzz-corpus/<target>), prints the executions and
# fails on the first crash, hang, leak or sanitizer finding. The input that
# found it is left as BUILD_DIR/fuzz-artifacts/<target>/crash-* (or timeout-*,
# leak-*, oom-*): add it to the corpus and a unit test once it is fixed.
#   tests/fuzz/run.sh BUILD_DIR [SECONDS]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$1"
seconds="${2:-30}"
status=0
for target in guide manifest condition shape weights skinchunks; do
  work="$build/fuzz-corpus/$target"
  artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$work" "$artifacts"
  log="$build/fuzz-$target.log"
  # -timeout: one input taking 5 s is a hang; -rss_limit_mb: a runaway allocation.
  if UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
     "$build/tests/fuzz/fuzz-$target" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -max_len=16384 \
       -dict="$here/yaml.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
       "$work" "$here/$target/corpus" > "$log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz-$target: $runs executions in ${seconds} s, no findings"
  else
    echo "fuzz-$target: FINDING (see $log and $artifacts)" >&2
    grep -E 'ERROR|SUMMARY|Test unit written' "$log" | head -5 >&2 || true
    status=1
  fi
done
exit $status
