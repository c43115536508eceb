#include "sil_xcp.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <vector>

#include "balbot.hpp"
#include "balbot_xcp.hpp"
#include "duet/xcp/host/slave_server.hpp"
#include "duet/xcp/slave.hpp"

namespace duet::sil {
namespace {

// The slave's timestamp function takes no argument: the model's time lives here, set before each tick.
std::atomic<std::uint32_t> model_microseconds{0};
std::uint32_t microseconds() { return model_microseconds.load(); }

// The queue is filled by the tick loop and emptied by the server's thread: a lock of its own, apart from the model's
// (the server may empty it while it holds the model's).
std::mutex queue_mutex;
std::uint32_t lock_queue() {
  queue_mutex.lock();
  return 0;
}
void unlock_queue(std::uint32_t) { queue_mutex.unlock(); }

}  // namespace

// The firmware's slave, as the generated code sizes it, so that a master plans DAQ the same on both.
struct SilXcp::Slave {
  balbot::xcp::Slave slave{{.timestamp = microseconds, .queue_lock = {lock_queue, unlock_queue}}};
  xcp::host::SlaveServer server;

  explicit Slave(std::mutex& lock)
      : server{slave.protocol(), slave.queue(), [&lock](const std::function<void()>& work) {
                 const std::lock_guard held{lock};
                 work();
               }} {}
};

SilXcp::SilXcp() : slave_(std::make_unique<Slave>(lock_)) {}
SilXcp::~SilXcp() { slave_->server.stop(); }

Status SilXcp::start(const std::string& address, std::uint16_t port) {
  return slave_->server.start({.protocol = xcp::host::Protocol::tcp, .address = address, .port = port});
}

std::uint16_t SilXcp::port() const { return slave_->server.port(); }

void SilXcp::tick_started(double now_s) { model_microseconds = static_cast<std::uint32_t>(std::llround(now_s * 1e6)); }

void SilXcp::task_finished(std::size_t task) {
  slave_->slave.protocol().on_event(static_cast<std::uint16_t>(task));
  slave_->server.notify();
}

}  // namespace duet::sil
