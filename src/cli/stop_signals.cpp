#include "stop_signals.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>

namespace duet::cli {
namespace {

// The handler's only way out (a self-pipe): what it may touch is a plain int.
volatile sig_atomic_t write_fd = -1;     // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
struct sigaction previous_interrupt {};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
struct sigaction previous_terminate {};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)

void on_signal(int /*number*/) {
  const int saved = errno;
  const char byte = 1;
  [[maybe_unused]] const ssize_t written = ::write(write_fd, &byte, 1);  // a full pipe already says enough
  errno = saved;
}

}  // namespace

StopSignals::StopSignals() {
  int ends[2] = {-1, -1};
  if (::pipe2(ends, O_CLOEXEC | O_NONBLOCK) != 0) return;
  read_fd_ = ends[0];
  write_fd = ends[1];
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, &previous_interrupt);
  ::sigaction(SIGTERM, &action, &previous_terminate);
}

StopSignals::~StopSignals() {
  if (read_fd_ < 0) return;
  ::sigaction(SIGINT, &previous_interrupt, nullptr);
  ::sigaction(SIGTERM, &previous_terminate, nullptr);
  ::close(write_fd);
  write_fd = -1;
  ::close(read_fd_);
}

bool StopSignals::received() {
  char bytes[16];
  while (read_fd_ >= 0 && ::read(read_fd_, bytes, sizeof bytes) > 0) received_ = true;
  return received_;
}

}  // namespace duet::cli
