#!/usr/bin/env bash
# The dashboard's figures (docs/PERFORMANCE.md): latency from the target's sample to the browser, and the browser's
# CPU time per second, with 8 signals at 1 kHz. The target is bench/dashboard_target (an XCP slave on the PC whose
# first signal is the wall-clock time of the sample); duet monitor samples it by DAQ and serves the dashboard;
# web/tests/bench_scope.mjs opens the Scope in headless Chromium and measures.
# Usage: [DUET_BUILD=build/host] bench/dashboard_latency.sh [SECONDS]   (after building that tree and web/)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
build=${DUET_BUILD:-build/host-release}
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; wait 2>/dev/null; rm -rf "$work"' EXIT

"$build/bench/dashboard_target" "$work/target.a2l" >"$work/target.out" &
until grep -q listening "$work/target.out" 2>/dev/null; do sleep 0.1; done
"$build/src/cli/duet" monitor --a2l "$work/target.a2l" --listen 127.0.0.1:0 --web web/dist >"$work/monitor.out" &
until grep -q "dashboard on" "$work/monitor.out" 2>/dev/null; do sleep 0.1; done
url=$(grep -oE 'http://127.0.0.1:[0-9]+/' "$work/monitor.out")
for page in scope tuning; do
  echo "== $page page, $seconds s"
  node web/tests/bench_scope.mjs --url "$url" --seconds "$seconds" --latency-signal wall_clock_ms --page "$page"
done
