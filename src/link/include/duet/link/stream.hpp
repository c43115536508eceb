#pragma once
// The byte streams the link runs over, on the PC: a small interface, and one implementation over file descriptors
// that serves socket pairs (tests), TCP connections (tcp.hpp), pipes and standard input and output. Every wait has
// a timeout, so a peer that falls silent gives an error that says so instead of a hang.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>

#include "duet/support/result.hpp"

namespace duet::link {

using Timeout = std::chrono::milliseconds;
inline constexpr Timeout default_timeout{10'000};
inline constexpr Timeout no_timeout = Timeout::max();  // waits as long as it takes

// Not thread-safe: one thread reads and writes a stream at a time. Every call blocks, at most for the timeout.
class Stream {
 public:
  Stream() = default;
  Stream(const Stream&) = delete;
  Stream& operator=(const Stream&) = delete;
  virtual ~Stream() = default;

  // Waits for at least one byte and reads what is there, up to bytes.size() (which must not be 0): how many were
  // read, or 0 when the peer closed the stream. Fails on an error, or when nothing came within the timeout.
  virtual Result<std::size_t> read_some(std::span<std::uint8_t> bytes) = 0;
  // Writes every byte, waiting (each time up to the timeout) while the peer does not take them.
  virtual Status write_all(std::span<const std::uint8_t> bytes) = 0;

  // Reads exactly bytes.size() bytes; the stream's end before that is a failure.
  Status read_exactly(std::span<std::uint8_t> bytes);
};

// A stream over a file descriptor to read and one to write (the same one for a socket). It closes them when it goes,
// unless told they are borrowed. Writing to a peer that is gone fails with an error, without SIGPIPE.
class FdStream : public Stream {
 public:
  enum class Ownership : std::uint8_t { owned, borrowed };
  FdStream(int read_fd, int write_fd, Timeout timeout, Ownership ownership = Ownership::owned);
  ~FdStream() override;

  Result<std::size_t> read_some(std::span<std::uint8_t> bytes) override;
  Status write_all(std::span<const std::uint8_t> bytes) override;

  [[nodiscard]] Timeout timeout() const { return timeout_; }
  void set_timeout(Timeout timeout) { timeout_ = timeout; }
  // Tells the peer no more bytes come (shutdown of a socket's sending side, or closing the writing pipe); reading
  // goes on.
  void close_writing();

 private:
  int read_fd_;
  int write_fd_;
  Timeout timeout_;
  Ownership ownership_;
  bool socket_ = true;  // until send() says otherwise
};

using StreamPair = std::pair<std::unique_ptr<FdStream>, std::unique_ptr<FdStream>>;

// Two streams connected to each other: a Unix socket pair (socketpair(2)).
[[nodiscard]] Result<StreamPair> socket_pair(Timeout timeout = default_timeout);
// Two streams connected to each other by two pipes, as a program and its child would be.
[[nodiscard]] Result<StreamPair> pipe_pair(Timeout timeout = default_timeout);
// This process's standard input and output (borrowed: left open).
[[nodiscard]] std::unique_ptr<FdStream> standard_streams(Timeout timeout = default_timeout);

}  // namespace duet::link
