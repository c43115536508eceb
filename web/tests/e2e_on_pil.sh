#!/usr/bin/env bash
# The dashboard end to end in headless Chromium against the robot's firmware on the emulated Cortex-M4 (duet pil in
# real time, with its bridge), through one of the two back ends:
#   monitor  duet monitor on the bridge's XCP port: the P slider's write is a DOWNLOAD that duet monitor reads back
#            with an UPLOAD, and the page shows the value read back; theta comes by DAQ at 1 kHz.
#   bridge   the bridge's own dashboard (the application channel, theta at 100 Hz): after the P slider's write the
#            value the firmware received (linux_gains[0]) is read over XCP through the bridge.
# Either way the Status page must show the executive's task table (the application channel's account, or the
# account in memory that duet monitor uploads), and the Disturb box must push and restart the simulated robot.
# Screenshots of every page go to ARTEFACTS. Prints "skipped: ..." (ctest's skip pattern) when something it needs is
# not built.
# Usage: e2e_on_pil.sh monitor|bridge DUET FIRMWARE A2L ARTEFACTS
set -euo pipefail
backend=$1 duet=$2 firmware=$3 a2l=$4 artefacts=$5
web=$(cd "$(dirname "$0")/.." && pwd)
[[ -f $firmware ]] || { echo "skipped: no firmware image $firmware (build the m4-qemu preset)"; exit 0; }
[[ -f $web/dist/index.html && -d $web/node_modules/playwright-core ]] ||
  { echo "skipped: the front end is not built (cd web && npm ci && npm run build)"; exit 0; }

work=$(mktemp -d)
children=()
cleanup() {
  for child in "${children[@]}"; do kill -INT "$child" 2>/dev/null || true; done
  wait 2>/dev/null || true
  [[ -n ${E2E_KEEP:-} ]] && cp -r "$work" "$E2E_KEEP"; rm -rf "$work"
}
trap cleanup EXIT

# The first match of a pattern in a child's output, waiting for it to appear.
address_in() {
  local file=$1 pattern=$2
  for _ in $(seq 1 200); do
    if grep -qoE "$pattern" "$file"; then grep -oE "$pattern" "$file" | head -1; return 0; fi
    sleep 0.1
  done
  echo "e2e_on_pil: '$pattern' never appeared in $file:" >&2; cat "$file" >&2; return 1
}

"$duet" pil "$firmware" --scenario "$(dirname "$a2l")/../scenarios/disturbed.yaml" --duration 120 --xcp 127.0.0.1:0 --websocket 127.0.0.1:0 >"$work/pil.out" 2>&1 &
children+=($!)
xcp=$(address_in "$work/pil.out" 'tcp://127.0.0.1:[0-9]+')
bridge_page=$(address_in "$work/pil.out" 'http://127.0.0.1:[0-9]+/')

# The plant's control endpoint, which the bridge relays already and duet monitor is told of.
plant_control=$(address_in "$work/pil.out" 'plant-control 127.0.0.1:[0-9]+' | cut -d' ' -f2)

if [[ $backend == monitor ]]; then
  "$duet" monitor --xcp "$xcp" --a2l "$a2l" --listen 127.0.0.1:0 --web "$web/dist" --plant-control "$plant_control" \
    --signal theta --signal theta_rate --signal theta_acc --signal gyro_y --signal y --signal position \
    --signal speed --signal duty_percent >"$work/monitor.out" 2>&1 &
  children+=($!)
  page=$(address_in "$work/monitor.out" 'http://127.0.0.1:[0-9]+/')
  value=0.025
else
  page=$bridge_page
  value=0.03
fi

node "$web/tests/dashboard_e2e.mjs" --url "$page" --artefacts "$artefacts" --parameter P --value "$value" \
  --signal theta --trigger-level auto --timeout-s 40 --expect-tasks yes --plant push --mdf4 save

if [[ $backend == bridge ]]; then
  # What the firmware took from the application channel, read over XCP through the bridge.
  received=$("$duet" xcp read --connect "$xcp" --a2l "$a2l" --json linux_gains)
  echo "read over XCP: $received"
  python3 -c 'import json, sys
gains = json.loads(sys.argv[1])["linux_gains"]
sys.exit(0 if abs(gains[0] - float(sys.argv[2])) < 1e-6 else f"P on the target is {gains[0]}, not {sys.argv[2]}")' \
    "$received" "$value"
fi
echo "screenshots in $artefacts"
