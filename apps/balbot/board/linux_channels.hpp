#pragma once
// XCP and the application channel to Linux over RPMsg (linux_channels.cpp).

namespace balbot::board {

// IPCC's clock and its interrupt at the lowest priority. Call before enabling interrupts.
void prepare_linux_channels();
// From the background loop: brings the link up once Linux's RPMsg driver is ready; true from then on.
bool poll_linux();

}  // namespace balbot::board
