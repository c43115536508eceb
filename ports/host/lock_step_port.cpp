#include "duet/host/lock_step_port.hpp"

namespace duet::host {

LockStepPort::LockStepPort(const rt::ModelDescription& model) : model_(model), interrupts_(model.tasks.size()) {}

void LockStepPort::advance(std::uint64_t ticks) {
  for (std::uint64_t tick = 0; tick < ticks && period_ns_ != 0; ++tick) {
    now_ns_ += period_ns_;
    interrupts_.pend(0);
  }
}

}  // namespace duet::host
