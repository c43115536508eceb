// Generated code for the emulated Cortex-M4 that sends on an IPC channel the image does not route: must not compile.
#include "duet/hardware/hardware.hpp"

void step() {
  const std::uint8_t bytes[] = {1, 2};
  duet::hardware::ipc_send<duet::hardware::ipc("telemetry")>(bytes);
}
