#!/usr/bin/env bash
# The thesis' XCP transfer test on the emulated Cortex-M4, through the bridge: the firmware (firmware.cpp) on QEMU's
# mps2-an386 with XCP on UART0, duet-bridge relaying it to TCP as it relays /dev/ttyRPMSG0 on the board, and
# `transfer_test --connect` as the master. Then the firmware's own account (its console: overruns, core load, the
# step's execution time) and the bridge's counters.
#
#   run_on_qemu.sh QEMU FIRMWARE.elf DUET_BRIDGE TRANSFER_TEST
#
# Exit codes: 0 every value came back and no step overran, 1 otherwise, 2 wrong arguments. "no firmware image" in the
# output: the m4-qemu preset has not built it (ctest then skips the test).
set -uo pipefail

if (($# != 4)); then
  echo "usage: run_on_qemu.sh QEMU FIRMWARE.elf DUET_BRIDGE TRANSFER_TEST" >&2
  exit 2
fi
qemu=$1 firmware=$2 bridge=$3 transfer_test=$4
if [[ ! -f $firmware ]]; then
  echo "run_on_qemu: no firmware image $firmware (cmake --build --preset m4-qemu builds it)"
  exit 1
fi

folder=$(mktemp -d /tmp/duet-transfer-test-XXXXXX)
qemu_pid="" bridge_pid=""
stop() {  # the children this script started, by their process ids, and the folder
  [[ -n $qemu_pid ]] && kill -TERM "$qemu_pid" 2>/dev/null && wait "$qemu_pid" 2>/dev/null
  [[ -n $bridge_pid ]] && kill -INT "$bridge_pid" 2>/dev/null && wait "$bridge_pid" 2>/dev/null
  qemu_pid="" bridge_pid=""
}
trap 'stop; rm -rf "$folder"' EXIT

# As `duet pil` runs the robot's firmware: instructions of 4 ns (-icount shift=2) that never wait for the host's
# clock, UART0 a unix socket for the bridge, UART3 the console.
"$qemu" -machine mps2-an386 -nographic -monitor none -kernel "$firmware" \
  -icount shift=2,align=off,sleep=off -semihosting-config enable=on,target=native \
  -chardev "socket,id=xcp,path=$folder/xcp.sock,server=on,wait=off" -serial chardev:xcp \
  -serial null -serial null -serial "file:$folder/console.txt" </dev/null 2>"$folder/qemu.txt" &
qemu_pid=$!
"$bridge" --channel "unix:$folder/xcp.sock" --listen 127.0.0.1:0 --no-websocket </dev/null 2>"$folder/bridge.txt" &
bridge_pid=$!

# The bridge says where it listens once it does (port 0: any free one), and when it has opened the firmware's
# channel, which QEMU creates a moment after it starts: until then it drops commands, as a dead slave would.
port="" opened=""
for ((waited = 0; waited < 100; ++waited)); do
  port=$(sed -n 's/.*listening for an XCP master on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$folder/bridge.txt")
  opened=$(grep -c "channel unix:$folder/xcp.sock open" "$folder/bridge.txt")
  [[ -n $port && $opened != 0 ]] && break
  sleep 0.1
done
if [[ -z $port || $opened == 0 ]]; then
  echo "run_on_qemu: duet-bridge did not reach the firmware within 10 s:" >&2
  cat "$folder/bridge.txt" "$folder/qemu.txt" >&2
  exit 1
fi

"$transfer_test" --connect "tcp://127.0.0.1:$port"
transfer_result=$?

# The console reports every second of model time, cumulatively: the report after the master's end covers the whole
# play-out.
reports() { grep -c '^duet-status ' "$folder/console.txt"; }
reports_at_end=$(reports)
for ((waited = 0; waited < 100 && $(reports) == reports_at_end; ++waited)); do sleep 0.1; done
stop

echo "the firmware's last report:"
tac "$folder/console.txt" | sed -n '1,/^duet-status /p' | tac | sed 's/^/  /'
echo "duet-bridge:"
grep -v 'listening for' "$folder/bridge.txt" | sed 's/^/  /'
if grep -qv 'terminating on signal' "$folder/qemu.txt"; then  # that line is the stop above, not news
  echo "QEMU said:"
  grep -v 'terminating on signal' "$folder/qemu.txt" | sed 's/^/  /'
fi

overruns=$(sed -n 's/^duet-status .*overruns=\([0-9]*\).*/\1/p' "$folder/console.txt" | tail -n 1)
if [[ -z $overruns || $overruns != 0 ]]; then
  echo "run_on_qemu: the firmware reported ${overruns:-nothing} overruns" >&2
  exit 1
fi
((transfer_result == 0)) || exit 1
echo "run_on_qemu: passed"
