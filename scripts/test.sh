#!/usr/bin/env bash
# Runs every test: GCC, and Clang with ASan + UBSan, each through its CMake workflow preset.
# gcc-test is the gcc preset with the tools at -Og (they are compiled for their tests, not their
# speed) and with the Catch2 suites of tests/core and tests/mechanics only (those over every
# scalar type; clang builds and runs every suite, with the sanitizers); gcc
# builds everything, the tools at -O3 as the demonstration does.
# Usage: bash scripts/test.sh [preset...]   (default: gcc-test clang)
set -euo pipefail
cd "$(dirname "$0")/.."
presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(gcc-test clang)
for preset in "${presets[@]}"; do
  case "$preset" in gcc|gcc-test|clang) ;; *) echo "usage: bash scripts/test.sh [gcc|gcc-test|clang]..." >&2; exit 2;; esac
done
source scripts/deps.sh
geomint_install_deps "${GEOMINT_BUILD_PACKAGES[@]}"
for preset in "${presets[@]}"; do
  echo "=== geomint: workflow preset '$preset' ==="
  start=$(date +%s)
  cmake --workflow --preset "$preset" --fresh
  echo "=== geomint: '$preset' passed in $(( $(date +%s) - start )) s ==="
done
