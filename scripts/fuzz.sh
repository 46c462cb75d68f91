#!/usr/bin/env bash
# Builds the libFuzzer targets (test/fuzz/fuzz_*.cpp) with clang++ in build-fuzz/ and runs each for FUZZ_SECONDS
# seconds (default 30) on a copy of its committed corpus (test/fuzz/corpus/<name>/; new inputs go to
# build-fuzz/corpus/<name>/, the repository is not modified). A crash, a sanitizer report or a violated check
# stops the script with a non-zero status; libFuzzer leaves the reproducer in build-fuzz/.
# Long runs: FUZZ_SECONDS=3600 bash scripts/fuzz.sh, or build-fuzz/test/fuzz/fuzz_<name> -runs=1000000 <dirs>.
# FUZZ_SANITIZERS=OFF (with FUZZ_DIR=<another directory>) builds the targets without ASan/UBSan, for campaigns of
# 10^6 executions and more (the targets' checks and crashes are still caught, silent memory errors are not).
# The seed is fixed (FUZZ_SEED, default 1) so that a CI run repeats what was run before it landed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
FUZZ_DIR="${FUZZ_DIR:-$ROOT/build-fuzz}"
FUZZ_SECONDS="${FUZZ_SECONDS:-30}"
JOBS="${JOBS:-$(nproc)}"
cmake -S "$ROOT" -B "$FUZZ_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DCGAL_HC_BUILD_FUZZERS=ON -DCGAL_HC_FUZZ_SANITIZERS="${FUZZ_SANITIZERS:-ON}" -DBUILD_TESTING=OFF -DCGAL_HC_BUILD_EXAMPLES=OFF -DCGAL_HC_BUILD_BENCHMARKS=OFF >/dev/null
targets=()
for src in "$ROOT"/test/fuzz/fuzz_*.cpp; do targets+=("$(basename "$src" .cpp)"); done
cmake --build "$FUZZ_DIR" -j "$JOBS" --target "${targets[@]}"
for t in "${targets[@]}"; do
  name="${t#fuzz_}"
  work="$FUZZ_DIR/corpus/$name"
  mkdir -p "$work" "$ROOT/test/fuzz/corpus/$name"
  echo "== $t: ${FUZZ_SECONDS} s"
  log="$FUZZ_DIR/$t.log"
  rc=0
  (cd "$FUZZ_DIR" && "$FUZZ_DIR/test/fuzz/$t" -seed="${FUZZ_SEED:-1}" -max_total_time="$FUZZ_SECONDS" -timeout=60 -rss_limit_mb=4096 \
       -print_final_stats=1 "$work" "$ROOT/test/fuzz/corpus/$name") >"$log" 2>&1 || rc=$?
  grep -E "^#[0-9]+ *DONE|stat::number_of_executed_units" "$log" || true
  if [ "$rc" -ne 0 ]; then
    echo "$t FAILED (exit $rc); log: $log" >&2
    tail -n 40 "$log" >&2
    exit "$rc"
  fi
done
echo "fuzz targets: ${#targets[@]} run, no failure"
