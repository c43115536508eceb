#pragma once
// A program run as a child process that cannot outlive duet: it gets PR_SET_PDEATHSIG, so the kernel kills it when
// duet ends however it ends (even by SIGKILL), and a process group of its own, so that the terminal's Ctrl-C
// reaches duet alone, which then stops its children in the order it chooses. Linux only.

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::cli {

class ChildProcess {
 public:
  // Where the child's standard output or error goes; its standard input is /dev/null.
  enum class Output : std::uint8_t { inherit, discard, pipe };
  struct Outputs {
    Output out = Output::inherit;
    Output err = Output::inherit;
  };

  // Runs `command` (command[0]: a path, or a name looked up on PATH). Fails, naming the program, when it cannot be
  // run (not found, not executable). Call from a thread that lives as long as the child: the kernel's "parent
  // death" is the death of the thread that started it.
  [[nodiscard]] static Result<ChildProcess> start(const std::vector<std::string>& command, Outputs outputs);

  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  // Kills (SIGKILL) and reaps a child still running; closes the pipes.
  ~ChildProcess();

  [[nodiscard]] pid_t pid() const { return pid_; }
  // The reading ends of Output::pipe (-1 otherwise), for poll(2) and read(2); they stay open after the child ended.
  [[nodiscard]] int output_fd() const { return output_fd_; }
  [[nodiscard]] int errors_fd() const { return errors_fd_; }

  // Does not block: the exit code once the child has ended (128 + the signal's number when a signal ended it), and
  // it is reaped then.
  [[nodiscard]] std::optional<int> exit_code();
  // Sends `number` to the child, unless it has ended.
  void signal(int number);
  // Sends `first` (SIGTERM unless told), then SIGKILL if the child has not ended within `grace`; reaps it and
  // returns its exit code. Blocks at most `grace` and a moment.
  int stop(std::chrono::milliseconds grace, int first);
  int stop(std::chrono::milliseconds grace);

 private:
  ChildProcess(pid_t pid, int output_fd, int errors_fd) : pid_(pid), output_fd_(output_fd), errors_fd_(errors_fd) {}
  void release();

  pid_t pid_ = -1;
  int output_fd_ = -1;
  int errors_fd_ = -1;
  std::optional<int> exit_code_;
};

}  // namespace duet::cli
