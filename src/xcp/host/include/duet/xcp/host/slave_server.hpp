#pragma once
// XCP on Ethernet for a slave running on the PC (the firmware's host build, software in the loop): a thread that
// listens on TCP or UDP, serves one master at a time, hands its commands to the Slave and sends the responses and
// the DAQ packets of the transmit queue, all in one LEN/CTR sequence. Listens on localhost unless told otherwise.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/framing.hpp"
#include "duet/xcp/host/endpoint.hpp"
#include "duet/xcp/slave.hpp"

namespace duet::xcp::host {

// Runs the given function while the model's tasks are held off, as the lowest-priority context on the real-time core
// would: Slave::handle() and Slave::on_event() must not run at the same time.
using Exclusive = std::function<void(const std::function<void()>&)>;

class SlaveServer {
 public:
  struct Options {
    Protocol protocol = Protocol::tcp;
    std::string address = "127.0.0.1";
    std::uint16_t port = 0;  // 0: any free port; see port()
    // Fill bytes after each packet up to a multiple of 4 bytes, counted in LEN, as some slaves send them on Ethernet:
    // the master must take a packet longer than its layout.
    bool pad_packets = false;
  };

  SlaveServer(Slave& slave, TransmitQueue& queue, Exclusive exclusive = {});
  ~SlaveServer();
  SlaveServer(const SlaveServer&) = delete;
  SlaveServer& operator=(const SlaveServer&) = delete;

  Status start(const Options& options);
  void stop();
  [[nodiscard]] std::uint16_t port() const { return port_; }
  // DAQ packets are waiting: send them now rather than at the next millisecond. Callable from any thread.
  void notify() const;

  [[nodiscard]] std::uint64_t refused_masters() const { return refused_masters_; }

 private:
  void serve();
  void handle_bytes(std::span<const std::uint8_t> bytes);
  void send_packet(std::span<const std::uint8_t> packet);
  void flush();
  void drain_queue();
  void drop_master();

  Slave& slave_;
  TransmitQueue& queue_;
  Exclusive exclusive_;
  Protocol protocol_ = Protocol::tcp;
  bool pad_packets_ = false;
  int listener_ = -1;
  int master_ = -1;
  int wake_ = -1;
  std::uint16_t port_ = 0;
  std::uint16_t counter_ = 0;
  std::vector<std::uint8_t> outgoing_;
  std::vector<std::uint8_t> packet_ = std::vector<std::uint8_t>(0x10000);  // one packet out of the queue
  std::vector<std::uint8_t> padded_;                                       // one packet and its fill bytes
  std::vector<std::uint8_t> decoder_buffer_;
  FrameDecoder decoder_;
  std::vector<std::uint8_t> udp_peer_;  // sockaddr of the UDP master
  std::atomic<bool> running_{false};
  std::atomic<std::uint64_t> refused_masters_{0};
  std::thread thread_;
};

}  // namespace duet::xcp::host
