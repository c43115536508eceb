#pragma once
// SIGINT and SIGTERM caught while a StopSignals lives: instead of ending the process they make its descriptor
// readable, so that a run with children (duet pil) stops them in order and still says how it went. The previous
// handlers come back when it goes. One at a time per process.

namespace duet::cli {

class StopSignals {
 public:
  StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  ~StopSignals();

  // Readable once a signal came, for poll(2); -1 if the pipe could not be made (signals then end the process).
  [[nodiscard]] int fd() const { return read_fd_; }
  // Whether a signal came (does not block).
  [[nodiscard]] bool received();

 private:
  int read_fd_ = -1;
  bool received_ = false;
};

}  // namespace duet::cli
