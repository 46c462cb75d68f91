#!/usr/bin/env bash
# The whole test suite: Release build of every test and example (-Wall -Wextra), then CTest.
source "$(dirname "$0")/common.sh"
install_missing_packages
configure_and_build -DBUILD_TESTING=ON -DCGAL_HC_BUILD_EXAMPLES=ON -DCGAL_HC_BUILD_BENCHMARKS=ON --
cd "$BUILD_DIR"
ctest --output-on-failure --timeout 1500
# Short libFuzzer runs (scripts/fuzz.sh) when clang++ and its fuzzer runtime are available.
if command -v clang++ >/dev/null 2>&1 && dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "install ok installed"; then
  bash "$ROOT/scripts/fuzz.sh"
fi
