#!/usr/bin/env bash
# The main demonstration: installs what is missing, builds, and shows the most end-to-end thing duet does so far.
# Today: the duet program on the PC, the self-test firmware and the executive's step-time test on an emulated
# Cortex-M4 (QEMU mps2-an386), a controller model simulated on the PC and its generated code on the emulated Cortex-M4,
# the self-balancing robot balancing the simulated robot on the PC,
# and the Linux-side bridge built for the Cortex-A7 and run under qemu-arm. Later issues grow it into the closed loop.
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
step_time=build/m4-qemu/apps/step_time/step-time.elf
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
echo "== 3. The executive on the emulated Cortex-M4: the thesis' step-time test, 4 ns per instruction (-icount shift=2)"
cmake -DQEMU=qemu-system-arm -DIMAGE="$step_time" -DICOUNT_SHIFT=2 -P ports/mps2-an386/run_in_qemu.cmake 2>&1
echo "demo: a square wave toggled by the model every base step, from 1 s down to 500 ns (the thesis failed at 10 us)"

echo
echo "== 4. A controller as a model (apps/pid_demo): checked, simulated on the PC, generated, run on the Cortex-M4"
$duet model check apps/pid_demo/pid_demo.yaml
mkdir -p build/demo
$duet sim apps/pid_demo/pid_demo.yaml --duration 5 --csv build/demo/pid_demo.csv --plot build/demo/pid_demo.svg
$duet gen apps/pid_demo/pid_demo.yaml -o build/demo/pid_demo
cmake -DQEMU=qemu-system-arm -DIMAGE=build/m4-qemu/apps/pid_demo/pid-demo-model.elf -DICOUNT_SHIFT=0 \
  -P ports/mps2-an386/run_in_qemu.cmake 2>&1
echo "demo: the generated code ended where the simulation ended, bit for bit; plot: build/demo/pid_demo.svg"

echo
echo "== 5. The self-balancing robot (apps/balbot) balancing the simulated robot for a minute, then the thesis' PD gains"
$duet sim apps/balbot/balbot.yaml --plant balbot --scenario apps/balbot/scenarios/disturbed.yaml --duration 60 \
  --csv build/demo/balbot.csv --plot build/demo/balbot.svg
$duet sim apps/balbot/balbot.yaml --plant balbot --scenario apps/balbot/scenarios/release.yaml -p use_lqr=0 \
  --duration 5 --csv build/demo/balbot_pd.csv --plot build/demo/balbot_pd.svg
echo "demo: held at 5 degrees until 2 s, then balanced by LQR state feedback through a push at 20 s; with the thesis'"
echo "      PD gains instead it falls (apps/balbot/README.md says why). Plots: build/demo/balbot.svg, balbot_pd.svg"

echo
echo "== 6. The Linux-side bridge for the Cortex-A7 (armhf, static), run under qemu-arm"
qemu-arm-static "$bridge" --version

echo
echo "demo: done. Built the duet program, the Cortex-M4 images and the armhf bridge; the self-test passed on the"
echo "      emulated Cortex-M4, the executive met the step-time target (10 us) there, a model was simulated on the PC"
echo "      and its generated code ran on the emulated Cortex-M4 to the same values, the robot model balanced the"
echo "      simulated robot, and the bridge ran as an armhf program. Run every test: scripts/test.sh"
