#pragma once
// The link over TCP: the plant listens (127.0.0.1:5601 unless told otherwise) and accepts one firmware at a time;
// the firmware connects. Nagle's algorithm is off: the link sends small frames and waits for their answers.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "duet/link/stream.hpp"
#include "duet/support/result.hpp"

namespace duet::link {

inline constexpr std::uint16_t default_port = 5601;

struct HostPort {
  std::string host = "127.0.0.1";
  std::uint16_t port = default_port;
  bool operator==(const HostPort&) const = default;
};

// "HOST:PORT", "[IPV6]:PORT" or ":PORT" (the host 127.0.0.1); port 0 asks the system for a free port when listening.
// A failure quotes the text and says what is wrong.
[[nodiscard]] Result<HostPort> parse_host_port(std::string_view text);
[[nodiscard]] std::string to_string(const HostPort& address);

// Connects to a listening plant; blocks up to `timeout` for the connection.
[[nodiscard]] Result<std::unique_ptr<FdStream>> connect_tcp(const HostPort& address, Timeout timeout = default_timeout);

class TcpListener {
 public:
  // Listens on `address` (the first address the host name resolves to).
  [[nodiscard]] static Result<TcpListener> open(const HostPort& address);
  TcpListener(TcpListener&& other) noexcept;
  TcpListener& operator=(TcpListener&& other) noexcept;
  TcpListener(const TcpListener&) = delete;
  TcpListener& operator=(const TcpListener&) = delete;
  ~TcpListener();

  // Where it listens, with the port the system chose for port 0.
  [[nodiscard]] const HostPort& address() const { return address_; }
  struct Accepted {
    std::unique_ptr<FdStream> stream;  // with `stream_timeout` for its reads and writes
    std::string peer;                  // "127.0.0.1:40312"
  };
  // Waits up to `timeout` (no_timeout: as long as it takes) for the next connection.
  [[nodiscard]] Result<Accepted> accept(Timeout timeout, Timeout stream_timeout = default_timeout);

 private:
  TcpListener(int fd, HostPort address) : fd_(fd), address_(std::move(address)) {}
  int fd_ = -1;
  HostPort address_;
};

}  // namespace duet::link
