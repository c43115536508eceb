#!/usr/bin/env bash
# External mode on the emulated Cortex-M4 (apps/balbot/README.md, "External mode on the emulated Cortex-M4"): the
# robot's firmware runs on QEMU against the simulated robot held in the air at 5 degrees (duet pil, lock-step), and
# `duet xcp`, through the bridge, switches the controller to the thesis' PID, records the tilt and the duty for 10 s
# and meanwhile doubles P (at 3 s) and raises D (at 6 s) on the running firmware. It writes the recording as CSV and
# as an SVG plot, then stops duet pil with SIGINT, as Ctrl-C would, and shows its summary.
#
# Usage: scripts/external_mode.sh   (after building duet and duet-bridge, host-release, and balbot-pil, m4-qemu)
# DUET=path/to/duet picks another build of duet; OUT (build/external-mode) is where the files go.
set -euo pipefail
cd "$(dirname "$0")/.."
duet=${DUET:-build/host-release/src/cli/duet}
a2l=apps/balbot/generated/balbot.a2l
# Two ports nobody uses: a master that reached another run's bridge would tune that run's firmware.
read -r free_xcp free_websocket < <(python3 -c 'import socket
sockets = [socket.socket() for _ in range(2)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in sockets))')
xcp=127.0.0.1:${XCP_PORT:-$free_xcp}
websocket=127.0.0.1:${WEBSOCKET_PORT:-$free_websocket}
out=${OUT:-build/external-mode}
mkdir -p "$out"

# Lock-step: with DAQ at 1 kHz the firmware on QEMU goes at 0.8 to 1.2 times real time on a 2-core machine even in
# lock-step, so a run paced to the wall clock would fall behind; in lock-step the firmware's time is exact whatever
# the pace.
"$duet" pil build/m4-qemu/apps/balbot/balbot-pil.elf --scenario apps/balbot/scenarios/held.yaml --lock-step \
  --xcp "$xcp" --websocket "$websocket" >"$out/pil.txt" 2>&1 &
run=$!
trap 'kill -INT $run 2>/dev/null || true' EXIT

# XCP answers once QEMU, the firmware and the bridge are up; the PID acts once the sensor is ready (1.5 s).
ready=
for _ in $(seq 100); do
  kill -0 $run 2>/dev/null || break  # it ended: e.g. the port was taken after all
  if [[ $("$duet" xcp read sensor_ready --a2l "$a2l" --connect "tcp://$xcp" 2>/dev/null) == "sensor_ready = 1"* ]]; then
    ready=yes
    break
  fi
  sleep 0.2
done
if [[ -z $ready ]] || ! kill -0 $run 2>/dev/null; then
  cat "$out/pil.txt"
  echo "external_mode: the firmware did not answer over XCP on $xcp with a ready sensor within 20 s" >&2
  exit 1
fi

# The thesis' gains (I = 0): the shipped I would wind the held robot's duty up to its limit and keep it there.
"$duet" xcp write P=0.0196 I=0 D=0.0187 --a2l "$a2l" --connect "tcp://$xcp"
# One session records and tunes: the bridge, like XCP, serves one master at a time. The writes happen at 3 and 6 s
# of the PC's clock; the recording's time is the firmware's (DAQ timestamps).
"$duet" xcp record --a2l "$a2l" --connect "tcp://$xcp" --signal theta --signal y --signal P --signal D \
  --event "rate 1" --duration 10 --write-at 3:P=0.0392 --write-at 6:D=0.5 \
  --output "$out/external_mode.csv" --plot "$out/external_mode.svg"

kill -INT $run
trap - EXIT
wait $run
sed -n '/^summary/,$p' "$out/pil.txt"
echo "external_mode: wrote $out/external_mode.csv and $out/external_mode.svg"
