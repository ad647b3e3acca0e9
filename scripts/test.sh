#!/usr/bin/env bash
# Runs every test: GCC, Clang and the ASan+UBSan build, each through its CMake workflow preset.
# Usage: bash scripts/test.sh [preset...]   (default: gcc clang sanitize)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/deps.sh
geomint_install_deps "${GEOMINT_BUILD_PACKAGES[@]}"
presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(gcc clang sanitize)
for preset in "${presets[@]}"; do
  case "$preset" in gcc|clang|sanitize) ;; *) echo "usage: bash scripts/test.sh [gcc|clang|sanitize]..." >&2; exit 2;; esac
  echo "=== geomint: workflow preset '$preset' ==="
  start=$(date +%s)
  cmake --workflow --preset "$preset" --fresh
  echo "=== geomint: '$preset' passed in $(( $(date +%s) - start )) s ==="
done
