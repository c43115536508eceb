#pragma once
// For tests: the controlling side of a pseudo-terminal, as QEMU's `-serial pty` gives one; the program under test
// opens the other side by path(). Non-blocking, closed with the object.

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <string>

namespace duet::bridge {

class PseudoTerminal {
 public:
  PseudoTerminal() {
    descriptor_ = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    grantpt(descriptor_);
    unlockpt(descriptor_);
    path_ = ptsname(descriptor_);
  }
  ~PseudoTerminal() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  [[nodiscard]] int descriptor() const { return descriptor_; }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  int descriptor_ = -1;
  std::string path_;
};

}  // namespace duet::bridge
