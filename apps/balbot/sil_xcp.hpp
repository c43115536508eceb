#pragma once
// The firmware's XCP slave in software in the loop (sil_main.cpp --xcp): the robot's generated calibration segment,
// signals and events (generated/balbot_xcp.hpp, at the generated A2L's addresses) served over XCP on TCP on the PC,
// so that duet xcp, duet monitor and duet studio's external mode reach the PC build as they reach the emulated
// Cortex-M4 behind the bridge. The server's thread reaches the firmware's memory only under memory_lock(), which the
// loop holds for each tick; DAQ timestamps are the model's time in microseconds, as on the target.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "duet/support/result.hpp"

namespace duet::sil {

class SilXcp {
 public:
  SilXcp();
  ~SilXcp();
  SilXcp(const SilXcp&) = delete;
  SilXcp& operator=(const SilXcp&) = delete;

  // Listens on TCP at `address`:`port` (0: any free port).
  Status start(const std::string& address, std::uint16_t port);
  [[nodiscard]] std::uint16_t port() const;

  std::mutex& memory_lock() { return lock_; }
  // From the tick loop, under memory_lock().
  void tick_started(double now_s);
  void task_finished(std::size_t task);

 private:
  struct Slave;
  std::mutex lock_;
  std::unique_ptr<Slave> slave_;
};

}  // namespace duet::sil
