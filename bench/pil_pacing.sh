#!/usr/bin/env bash
# How well the main demonstration keeps real time (docs/PERFORMANCE.md, "Processor in the loop"): runs what
# scripts/demo.sh runs (the robot's firmware on QEMU, the disturbed scenario, the bridge), paced, for N seconds of
# model time, and prints the late-tick figure after the first second: ticks more than 1 ms later than their
# wall-clock time (the target: at most 1 %), with the machine's load before and during the run. With --stress, the
# same while `stress-ng --cpu 2` keeps both processors busy (started before the run, stopped after it).
#
# Usage: bench/pil_pacing.sh [SECONDS] [--stress]     (default 30 s; after building duet and duet-bridge,
#        host-release, and balbot-pil, m4-qemu, as scripts/demo.sh does)
# DUET=path/to/duet picks another build of duet. The summary of each run is kept in build/pil-pacing/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=30
stress=false
for argument in "$@"; do
  case $argument in
    --stress) stress=true ;;
    *) seconds=$argument ;;
  esac
done
duet=${DUET:-build/host-release/src/cli/duet}
firmware=build/m4-qemu/apps/balbot/balbot-pil.elf
out=${OUT:-build/pil-pacing}
mkdir -p "$out"
# Ports nobody uses, so that a demonstration running meanwhile does not stop this one from starting.
read -r xcp_port websocket_port < <(python3 -c 'import socket
sockets = [socket.socket() for _ in range(2)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in sockets))')

label=no-stress
if $stress; then
  label=stress
  command -v stress-ng >/dev/null || { echo "pil_pacing: stress-ng is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
  stress-ng --cpu 2 --timeout $((seconds + 30))s --quiet &
  stressing=$!
  trap 'kill $stressing 2>/dev/null || true; wait $stressing 2>/dev/null || true' EXIT
  sleep 1  # its workers running
fi
summary="$out/summary-$label.txt"
echo "pil_pacing: $seconds s of the demonstration, paced, $label; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
"$duet" pil "$firmware" --scenario apps/balbot/scenarios/disturbed.yaml --duration "$seconds" \
  --xcp "127.0.0.1:$xcp_port" --websocket "127.0.0.1:$websocket_port" >"$summary"
# The pacing lines of the summary, up to the tilt's.
sed -n '/^  pacing/,/^  tilt/p' "$summary" | sed '$d'
awk '/^  pacing    after the first second/ {
  for (i = 1; i <= NF; ++i) if ($i == "of") { late = $(i - 1); ticks = $(i + 1) }
  gsub(",", "", late); gsub(",", "", ticks)
  printf "pil_pacing: late ticks after the first second: %s of %s (%.2f %%)\n", late, ticks, 100 * late / ticks
}' "$summary"
