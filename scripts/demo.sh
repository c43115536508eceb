#!/usr/bin/env bash
# The main demonstration: installs what is missing, builds what it needs, and runs the self-balancing robot's
# firmware on an emulated Cortex-M4 (QEMU mps2-an386) against the simulated robot, in real time, with the Linux-side
# bridge relaying XCP and the application channel (duet pil, docs/LINK.md "Processor in the loop"). It prints how to
# connect an XCP master (duet xcp, CANape, pyXCP with the generated A2L) and the address of the dashboard (open it in
# a browser: tuning, scope, recorder, status; docs/DASHBOARD.md) while it runs, and a summary at the end.
#
# Usage: scripts/demo.sh [duet pil options]     e.g. --duration 30, --lock-step, --scenario FILE
# Without --duration it runs until Ctrl-C. scripts/tour.sh shows the parts one by one.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh

# Builds targets of a preset quietly; on failure shows what went wrong.
build() {
  local preset=$1
  shift
  local log="build/demo-$preset.log"
  mkdir -p build
  if ! { cmake --preset "$preset" && cmake --build --preset "$preset" --target "$@"; } >"$log" 2>&1; then
    cat "$log"
    echo "demo: building $* of preset $preset failed (log: $log)" >&2
    exit 1
  fi
  echo "demo: built $* ($preset)"
}

build host-release duet duet-bridge
build m4-qemu balbot-pil
(cd web && npm run --silent build) && echo "demo: built the dashboard (web/dist)"

scenario=apps/balbot/scenarios/disturbed.yaml
for argument in "$@"; do
  [[ $argument == --scenario ]] && scenario=  # the caller's
done
echo "demo: the robot's firmware on the emulated Cortex-M4, the simulated robot ($scenario), the bridge"
exec build/host-release/src/cli/duet pil build/m4-qemu/apps/balbot/balbot-pil.elf \
  ${scenario:+--scenario "$scenario"} --csv build/demo-robot.csv --plot build/demo-robot.svg "$@"
