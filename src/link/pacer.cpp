#include "duet/link/pacer.hpp"

#include <thread>

namespace duet::link {

void Pacer::wait_until(double time_s) {
  const auto offset = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>{time_s});
  const Clock::time_point now = Clock::now();
  if (!origin_) {
    origin_ = now - offset;
    return;
  }
  const Clock::time_point deadline = *origin_ + offset;
  if (now < deadline) {
    std::this_thread::sleep_until(deadline);  // steady clock: not moved by changes of the system's time
    return;
  }
  const auto lateness = std::chrono::duration_cast<std::chrono::nanoseconds>(now - deadline);
  if (lateness > tolerance_) ++late_;
  if (lateness > worst_) worst_ = lateness;
}

}  // namespace duet::link
