#!/usr/bin/env bash
# duet studio's figures (docs/PERFORMANCE.md): the robot's layout and first drawing, edit-to-checked latency, and the
# live values' refresh with every signal of the robot's top level visible against the firmware built for the PC in
# real time. web/tests/bench_studio.mjs measures in headless Chromium and prints one JSON line.
# Usage: [DUET_BUILD=build/host-release] bench/studio.sh   (after building that tree and web/)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${DUET_BUILD:-build/host-release}
node web/tests/bench_studio.mjs --duet "$build/src/cli/duet" --root . --sil "$build/apps/balbot/balbot_sil" "$@"
