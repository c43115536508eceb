#include "duet/link/stream.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>

namespace duet::link {
namespace {

std::string system_error(const char* what) { return std::string{what} + ": " + std::strerror(errno); }

std::string seconds(Timeout timeout) {
  const auto ms = timeout.count();
  return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

// Waits until `fd` is ready for `events`: true when it is, false when the timeout passed first.
Result<bool> wait_for(int fd, short events, Timeout timeout) {
  using Clock = std::chrono::steady_clock;
  const bool forever = timeout == no_timeout;
  const Clock::time_point deadline = forever ? Clock::time_point::max() : Clock::now() + timeout;
  for (;;) {
    int wait_ms = -1;
    if (!forever) {
      const auto left = std::chrono::ceil<Timeout>(deadline - Clock::now()).count();
      wait_ms = static_cast<int>(std::clamp<Timeout::rep>(left, 0, 1'000'000));
    }
    pollfd poll_fd{.fd = fd, .events = events, .revents = 0};
    const int ready = ::poll(&poll_fd, 1, wait_ms);
    if (ready > 0) return true;  // readable, or hung up / in error: the read or write that follows says which
    if (ready == 0 && !forever && Clock::now() >= deadline) return false;
    if (ready < 0 && errno != EINTR) return Failure{system_error("poll")};
  }
}

// write(2) to a pipe whose reader is gone raises SIGPIPE, which ends the process: block it for this thread while
// writing, and take a SIGPIPE that the write raised before unblocking, so that the write just fails with EPIPE.
ssize_t write_without_sigpipe(int fd, const std::uint8_t* bytes, std::size_t size) {
  sigset_t pipe_signal;
  sigset_t before;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  sigset_t pending;
  sigemptyset(&pending);
  sigpending(&pending);
  const bool already_pending = sigismember(&pending, SIGPIPE) == 1;
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &before);
  const ssize_t written = ::write(fd, bytes, size);
  const int saved = errno;
  if (written < 0 && errno == EPIPE && !already_pending) {
    const timespec none{0, 0};
    while (sigtimedwait(&pipe_signal, nullptr, &none) < 0 && errno == EINTR) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
  errno = saved;
  return written;
}

}  // namespace

Status Stream::read_exactly(std::span<std::uint8_t> bytes) {
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    auto got = read_some(bytes.subspan(filled));
    if (!got) return Failure{got.error()};
    if (got.value() == 0) {
      return Failure{"the stream ended after " + std::to_string(filled) + " of " + std::to_string(bytes.size()) +
                     " bytes"};
    }
    filled += got.value();
  }
  return done();
}

FdStream::FdStream(int read_fd, int write_fd, Timeout timeout, Ownership ownership)
    : read_fd_(read_fd), write_fd_(write_fd), timeout_(timeout), ownership_(ownership) {
  // Non-blocking, so that a write the peer takes only part of comes back instead of blocking past the timeout. A
  // borrowed descriptor (standard input) may be shared with other programs: it stays as it is.
  if (ownership_ == Ownership::owned) {
    for (const int fd : {read_fd_, write_fd_}) {
      if (fd >= 0) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    }
  }
}

FdStream::~FdStream() {
  if (ownership_ == Ownership::borrowed) return;
  if (read_fd_ >= 0) ::close(read_fd_);
  if (write_fd_ >= 0 && write_fd_ != read_fd_) ::close(write_fd_);
}

// An owned descriptor is non-blocking: try first and wait only when there is nothing yet, which saves a poll(2) per
// call when the peer's bytes are already there. A borrowed one may block: wait first.
Result<std::size_t> FdStream::read_some(std::span<std::uint8_t> bytes) {
  if (read_fd_ < 0) return Failure{"the stream is closed for reading"};
  bool ready = false;
  for (;;) {
    if (ready) {
      const ssize_t got = ::read(read_fd_, bytes.data(), bytes.size());
      if (got >= 0) return static_cast<std::size_t>(got);
      if (errno == ECONNRESET) return std::size_t{0};  // the peer went away: for the link, the end of the stream
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) return Failure{system_error("read")};
    }
    auto waited = wait_for(read_fd_, POLLIN, timeout_);
    if (!waited) return Failure{waited.error()};
    if (!waited.value()) return Failure{"nothing received for " + seconds(timeout_)};
    ready = true;
  }
}

Status FdStream::write_all(std::span<const std::uint8_t> bytes) {
  if (write_fd_ < 0) return Failure{"the stream is closed for writing"};
  bool ready = ownership_ == Ownership::owned;
  while (!bytes.empty()) {
    if (ready) {
      ssize_t written = -1;
      if (socket_) {
        written = ::send(write_fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        if (written < 0 && errno == ENOTSOCK) socket_ = false;
      }
      if (!socket_) written = write_without_sigpipe(write_fd_, bytes.data(), bytes.size());
      if (written >= 0) {
        bytes = bytes.subspan(static_cast<std::size_t>(written));
        continue;
      }
      if (errno == EPIPE || errno == ECONNRESET) return Failure{"the peer closed the stream"};
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) return Failure{system_error("write")};
    }
    auto waited = wait_for(write_fd_, POLLOUT, timeout_);
    if (!waited) return Failure{waited.error()};
    if (!waited.value()) return Failure{"the peer took no bytes for " + seconds(timeout_)};
    ready = true;
  }
  return done();
}

void FdStream::close_writing() {
  if (write_fd_ < 0) return;
  if (write_fd_ == read_fd_) {
    ::shutdown(write_fd_, SHUT_WR);
  } else if (ownership_ == Ownership::owned) {
    ::close(write_fd_);
  }
  write_fd_ = -1;
}

Result<StreamPair> socket_pair(Timeout timeout) {
  int fds[2] = {-1, -1};
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) return Failure{system_error("socketpair")};
  return StreamPair{std::make_unique<FdStream>(fds[0], fds[0], timeout),
                    std::make_unique<FdStream>(fds[1], fds[1], timeout)};
}

Result<StreamPair> pipe_pair(Timeout timeout) {
  int there[2] = {-1, -1};  // first's writing end -> second's reading end
  int back[2] = {-1, -1};
  if (::pipe2(there, O_CLOEXEC) != 0) return Failure{system_error("pipe")};
  if (::pipe2(back, O_CLOEXEC) != 0) {
    const std::string message = system_error("pipe");
    ::close(there[0]);
    ::close(there[1]);
    return Failure{message};
  }
  return StreamPair{std::make_unique<FdStream>(back[0], there[1], timeout),
                    std::make_unique<FdStream>(there[0], back[1], timeout)};
}

std::unique_ptr<FdStream> standard_streams(Timeout timeout) {
  return std::make_unique<FdStream>(STDIN_FILENO, STDOUT_FILENO, timeout, FdStream::Ownership::borrowed);
}

}  // namespace duet::link
