#!/usr/bin/env bash
# The main demonstration: installs what is missing, builds, and shows the most end-to-end thing duet does so far.
# Today: the duet program on the PC, the self-test firmware on an emulated Cortex-M4 (QEMU mps2-an386), and the
# Linux-side bridge built for the Cortex-A7 and run under qemu-arm. Later issues grow it into the closed loop.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh

# Builds a preset quietly; on failure shows what went wrong.
build() {
  local log="build/demo-$1.log"
  mkdir -p build
  if ! { cmake --preset "$1" && cmake --build --preset "$1"; } >"$log" 2>&1; then
    cat "$log"
    echo "demo: building preset $1 failed (log: $log)" >&2
    exit 1
  fi
  echo "demo: built preset $1"
}

build host-release
build m4-qemu
build a7-linux

duet=build/host-release/src/cli/duet
firmware=build/m4-qemu/ports/mps2-an386/mps2-an386-selftest.elf
bridge=build/a7-linux/src/bridge/duet-bridge

echo
echo "== 1. The duet program on the PC: $($duet --version)"
$duet --help

echo
echo "== 2. Firmware for the Cortex-M4, booted on QEMU's mps2-an386 (deterministic time, -icount)"
arm-none-eabi-size "$firmware"
cmake -DQEMU=qemu-system-arm -DIMAGE="$firmware" -P ports/mps2-an386/run_in_qemu.cmake 2>&1
echo "demo: the firmware exited with code 0 through semihosting"

echo
echo "== 3. The Linux-side bridge for the Cortex-A7 (armhf, static), run under qemu-arm"
qemu-arm-static "$bridge" --version

echo
echo "demo: done. Built the duet program, the Cortex-M4 self-test image and the armhf bridge; the image passed its"
echo "      self-test on the emulated Cortex-M4 and the bridge ran as an armhf program. Run every test: scripts/test.sh"
