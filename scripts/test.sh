#!/usr/bin/env bash
# Installs what is missing, builds every preset and runs every test, ending with one ctest summary over all of them.
# Usage: scripts/test.sh        (CI runs it through .ci/run)
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
echo "== build: the dashboard's front end (web/)"
(cd web && npm run --silent build)

presets=(host host-release m4-qemu m4-stm32mp15 a7-linux fuzz)
mkdir -p build
for preset in "${presets[@]}"; do
  echo "== configure and build: $preset"
  cmake --preset "$preset" >"build/configure-$preset.log" 2>&1 || { cat "build/configure-$preset.log"; exit 1; }
  cmake --build --preset "$preset"
done

# One ctest run over every build tree, so that a single summary counts every test.
mkdir -p build/all-tests
{
  echo "# Written by scripts/test.sh: runs the tests of every preset's build tree."
  for preset in "${presets[@]}"; do
    [[ -f build/$preset/CTestTestfile.cmake ]] && echo "subdirs(\"../$preset\")"
  done
} >build/all-tests/CTestTestfile.cmake
echo "== test: ${presets[*]}"
ctest --test-dir build/all-tests --output-on-failure --no-tests=error --parallel "$(nproc)"
